// Bug: the tutorial's own slip: in the flipped branch point_on_a and point_on_b
// are stored the other way round.
#include "mutant_plugin.h"

const char* const mutant::name = "mutant-swapped-pair";
mfz::ClippingSteps mutant::steps() {
  mfz::ClippingSteps s;
  s.emit_contacts = [](const mfz::ClipFace& reference, const mfz::ClipPolygon& clipped, const mfz::Vec3& n,
                       bool flipped, mfz_manifold& out) {
    const int first = out.contact_count;
    mfz::emit_clipped_contacts(reference, clipped, n, flipped, out);
    if (flipped)
      for (int i = first; i < out.contact_count; ++i) std::swap(out.contacts[i].point_on_a, out.contacts[i].point_on_b);
  };
  return s;
}
void mutant::before(const mfz_hull&, mfz_pose&, const mfz_hull&, mfz_pose&) {}
void mutant::after(const mfz_hull&, const mfz_pose&, const mfz_hull&, const mfz_pose&, mfz_manifold&) {}

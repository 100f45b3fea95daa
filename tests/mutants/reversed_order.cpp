// Correct: clips against the reference prism's sides in reverse order and
// reports the contacts in reverse order. Neither order is the geometry's.
#include "mutant_plugin.h"

namespace {
bool clip_sides_backwards(const mfz::ClipFace& reference, mfz::ClipPolygon& incident, mfz::ClipTrace*) {
  const mfz::ClipPolygon& loop = *reference.polygon;
  double largest = 0;
  for (int k = 0; k < loop.size(); ++k) largest = std::max(largest, loop[k].cwiseAbs().maxCoeff());
  for (int k = 0; k < incident.size(); ++k) largest = std::max(largest, incident[k].cwiseAbs().maxCoeff());
  const double on_plane = mfz::tol::world_rounding(largest);
  mfz::ClipPolygon scratch;
  for (int k = loop.size(); k-- > 0;) {
    const mfz::Vec3 outward = (loop[(k + 1) % loop.size()] - loop[k]).cross(reference.normal);
    const double length = outward.norm();
    if (!(length > 0)) continue;
    const mfz::Plane side{outward / length, outward.dot(loop[k]) / length};
    if (!mfz::clip_to_plane(incident, side, scratch, on_plane)) return false;
    incident.take(scratch);
  }
  return true;
}
}  // namespace

const char* const mutant::name = "correct-reversed-order";
mfz::ClippingSteps mutant::steps() {
  mfz::ClippingSteps s;
  s.clip_to_sides = clip_sides_backwards;
  return s;
}
void mutant::before(const mfz_hull&, mfz_pose&, const mfz_hull&, mfz_pose&) {}
void mutant::after(const mfz_hull&, const mfz_pose&, const mfz_hull&, const mfz_pose&, mfz_manifold& m) {
  std::reverse(m.contacts, m.contacts + m.contact_count);
}

// Correct: clips against the reference prism's sides in reverse order and
// reports the contacts in reverse order. Neither order is the geometry's.
#include "mutant_plugin.h"

namespace {
bool clip_sides_backwards(const mfz::ClipFace& reference, mfz::ClipPolygon& incident, mfz::ClipTrace*) {
  const mfz::SideBands bands = mfz::side_bands(reference, incident);
  mfz::ClipPolygon scratch;
  for (int k = reference.polygon->size(); k-- > 0;) {
    mfz::Plane computed;
    mfz::SideEdge computed_edge;
    const mfz::PrismSide side = mfz::prism_side(reference, k, computed, computed_edge);
    if (!side.plane) continue;
    if (!mfz::clip_to_plane(incident, *side.plane, scratch, bands.on_plane, bands.near_plane, side.edge)) return false;
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

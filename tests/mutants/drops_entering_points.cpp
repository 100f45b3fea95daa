// Bug: Sutherland-Hodgman that forgets the crossing point where an edge
// enters the kept side (it keeps the exit crossing and the inside points).
#include "mutant_plugin.h"

namespace {
bool clip_without_entries(const mfz::ClipFace& reference, mfz::ClipPolygon& incident, mfz::ClipTrace*) {
  const mfz::ClipPolygon& loop = *reference.polygon;
  for (int k = 0; k < loop.size(); ++k) {
    const mfz::Vec3 outward = (loop[(k + 1) % loop.size()] - loop[k]).cross(reference.normal);
    const double length = outward.norm();
    if (!(length > 0)) continue;
    const mfz::Plane side{outward / length, outward.dot(loop[k]) / length};
    mfz::ClipPolygon kept;
    for (int i = 0; i < incident.size(); ++i) {
      const mfz::Vec3& from = incident[(i + incident.size() - 1) % incident.size()];
      const mfz::Vec3& to = incident[i];
      const double d0 = side.signed_distance(from), d1 = side.signed_distance(to);
      if (d1 <= 0) {
        kept.push(to);  // the entering crossing (d0 > 0) is the one forgotten
      } else if (d0 <= 0) {
        kept.push(from + (d0 / (d0 - d1)) * (to - from));
      }
    }
    incident.take(kept);
  }
  return true;
}
}  // namespace

const char* const mutant::name = "mutant-drops-entering-points";
mfz::ClippingSteps mutant::steps() {
  mfz::ClippingSteps s;
  s.clip_to_sides = clip_without_entries;
  return s;
}
void mutant::before(const mfz_hull&, mfz_pose&, const mfz_hull&, mfz_pose&) {}
void mutant::after(const mfz_hull&, const mfz_pose&, const mfz_hull&, const mfz_pose&, mfz_manifold&) {}

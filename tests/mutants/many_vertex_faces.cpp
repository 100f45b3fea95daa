// Bug only on faces with many vertices: the side planes go into a fixed array
// of 8, and a reference face with more edges is clipped by its first 8 only.
#include "generator/clip_polygon.h"
#include "mutant_plugin.h"

const char* const mutant::name = "mutant-many-vertex-faces";
mfz::ClippingSteps mutant::steps() {
  mfz::ClippingSteps s;
  s.clip_to_sides = [](const mfz::ClipFace& reference, mfz::ClipPolygon& incident, mfz::ClipTrace*) {
    const mfz::ClipPolygon& loop = *reference.polygon;
    mfz::ClipPolygon scratch;
    for (int k = 0; k < loop.size() && k < 8; ++k) {
      const mfz::Vec3 outward = (loop[(k + 1) % loop.size()] - loop[k]).cross(reference.normal).normalized();
      if (!mfz::clip_to_plane(incident, mfz::Plane{outward, outward.dot(loop[k])}, scratch)) return false;
      std::swap(incident, scratch);
    }
    return true;
  };
  return s;
}
void mutant::before(const mfz_hull&, mfz_pose&, const mfz_hull&, mfz_pose&) {}
void mutant::after(const mfz_hull&, const mfz_pose&, const mfz_hull&, const mfz_pose&, mfz_manifold&) {}

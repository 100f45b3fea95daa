// Bug: SAT tests face normals only, never edge-edge axes.
#include "mutant_plugin.h"
#include "generator/sat.h"

namespace {
mfz::SatResult faces_only(const mfz::PosedHull& a, const mfz::PosedHull& b) {
  mfz::SatResult best;
  best.depth = INFINITY;
  const auto consider = [&](const mfz::Vec3& axis, mfz::AxisKind kind, int fa, int fb) {
    bool along = true;
    const double overlap = mfz::overlap_along(a, b, axis, along);
    if (overlap < best.depth || overlap < 0) best = {overlap < 0, along ? axis : mfz::Vec3(-axis), overlap, kind, fa, fb};
    return overlap >= 0;
  };
  for (int f = 0; f < a.face_count(); ++f)
    if (!consider(a.world_face_normal(f), mfz::AxisKind::face_a, f, -1)) return best;
  for (int f = 0; f < b.face_count(); ++f)
    if (!consider(b.world_face_normal(f), mfz::AxisKind::face_b, -1, f)) return best;
  return best;
}
}  // namespace

const char* const mutant::name = "mutant-edge-axes-skipped";
mfz::ClippingSteps mutant::steps() {
  mfz::ClippingSteps s;
  s.sat = faces_only;
  return s;
}
void mutant::before(const mfz_hull&, mfz_pose&, const mfz_hull&, mfz_pose&) {}
void mutant::after(const mfz_hull&, const mfz_pose&, const mfz_hull&, const mfz_pose&, mfz_manifold&) {}

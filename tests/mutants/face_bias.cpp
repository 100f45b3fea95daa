// Correct under its profile: SAT prefers a face axis whose overlap is within
// 5% of the least (as engines do for stable stacking: Box2D's relative
// tolerance, Bullet's and ODE's face-first preferences). It declares
// face-bias=0.05; without it, depth-exact fails.
#define MUTANT_PROFILE "face-bias=0.05"
#include "mutant_plugin.h"

#include "generator/sat.h"

namespace {

constexpr double kBias = 0.05;

// The least overlap over the face normals of A (B beyond +n) and of B (B
// beyond -n), a face axis counted one way only, as the built-in's SAT does.
mfz::SatResult best_face_axis(const mfz::PosedHull& a, const mfz::PosedHull& b) {
  mfz::SatResult best;
  best.depth = std::numeric_limits<double>::infinity();
  for (int f = 0; f < a.face_count(); ++f) {
    const mfz::Vec3 n = a.world_face_normal(f);
    const double overlap = a.project(n).max - b.project(n).min;
    if (overlap < best.depth) best = {false, n, overlap, mfz::AxisKind::face_a, f, -1};
  }
  for (int f = 0; f < b.face_count(); ++f) {
    const mfz::Vec3 n = b.world_face_normal(f);
    const double overlap = b.project(n).max - a.project(n).min;
    if (overlap < best.depth) best = {false, -n, overlap, mfz::AxisKind::face_b, -1, f};
  }
  return best;
}

}  // namespace

const char* const mutant::name = "correct-face-bias";
mfz::ClippingSteps mutant::steps() {
  mfz::ClippingSteps s;
  s.sat = [](const mfz::PosedHull& a, const mfz::PosedHull& b) {
    const mfz::SatResult exact = mfz::run_sat(a, b);
    if (exact.separated || exact.kind != mfz::AxisKind::edge_edge) return exact;
    const mfz::SatResult face = best_face_axis(a, b);
    return face.depth <= (1 + kBias) * exact.depth ? face : exact;
  };
  return s;
}
void mutant::before(const mfz_hull&, mfz_pose&, const mfz_hull&, mfz_pose&) {}
void mutant::after(const mfz_hull&, const mfz_pose&, const mfz_hull&, const mfz_pose&, mfz_manifold&) {}

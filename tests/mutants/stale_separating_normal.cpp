// Correct: the built-in generator, except that a pair it finds apart is
// reported with the separating normal of the last pair it found apart, as a
// generator that keeps a separating-axis cache may. The contract checks no
// normal or penetration where the hulls do not collide, so every check must
// pass, `deterministic` included.
#include "mutant_plugin.h"

const char* const mutant::name = "correct-stale-separating-normal";
mfz::ClippingSteps mutant::steps() { return {}; }
void mutant::before(const mfz_hull&, mfz_pose&, const mfz_hull&, mfz_pose&) {}
void mutant::after(const mfz_hull&, const mfz_pose&, const mfz_hull&, const mfz_pose&, mfz_manifold& m) {
  if (m.colliding) return;
  static thread_local mfz_vec3 remembered = {0, 0, 1};
  static thread_local double remembered_gap = 0;
  std::swap(m.normal, remembered);
  std::swap(m.penetration, remembered_gap);
}

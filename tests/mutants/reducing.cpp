// Correct: the built-in generator reducing its manifold to at most 4 contacts
// (deepest; farthest from it; largest triangle; largest quadrilateral), as
// engines with persistent manifolds do. It must pass.
#define MUTANT_PROFILE "max-contacts=4"
#include "mutant_plugin.h"

namespace {
mfz::Vec3 at(const mfz_contact& c) { return mfz::to_vec(c.point_on_a); }

int pick(const mfz_manifold& m, const bool* taken, double (*score)(const mfz_manifold&, const int*, int, int),
         const int* chosen, int count) {
  int best = -1;
  double best_score = -1;
  for (int i = 0; i < m.contact_count; ++i)
    if (!taken[i])
      if (const double s = score(m, chosen, count, i); s > best_score) best_score = s, best = i;
  return best;
}
}  // namespace

const char* const mutant::name = "correct-reducing";
mfz::ClippingSteps mutant::steps() { return {}; }
void mutant::before(const mfz_hull&, mfz_pose&, const mfz_hull&, mfz_pose&) {}
void mutant::after(const mfz_hull&, const mfz_pose&, const mfz_hull&, const mfz_pose&, mfz_manifold& m) {
  if (m.contact_count <= 4) return;
  bool taken[MFZ_MAX_CONTACTS] = {};
  int chosen[4];
  const auto deepest = [](const mfz_manifold& m, const int*, int, int i) { return -m.contacts[i].penetration; };
  const auto farthest = [](const mfz_manifold& m, const int* c, int, int i) {
    return (at(m.contacts[i]) - at(m.contacts[c[0]])).norm();
  };
  const auto triangle = [](const mfz_manifold& m, const int* c, int, int i) {
    return (at(m.contacts[c[1]]) - at(m.contacts[c[0]])).cross(at(m.contacts[i]) - at(m.contacts[c[0]])).norm();
  };
  const auto quad = [](const mfz_manifold& m, const int* c, int, int i) {
    // The area of the hull of the three kept points and this one: the
    // largest of the three quadrilaterals they make (a point inside the
    // triangle makes none larger than it). Not the largest triangle the
    // point makes with an edge: that picks a point beside a kept one.
    const mfz::Vec3 p[4] = {at(m.contacts[c[0]]), at(m.contacts[c[1]]), at(m.contacts[c[2]]), at(m.contacts[i])};
    const auto area = [&](int a, int b, int d, int e) {
      return 0.5 * ((p[b] - p[a]).cross(p[d] - p[a]) + (p[d] - p[a]).cross(p[e] - p[a])).norm();
    };
    return std::max({area(0, 1, 2, 3), area(0, 1, 3, 2), area(0, 3, 1, 2)});
  };
  double (*rules[4])(const mfz_manifold&, const int*, int, int) = {deepest, farthest, triangle, quad};
  int count = 0;
  for (auto rule : rules) {
    const int i = pick(m, taken, rule, chosen, count);
    if (i < 0) break;
    taken[i] = true;
    chosen[count++] = i;
  }
  mfz_contact kept[4];
  for (int k = 0; k < count; ++k) kept[k] = m.contacts[chosen[k]];
  for (int k = 0; k < count; ++k) m.contacts[k] = kept[k];
  m.contact_count = count;
}

// Correct: the built-in generator reducing its manifold to at most 4
// contacts, the four that span the largest area, as engines with persistent
// manifolds reduce theirs. It must pass: the contract names this reducer.
//
// It kept four picked one at a time once (the deepest, the farthest from it,
// the largest triangle, the largest quadrilateral), as Bullet's cache does.
// On two plates 0.1 thick sunk through each other that pick left out the
// other full-depth end of the first-touching strip and the three points on
// the far side, and missed the whole intersection's centroid by 0.168
// (tolerance 0.124); the four of largest area enclose both centroids (O23,
// manifuzz fuzz).
#define MUTANT_PROFILE "max-contacts=4"
#include "mutant_plugin.h"

namespace {
mfz::Vec3 at(const mfz_contact& c) { return mfz::to_vec(c.point_on_a); }

// Twice the area of triangle pqr, projected along unit n.
double twice_triangle(const mfz::Vec3& p, const mfz::Vec3& q, const mfz::Vec3& r, const mfz::Vec3& n) {
  return std::abs((q - p).cross(r - p).dot(n));
}

// Twice the area of the convex hull of four points, projected along unit n:
// the largest of the three quadrilaterals through them (a convex one is its
// hull) and of the four triangles (one point inside the other three).
double twice_hull_area(const mfz::Vec3 (&p)[4], const mfz::Vec3& n) {
  const auto quad = [&](int a, int b, int c, int d) {
    return std::abs(((p[b] - p[a]).cross(p[c] - p[a]) + (p[c] - p[a]).cross(p[d] - p[a])).dot(n));
  };
  return std::max({quad(0, 1, 2, 3), quad(0, 1, 3, 2), quad(0, 3, 1, 2), twice_triangle(p[1], p[2], p[3], n),
                   twice_triangle(p[0], p[2], p[3], n), twice_triangle(p[0], p[1], p[3], n),
                   twice_triangle(p[0], p[1], p[2], n)});
}
}  // namespace

const char* const mutant::name = "correct-reducing";
mfz::ClippingSteps mutant::steps() { return {}; }
void mutant::before(const mfz_hull&, mfz_pose&, const mfz_hull&, mfz_pose&) {}
void mutant::after(const mfz_hull&, const mfz_pose&, const mfz_hull&, const mfz_pose&, mfz_manifold& m) {
  if (m.contact_count <= 4) return;
  const mfz::Vec3 n = mfz::to_vec(m.normal);
  // Every four of at most MFZ_MAX_CONTACTS (1,820 of 16); the first found
  // keeps a tie, so the answer is deterministic.
  int best[4] = {0, 1, 2, 3};
  double best_area = -1;
  for (int i = 0; i < m.contact_count; ++i)
    for (int j = i + 1; j < m.contact_count; ++j)
      for (int k = j + 1; k < m.contact_count; ++k)
        for (int l = k + 1; l < m.contact_count; ++l) {
          const mfz::Vec3 p[4] = {at(m.contacts[i]), at(m.contacts[j]), at(m.contacts[k]), at(m.contacts[l])};
          if (const double area = twice_hull_area(p, n); area > best_area) {
            best_area = area;
            best[0] = i, best[1] = j, best[2] = k, best[3] = l;
          }
        }
  mfz_contact kept[4];
  for (int k = 0; k < 4; ++k) kept[k] = m.contacts[best[k]];
  for (int k = 0; k < 4; ++k) m.contacts[k] = kept[k];
  m.contact_count = 4;
}

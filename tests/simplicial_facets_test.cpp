// The brute-force builder of small hulls answers only where Qhull would give
// the same facets, and declines everywhere else.
#include "geometry/simplicial_facets.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <random>
#include <set>
#include <string>

#include "geometry/hull.h"
#include "test_support.h"

namespace mfz {
namespace {

// A facet as the set of its points: Qhull's order and ours differ.
std::set<std::array<int, 3>> facet_sets(const std::vector<QhullFacet>& facets) {
  std::set<std::array<int, 3>> out;
  for (const QhullFacet& f : facets) {
    EXPECT_EQ(f.point_ids.size(), 3u);
    std::array<int, 3> ids{f.point_ids[0], f.point_ids[1], f.point_ids[2]};
    std::sort(ids.begin(), ids.end());
    out.insert(ids);
  }
  return out;
}

// Clouds on a sphere and inside a ball (interior points), 4 to 12 points.
std::vector<Vec3> cloud(int count, unsigned seed) {
  std::vector<Vec3> points = test::sphere_points(count, seed);
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> radius(0.2, 1.0);
  if (seed % 2)
    for (Vec3& p : points) p *= radius(random);
  return points;
}

TEST(SimplicialFacets, AreQhullsFacetsOnCloudsInGeneralPosition) {
  int answered = 0;
  for (unsigned seed = 1; seed <= 300; ++seed) {
    const std::vector<Vec3> points = cloud(4 + static_cast<int>(seed % 9), seed);
    const auto simplicial = simplicial_facets(points);
    if (!simplicial) continue;
    ++answered;
    std::string error;
    const std::vector<QhullFacet> qhull = qhull_facets(points, /*triangulate=*/false, error);
    ASSERT_EQ(facet_sets(*simplicial), facet_sets(qhull)) << "seed " << seed;
    for (const QhullFacet& f : *simplicial) {
      const Vec3 a = points[f.point_ids[0]], b = points[f.point_ids[1]], c = points[f.point_ids[2]];
      EXPECT_GT((b - a).cross(c - a).dot(f.normal), 0) << "counter-clockwise seen from outside";
      EXPECT_NEAR(f.normal.norm(), 1, 1e-15);
      for (const Vec3& p : points) EXPECT_LE(f.normal.dot(p) - f.offset, 1e-15) << "every point below";
      const auto same = std::find_if(qhull.begin(), qhull.end(), [&](const QhullFacet& q) {
        return facet_sets({q}) == facet_sets({f});
      });
      EXPECT_LT((same->normal.normalized() - f.normal).norm(), 1e-13) << "the same plane as Qhull's";
    }
  }
  EXPECT_GT(answered, 280) << "clouds in general position are answered";
}

TEST(SimplicialFacets, DeclineCoplanarFacesAndLargeClouds) {
  EXPECT_FALSE(simplicial_facets(test::box_points(1, 2, 3))) << "a box's faces are two triangles each";
  std::vector<Vec3> pyramid = {{0, 0, 1}, {-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  EXPECT_FALSE(simplicial_facets(pyramid)) << "a square base";
  pyramid[4].z() = 1e-12;  // nearer its base's plane than kNearPlane
  EXPECT_FALSE(simplicial_facets(pyramid));
  pyramid[4].z() = -1e-3;  // a true fold: two triangles
  EXPECT_TRUE(simplicial_facets(pyramid));
  EXPECT_FALSE(simplicial_facets(test::sphere_points(kSimplicialMaxPoints + 1, 5)));
  EXPECT_FALSE(simplicial_facets(test::sphere_points(3, 5)));
}

// A point in the middle of a hull's edge lies on no facet's plane but the
// two it joins; the triangles through it do not close, and Qhull decides.
TEST(SimplicialFacets, APointOnAnEdgeLeavesTheHullToQhull) {
  const std::vector<Vec3> with_midpoint = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.5, 0, 0}};
  const HullBuild built = build_hull(with_midpoint);
  ASSERT_TRUE(built.hull) << built.error;
  EXPECT_EQ(built.hull->vertex_count(), 4) << "the midpoint is not a vertex";
  EXPECT_EQ(built.hull->face_count(), 4);
}

}  // namespace
}  // namespace mfz

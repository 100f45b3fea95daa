// The builder of hulls in general position answers only where Qhull would
// give the same facets, and declines everywhere else; where the brute force
// over every triple it replaced answered, it gives the same facets to the bit.
#include "geometry/simplicial_facets.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <random>
#include <set>
#include <string>

#include "families.h"
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

// The brute force the builder replaced: every triangle of three points with
// every other point clearly below its plane is a facet; a point within
// kNearPlane of such a plane declines.
std::optional<std::vector<QhullFacet>> every_triple(const std::vector<Vec3>& points) {
  const int n = static_cast<int>(points.size());
  double diameter = 0;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) diameter = std::max(diameter, (points[i] - points[j]).squaredNorm());
  diameter = std::sqrt(diameter);
  std::vector<QhullFacet> facets;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      for (int k = j + 1; k < n; ++k) {
        const Vec3 normal = (points[j] - points[i]).cross(points[k] - points[i]);
        const double twice_area = normal.norm();
        if (!(twice_area > kNearPlane * diameter * diameter)) continue;
        const double near = kNearPlane * diameter * twice_area;
        int above = 0, below = 0, on = 0;
        for (int l = 0; l < n; ++l) {
          if (l == i || l == j || l == k) continue;
          const double height = normal.dot(points[l] - points[i]);
          above += height > near;
          below += height < -near;
          on += std::abs(height) <= near;
        }
        if (above > 0 && below > 0) continue;
        if (on > 0) return std::nullopt;
        const bool outward = above == 0;
        QhullFacet facet;
        facet.normal = (outward ? normal : Vec3(-normal)) / twice_area;
        facet.offset = facet.normal.dot(points[i]);
        facet.point_ids = outward ? std::vector<int>{i, j, k} : std::vector<int>{i, k, j};
        facets.push_back(std::move(facet));
      }
  return facets;
}

// Clouds on a sphere and inside a ball (interior points).
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

TEST(SimplicialFacets, AreQhullsFacetsOnLargeCloudsInGeneralPosition) {
  int answered = 0;
  for (unsigned seed = 1; seed <= 60; ++seed) {
    const std::vector<Vec3> points = cloud(13 + static_cast<int>(seed * 7 % (kSimplicialMaxPoints - 12)), seed);
    const auto grown = simplicial_facets(points);
    if (!grown) continue;
    ++answered;
    std::string error;
    ASSERT_EQ(facet_sets(*grown), facet_sets(qhull_facets(points, /*triangulate=*/false, error)))
        << "seed " << seed << ", " << points.size() << " points";
  }
  EXPECT_GT(answered, 55) << "clouds in general position are answered";
}

// Far from the origin Qhull merges within its coordinates' rounding; the
// grown hull declines there rather than give other facets.
TEST(SimplicialFacets, AreQhullsFacetsOnCloudsFarFromTheOrigin) {
  int answered = 0;
  for (unsigned seed = 1; seed <= 240; ++seed) {
    std::vector<Vec3> points = test::sphere_points(8 + static_cast<int>(seed % 5) * 23, seed);
    const double offset = std::pow(10.0, 6 + static_cast<int>(seed % 6));
    const Vec3 away = offset * test::sphere_points(1, 5000 + seed)[0];
    for (Vec3& p : points) p += away;
    const auto grown = simplicial_facets(points);
    if (!grown) continue;
    ++answered;
    std::string error;
    ASSERT_EQ(facet_sets(*grown), facet_sets(qhull_facets(points, /*triangulate=*/false, error)))
        << "seed " << seed << ", " << points.size() << " points " << offset << " from the origin";
  }
  EXPECT_GT(answered, 80);
}

// Every family of the property suite (folds of 1e-9 rad, slabs, needles,
// 64-gon caps, far frames): wherever the grown hull answers, Qhull gives
// the same triangles, and where a family's faces are nearly coplanar it
// declines.
RC_GTEST_PROP(SimplicialFacets, AreQhullsFacetsOnEveryFamilyOfTheSuite, ()) {
  const props::GeneratedCase c = *props::any_case();
  for (const std::vector<Vec3>* points : {&c.file.points_a, &c.file.points_b}) {
    const auto grown = simplicial_facets(*points);
    RC_TAG(grown ? "grown" : "declined");
    if (!grown) continue;
    std::string error;
    RC_ASSERT(facet_sets(*grown) == facet_sets(qhull_facets(*points, /*triangulate=*/false, error)));
  }
}

TEST(SimplicialFacets, GiveTheBruteForcesFacetsToTheBitWhereItAnswered) {
  int compared = 0;
  for (unsigned seed = 1; seed <= 400; ++seed) {
    std::vector<Vec3> points = cloud(4 + static_cast<int>(seed % 9), seed);
    // Every tenth cloud with a point pushed nearly onto another's plane.
    if (seed % 10 == 0) points.back() = 0.5 * (points[0] + points[1]) + 1e-10 * points.back();
    const auto brute = every_triple(points), grown = simplicial_facets(points);
    if (!brute) {
      EXPECT_FALSE(grown) << "seed " << seed << ": the brute force declined";
      continue;
    }
    if (!grown) continue;  // it declined where a triple's plane was near a point: Qhull decides
    ++compared;
    ASSERT_EQ(brute->size(), grown->size()) << "seed " << seed;
    for (size_t f = 0; f < brute->size(); ++f) {
      EXPECT_EQ((*brute)[f].point_ids, (*grown)[f].point_ids) << "seed " << seed << ", facet " << f;
      EXPECT_EQ((*brute)[f].normal, (*grown)[f].normal) << "seed " << seed << ", facet " << f;
      EXPECT_EQ((*brute)[f].offset, (*grown)[f].offset) << "seed " << seed << ", facet " << f;
    }
  }
  EXPECT_GT(compared, 300);
}

// Points of a small lattice, each moved by less than kNearPlane: four of
// them lie nearly on a plane almost everywhere, so the brute force declines,
// and so must the grown hull, whichever point reached such a plane first.
TEST(SimplicialFacets, DeclineNearlyCoplanarLatticesAsTheBruteForceDid) {
  int declined = 0;
  for (unsigned seed = 1; seed <= 300; ++seed) {
    std::mt19937 random(seed);
    std::uniform_int_distribution<int> coordinate(0, 2);
    std::uniform_real_distribution<double> jitter(-1e-11, 1e-11);
    std::vector<Vec3> points;
    const int count = 5 + static_cast<int>(seed % 8);
    while (static_cast<int>(points.size()) < count) {
      const Vec3 p(coordinate(random) + jitter(random), coordinate(random) + jitter(random),
                   coordinate(random) + jitter(random));
      if (std::none_of(points.begin(), points.end(), [&](const Vec3& q) { return (q - p).norm() < 0.5; }))
        points.push_back(p);
    }
    if (every_triple(points)) continue;
    ++declined;
    EXPECT_FALSE(simplicial_facets(points)) << "seed " << seed;
  }
  EXPECT_GT(declined, 200);
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
  std::vector<Vec3> flat = test::sphere_points(9, 6);
  for (Vec3& p : flat) p.z() *= 1e-12;
  EXPECT_FALSE(simplicial_facets(flat)) << "every point on one plane";
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

// The closest point of a polygon with its core: the same point, to the bit,
// as the full inside test gives, for points deep inside, near every edge on
// either side, and outside.
#include "geometry/closest_point.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "geometry/loop_corners.h"
#include "test_support.h"

namespace mfz {
namespace {

// A regular polygon of `corners`, turned and moved far from the origin, as a
// reference face's world loop is.
std::vector<Vec3> turned_polygon(int corners, const Vec3& at, const Quat& turn) {
  std::vector<Vec3> loop;
  for (int k = 0; k < corners; ++k) {
    const double t = 2 * M_PI * k / corners;
    loop.push_back(at + turn * Vec3(std::cos(t), std::sin(t), 0));
  }
  return loop;
}

TEST(PolygonCore, GivesTheClosestPointTheInsideTestGives) {
  int by_core = 0, by_test = 0;
  for (const int corners : {3, 8, 64, 200}) {
    for (const double far : {0.0, 1e3, 1e6}) {
      const Quat turn = test::about(Vec3(1, 2, 3), 0.3 * corners + far * 1e-6);
      const Vec3 at = far * Vec3(0.6, -0.8, 0.3);
      const std::vector<Vec3> loop = turned_polygon(corners, at, turn);
      const Vec3 normal = turn * Vec3(0, 0, 1);
      const PolygonCore core = polygon_core(loop.data(), corners, normal);
      ASSERT_GT(core.radius, 0) << corners << " corners";
      // The inradius of a regular polygon of unit circumradius.
      const double inradius = std::cos(M_PI / corners);
      for (int i = 0; i < 400; ++i) {
        // Odd points toward an edge's midpoint, from 1e-6 inside it to 1e-6
        // beyond, in steps finer than the core's room; even ones anywhere,
        // from the centre out.
        const double angle = i % 2 == 1 ? 2 * M_PI * (i % corners + 0.5) / corners : 0.0137 * i * corners;
        const double ring = inradius * (i % 2 == 0 ? 0.02 * (i % 50) : 1 + 1e-7 * ((i % 21) - 10));
        const Vec3 p = at + turn * Vec3(ring * std::cos(angle), ring * std::sin(angle), 0.1 * std::sin(3.0 * i));
        const Vec3 with_core = closest_point_on_polygon(p, loop.data(), corners, normal, core);
        const Vec3 without = closest_point_on_polygon(p, loop.data(), corners, normal);
        EXPECT_EQ(with_core, without) << corners << " corners, " << far << " out, point " << i;
        const Vec3 projected = p - normal.dot(p - loop[0]) * normal;
        ((projected - core.centre).norm() < core.radius ? by_core : by_test) += 1;
      }
    }
  }
  // Both ways were taken, many times each.
  EXPECT_GT(by_core, 1000);
  EXPECT_GT(by_test, 1000);
}

// The corners either side, without a division, are the remainders' corners
// on every loop a face can have (3 to a hull's 1,024 points).
TEST(LoopCorners, NextAndPreviousAreTheRemaindersAroundTheLoop) {
  for (int n = 1; n <= 1024; ++n)
    for (int k = 0; k < n; ++k) {
      ASSERT_EQ(next_corner(k, n), (k + 1) % n) << k << " of " << n;
      ASSERT_EQ(previous_corner(k, n), (k + n - 1) % n) << k << " of " << n;
    }
}

// A face 80,000 across with two corners 1e-9 apart, the edge between them
// turned back as rounding leaves such an edge: a point 1e-8 above the face,
// its foot far inside, lies right of that edge. Its closest point is its
// foot, 1e-8 away, not the nearest long edge's point 20,000 away, which
// made two hulls 2.3e-8 apart 23.5 apart to the exact oracle (h33).
TEST(ClosestPointOnPolygon, AFootInsideALoopWithAnEdgeTooShortForItsDirectionIsItsOwnClosestPoint) {
  const std::vector<Vec3> loop = {Vec3(0, 0, 0), Vec3(80000, 0, 0), Vec3(80000 - 1e-9, -1e-10, 0), Vec3(0, 60000, 0)};
  const Vec3 p(20000, 20000, 1e-8);
  for (int turn = 0; turn < 4; ++turn) {  // every corner first in the loop
    std::vector<Vec3> turned;
    for (int k = 0; k < 4; ++k) turned.push_back(loop[(k + turn) % 4]);
    const Vec3 nearest = closest_point_on_polygon(p, turned.data(), 4, Vec3(0, 0, 1));
    EXPECT_LE((nearest - p).norm(), 1.1e-8) << "loop from corner " << turn;
    const PolygonCore core = polygon_core(turned.data(), 4, Vec3(0, 0, 1));
    EXPECT_LE((closest_point_on_polygon(p, turned.data(), 4, Vec3(0, 0, 1), core) - p).norm(), 1.1e-8)
        << "with its core, from corner " << turn;
  }
}

TEST(PolygonCore, IsEmptyForADegenerateLoop) {
  const std::vector<Vec3> segment = {Vec3(0, 0, 0), Vec3(1, 0, 0)};
  EXPECT_LT(polygon_core(segment.data(), 2, Vec3(0, 0, 1)).radius, 0);
  const std::vector<Vec3> point = {Vec3(1, 1, 1), Vec3(1, 1, 1), Vec3(1, 1, 1)};
  EXPECT_LT(polygon_core(point.data(), 3, Vec3(0, 0, 1)).radius, 0);
}

}  // namespace
}  // namespace mfz

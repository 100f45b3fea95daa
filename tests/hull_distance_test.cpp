#include <gtest/gtest.h>

#include "geometry/hull_distance.h"
#include "test_support.h"

namespace mfz {
namespace {

TEST(SignedDistance, IsMinusTheDistanceToTheNearestPlaneInside) {
  const Hull cube = *build_hull(test::box_points(1, 1, 1)).hull;
  EXPECT_DOUBLE_EQ(signed_distance(cube, {}, Vec3(0.25, 0, 0)), -0.75);
}

TEST(SignedDistance, IsTheDistanceToTheNearestFaceOutside) {
  const Hull cube = *build_hull(test::box_points(1, 1, 1)).hull;
  EXPECT_NEAR(signed_distance(cube, {}, Vec3(2, 2, 0)), std::sqrt(2.0), 1e-15);
}

// Two faces of a hull folded by 1e-14 along a diagonal: a point on the one
// (its plane says 0) lies 1e-13 outside the other's plane by rounding. Its
// distance is that rounding, not the 0.3 to the other face's polygon: the
// nearest point may be on a face whose plane the point is not outside of
// (manifuzz fuzz, the built-in, a 1e-3 tetrahedron deep inside a 2e4 hull).
TEST(SignedDistance, APointOnAFaceIsOnTheSurfaceWhenRoundingPutsItOutsideAFoldedNeighbour) {
  const std::vector<Vec3> points = {{-8000, -1000, 0},   {-8000, 1000, 5000}, {0, -1000, -5000}, {8000, -1000, 5000},
                                    {8000, 1000, 0},     {8000, 1000, 5000},
                                    {-7999.999999994894, 1000.0000000001725, -5000}};
  const Hull folded = *build_hull(points).hull;
  const Vec3 on_surface(-0.034176573742342953, 1000.0000000000863, -0.38336325324223708);
  EXPECT_LT(std::abs(signed_distance(folded, {}, on_surface)), 1e-9 * folded.diameter());
}

}  // namespace
}  // namespace mfz

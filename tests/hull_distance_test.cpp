#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "geometry/closest_point.h"
#include "geometry/hull_distance.h"
#include "test_support.h"

namespace mfz {
namespace {

TEST(SignedDistance, IsMinusTheDistanceToTheNearestPlaneInside) {
  const Hull cube = *build_hull(test::box_points(1, 1, 1)).hull;
  EXPECT_DOUBLE_EQ(signed_distance(cube, {}, Vec3(0.25, 0, 0)), -0.75);
}

// Inside, the distance is the highest of the face planes' heights, to the
// bit: the heights taken in vector lanes (stop 64) are the face's normal
// dotted with the point less Hull::face_offset, each dot product summed as
// Vec3's is.
TEST(SignedDistance, InsideIsTheHighestPlaneHeightToTheBitOfFaceNormalAndOffset) {
  for (const int points : {8, 32, 100}) {
    const Hull hull = *build_hull(test::sphere_points(points, 40u + points)).hull;
    std::mt19937_64 random(points);
    std::uniform_real_distribution<double> coordinate(-0.6, 0.6);
    int inside = 0;
    for (int k = 0; k < 400; ++k) {
      const Vec3 p(coordinate(random), coordinate(random), coordinate(random));
      double highest = -INFINITY;
      for (int f = 0; f < hull.face_count(); ++f)
        highest = std::max(highest, hull.face_normal(f).dot(p) - hull.face_offset(f));
      if (!(highest < 0)) continue;
      ++inside;
      EXPECT_EQ(signed_distance(hull, {}, p), highest) << points << " points, " << p.transpose();
    }
    EXPECT_GT(inside, 50) << points << " points";
  }
}

TEST(SignedDistance, IsTheDistanceToTheNearestFaceOutside) {
  const Hull cube = *build_hull(test::box_points(1, 1, 1)).hull;
  EXPECT_NEAR(signed_distance(cube, {}, Vec3(2, 2, 0)), std::sqrt(2.0), 1e-15);
}

// A point 1 below a 1,000-gon face is 1 from the hull wherever it stands
// under the face. With room for 512 corners the face was measured by the
// first 512 of its loop, a half disc: below the other half, within its
// depth of the half disc's chord (where the vertices' GJK is not asked), a
// point was as far as the chord, 8% further (F61's hulls).
TEST(SignedDistance, APointBelowAnyPartOfAThousandGonFaceIsAsFarAsItsDepth) {
  const Hull hull = *build_hull(test::pyramid_points(1000, 3, 2)).hull;
  for (int k = 0; k < 8; ++k) {
    const Vec3 below(0.5 * std::cos(M_PI * k / 4), 0.5 * std::sin(M_PI * k / 4), -1);
    EXPECT_NEAR(signed_distance(hull, {}, below), 1, 1e-12) << below.transpose();
  }
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

// A pyramid whose base has a vertex 6.9e-11 below it and 3e-10 from its
// neighbour: the base's two merged faces and the sliver between them leave
// a wedge 2.5 wide uncovered, 73 from the short edge. A point there, 4.8e-11
// inside the hull of the vertices (exact arithmetic), measured 2.55 outside
// by the faces; the vertices say it is on the surface (h16: a false
// on-surface of 1.25e-4 L on the built-in, swap-symmetry, manifuzz fuzz
// --strict).
TEST(SignedDistance, APointOverACrackBetweenMergedFacesIsOnTheSurfaceOfTheVertices) {
  const std::vector<Vec3> points = {{10000, 0, 0},   {10000, 1000, 0}, {9600, 2800, 0},   {9100, 4200, 0},
                                    {8400, 5400, 0}, {6550, 7600, 0},  {-9000, 4200, 0},  {-9900, 1000, 0},
                                    {-10000, 0, 0},  {8000, -7000, 0}, {9898.214418809326, -1423.1483827328532, 0},
                                    {0, 0, 10000},   {9898.214418809295, -1423.1483827325628, -6.9e-11}};
  const Hull pyramid = *build_hull(points).hull;
  const Vec3 over_the_crack(9890.4653396695066, -1350.3868087508836, -2.0008883439004421e-11);
  EXPECT_LT(std::abs(signed_distance(pyramid, {}, over_the_crack)), 1e-9 * pyramid.diameter());
  EXPECT_LT(std::abs(signed_distance_past(pyramid, {}, over_the_crack, 0)), 1e-9 * pyramid.diameter());
}

// The nearest face by brute force: minus the least depth under a plane
// inside, the nearest polygon outside.
double distance_by_every_face(const Hull& hull, const Vec3& p) {
  double inside = -INFINITY, outside = INFINITY;
  for (int f = 0; f < hull.face_count(); ++f) {
    std::vector<Vec3> loop;
    for (int k = 0; k < hull.face_size(f); ++k) loop.push_back(hull.vertex(hull.face_vertex(f, k)));
    inside = std::max(inside, hull.face_normal(f).dot(p) - hull.face_offset(f));
    outside = std::min(outside, (closest_point_on_polygon(p, loop.data(), hull.face_size(f), hull.face_normal(f)) - p).norm());
  }
  return inside <= 0 ? inside : outside;
}

// Where the vertices decide, a point truly outside keeps its distance:
// past a needle's tip, where the face planes are near and the faces far,
// and beside its sharp edges, as every face measured one by one says.
TEST(SignedDistance, APointPastASharpTipOrEdgeKeepsItsDistanceWhereTheVerticesDecide) {
  const Hull needle = *build_hull({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.5, 0.5, 100}}).hull;
  const Vec3 tip(0.5, 0.5, 100);
  for (const Vec3& away : {Vec3(0, 0, 1), Vec3(0.6, 0.8, 0), Vec3(1, 1, 1).normalized(), Vec3(-1, 0, 0.01).normalized()}) {
    const Vec3 p = tip + 2.0 * away;
    EXPECT_NEAR(signed_distance(needle, {}, p), distance_by_every_face(needle, p), 1e-12 * needle.diameter())
        << away.transpose();
  }
}

// h27: a sheet 6.5e8 long whose two wide faces meet at a knife edge 1.5e-5
// rad apart; a point in their planes, 3.6 beyond the knife edge beside the
// tip, is within 5.4e-5 of every plane, so the vertices decide, and their
// GJK must not take a simplex of no volume (a support point met again,
// its triple product rounded to -0.006) for one that holds the point: it
// measured 0.
TEST(SignedDistance, APointBesideANeedlesKnifeEdgeIsAsFarAsTheEdgeWhereTheVerticesDecide) {
  const Vec3 tip(-650377000, 0, 0.4), far_corner(26920, -8541.6, -60000), thick_corner(0.5, 0.85, -0.4);
  const Hull sheet = *build_hull({thick_corner, {0, 0, 0}, tip, far_corner}).hull;
  // The wide face holding the knife edge from the tip to the far corner,
  // and the way out of the sheet across that edge, in the face's plane.
  int wide = -1;
  for (int f = 0; f < sheet.face_count(); ++f)
    if (std::abs(sheet.face_normal(f).y()) > 0.9 && (wide < 0 || sheet.face_normal(f).y() > 0)) wide = f;
  ASSERT_GE(wide, 0);
  const Vec3 normal = sheet.face_normal(wide), edge = (far_corner - tip).normalized();
  Vec3 out = normal.cross(edge).normalized();
  if (out.dot(thick_corner - tip) > 0) out = -out;
  int measured = 0;
  for (const double along : {1000.0, 2000.0, 4648.0, 6000.0})
    for (const double beyond : {0.5, 1.0, 3.6, 6.5}) {
      const Vec3 p = tip + along * edge + beyond * out;
      const double by_faces = distance_by_every_face(sheet, p);
      if (!(by_faces > 0.4 * beyond)) continue;
      EXPECT_NEAR(signed_distance(sheet, {}, p), by_faces, 1e-3) << along << " along, " << beyond << " beyond";
      ++measured;
    }
  EXPECT_GE(measured, 12);
}

// signed_distance keeps 256 faces' heights and takes the others' again: on
// a hull of 596 faces, points just inside and just outside the faces past
// the 256th are as far as every face measured one by one says.
TEST(SignedDistance, FacesPastTheKeptHeightsCountInsideAndOutside) {
  const Hull ball = *build_hull(test::sphere_points(300, 7)).hull;
  ASSERT_GT(ball.face_count(), 512);
  for (int f = 256; f < ball.face_count(); f += 7) {
    Vec3 centre = Vec3::Zero();
    for (int k = 0; k < ball.face_size(f); ++k) centre += ball.vertex(ball.face_vertex(f, k));
    centre /= ball.face_size(f);
    for (const double off : {-1e-3, 1e-3}) {
      const Vec3 p = centre + off * ball.face_normal(f);
      EXPECT_NEAR(signed_distance(ball, {}, p), distance_by_every_face(ball, p), 1e-15) << "face " << f << ", " << off;
      EXPECT_NEAR(signed_distance(ball, {}, p), off, 1e-12) << "face " << f;
    }
  }
}

// Beyond its allowance signed_distance_past is signed_distance to the bit;
// within it, no more than the allowance: around a 40-point ball, points
// inside, on and outside at distances either side of each allowance.
TEST(SignedDistance, PastAnAllowanceIsExactAndWithinItAtMostTheAllowance) {
  const Hull ball = *build_hull(test::sphere_points(40, 3)).hull;
  const Pose turned{Vec3(3, -1, 2), Quat(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()))};
  int beyond = 0, within = 0;
  for (const Vec3& direction : test::sphere_points(200, 5))
    for (const double radius : {0.5, 0.99, 1.0, 1.01, 1.1, 1.5, 3.0}) {
      const Vec3 p = turned.to_world(radius * direction);
      const double exact = signed_distance(ball, turned, p);
      for (const double allowed : {0.0, 0.005, 0.05, 0.3, 1.0}) {
        const double past = signed_distance_past(ball, turned, p, allowed);
        if (exact > allowed) {
          EXPECT_EQ(past, exact) << "radius " << radius << ", allowed " << allowed;
          ++beyond;
        } else {
          EXPECT_LE(past, allowed) << "radius " << radius << ", allowed " << allowed;
          ++within;
        }
      }
    }
  EXPECT_GT(beyond, 1000);
  EXPECT_GT(within, 1000);
}

// Within its allowance signed_distance_past answers from the face the
// point stands highest over (the first such face where heights tie): off
// each face of a cube, that face's own distance, where any other face
// would answer further.
TEST(SignedDistance, WithinAnAllowanceTheFaceStoodHighestOverAnswersFirst) {
  const Hull cube = *build_hull(test::box_points(1, 1, 1)).hull;
  for (int f = 0; f < cube.face_count(); ++f) {
    const Vec3 n = cube.face_normal(f);
    const Vec3 p = 1.5 * n + 0.25 * n.unitOrthogonal();
    EXPECT_EQ(signed_distance_past(cube, {}, p, 10), 0.5) << "face " << f;
  }
}

}  // namespace
}  // namespace mfz

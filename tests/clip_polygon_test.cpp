#include "generator/clip_polygon.h"

#include <gtest/gtest.h>

#include <cmath>

#include "test_support.h"

namespace mfz {
namespace {

ClipPolygon unit_square() {
  ClipPolygon square;
  for (const Vec3& p : {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)}) square.push(p);
  return square;
}

TEST(SutherlandHodgman, ClippingASquareThroughTheMiddleKeepsTheInsideHalf) {
  ClipPolygon out;
  ASSERT_TRUE(clip_to_plane(unit_square(), Plane{Vec3(1, 0, 0), 0.5}, out));
  ASSERT_EQ(out.size(), 4);
  for (int k = 0; k < out.size(); ++k) EXPECT_LE(out[k].x(), 0.5);
}

TEST(SutherlandHodgman, APointOnThePlaneIsInside) {
  ClipPolygon out;
  clip_to_plane(unit_square(), Plane{Vec3(1, 0, 0), 1.0}, out);
  EXPECT_EQ(out.size(), 4);
}

TEST(SutherlandHodgman, APlaneMissingThePolygonRemovesEverything) {
  ClipPolygon out;
  clip_to_plane(unit_square(), Plane{Vec3(1, 0, 0), -0.1}, out);
  EXPECT_TRUE(out.empty());
}

TEST(SutherlandHodgman, CuttingACornerAddsOnePoint) {
  ClipPolygon out;
  clip_to_plane(unit_square(), Plane{Vec3(1, 1, 0).normalized(), 1.5 / std::sqrt(2.0)}, out);
  EXPECT_EQ(out.size(), 5);
}

// O3 / F23: the square's right edge lies in the plane x = 1, its ends a
// rounding error either side. Without a band the pass "crosses" that edge
// wherever rounding / rounding puts the crossing: here at the edge's middle.
ClipPolygon square_with_right_edge_off_by_rounding() {
  ClipPolygon square;
  for (const Vec3& p : {Vec3(0, 0, 0), Vec3(std::nextafter(1.0, 2.0), 0, 0), Vec3(std::nextafter(1.0, 0.0), 1, 0), Vec3(0, 1, 0)}) square.push(p);
  return square;
}

TEST(SutherlandHodgman, WithoutABandAnEdgeInThePlaneIsCrossedWhereRoundingSays) {
  ClipPolygon out;
  clip_to_plane(square_with_right_edge_off_by_rounding(), Plane{Vec3(1, 0, 0), 1.0}, out);
  ASSERT_EQ(out.size(), 5);
  bool crossing_mid_edge = false;
  for (int k = 0; k < out.size(); ++k) crossing_mid_edge |= out[k].y() > 0.25 && out[k].y() < 0.75;
  EXPECT_TRUE(crossing_mid_edge);
}

TEST(SutherlandHodgman, AnEdgeWithinTheBandOfThePlaneKeepsItsEndsAndAddsNoCrossing) {
  ClipPolygon out;
  clip_to_plane(square_with_right_edge_off_by_rounding(), Plane{Vec3(1, 0, 0), 1.0}, out, 1e-15);
  ASSERT_EQ(out.size(), 4);
  for (int k = 0; k < out.size(); ++k) EXPECT_TRUE(out[k].y() == 0 || out[k].y() == 1) << k;
}

TEST(SutherlandHodgman, ABandStillCutsAnEdgeThatReallyCrosses) {
  ClipPolygon out;
  clip_to_plane(unit_square(), Plane{Vec3(1, 0, 0), 0.5}, out, 1e-15);
  ASSERT_EQ(out.size(), 4);
  for (int k = 0; k < out.size(); ++k) EXPECT_LE(out[k].x(), 0.5);
}

// F32: the square's right edge leans 1e-6 rad off the plane x = 1, its lower
// end 1.5e-12 outside (a world's rounding the frame's band does not cover),
// its upper end inside. Interpolating puts the crossing 1.5e-6 up the edge;
// within the wider band the lower end crosses at its foot.
ClipPolygon square_with_right_edge_leaning_past_the_plane() {
  ClipPolygon square;
  for (const Vec3& p : {Vec3(0, 0, 0), Vec3(1 + 1.5e-12, 0, 0), Vec3(1 + 1.5e-12 - 1e-6, 1, 0), Vec3(0, 1, 0)})
    square.push(p);
  return square;
}

TEST(SutherlandHodgman, AnOutsideEndWithinTheWiderBandCrossesAtItsFoot) {
  ClipPolygon interpolated, at_foot;
  clip_to_plane(square_with_right_edge_leaning_past_the_plane(), Plane{Vec3(1, 0, 0), 1.0}, interpolated, 1e-15);
  clip_to_plane(square_with_right_edge_leaning_past_the_plane(), Plane{Vec3(1, 0, 0), 1.0}, at_foot, 1e-15, 1e-10);
  ASSERT_EQ(interpolated.size(), 5);
  ASSERT_EQ(at_foot.size(), 5);
  double highest_crossing = 0, foot_height = 1;
  for (int k = 0; k < interpolated.size(); ++k)
    if (interpolated[k].y() > 0 && interpolated[k].y() < 1) highest_crossing = interpolated[k].y();
  for (int k = 0; k < at_foot.size(); ++k)
    if (at_foot[k].x() == 1.0) foot_height = at_foot[k].y();
  EXPECT_GT(highest_crossing, 1e-6);
  EXPECT_EQ(foot_height, 0);
}

TEST(SutherlandHodgman, AnOutsideEndPastTheWiderBandIsStillInterpolated) {
  ClipPolygon out;
  clip_to_plane(unit_square(), Plane{Vec3(1, 0, 0), 0.5}, out, 1e-15, 1e-10);
  ASSERT_EQ(out.size(), 4);
  for (int k = 0; k < out.size(); ++k) EXPECT_LE(out[k].x(), 0.5);
}

// F48: the square's right edge lies 1e-9 rad off the plane x = 1, its upper
// end 1e-9 outside (past both bands), its lower end on the plane within the
// band of 1e-11, rounded one way or the other. Either way the lower end is
// the edge's crossing: the square keeps its three corners inside and adds
// nothing. Interpolating from the end 1e-12 inside put a crossing 1e-3 up
// the edge, where the end 1e-12 outside gave none (a tetrahedron's edge in a
// side plane, tilted 1e-12: one contact 2.5 from the other frame's).
TEST(SutherlandHodgman, AnInsideEndWithinTheBandIsTheCrossingWhicheverSideItRoundsTo) {
  const auto clipped = [](double lower_end) {
    ClipPolygon square, out;
    for (const Vec3& p : {Vec3(0, 0, 0), Vec3(1 + lower_end, 0, 0), Vec3(1 + 1e-9, 1, 0), Vec3(0, 1, 0)}) square.push(p);
    clip_to_plane(square, Plane{Vec3(1, 0, 0), 1.0}, out, 1e-11, 1e-11);
    return out;
  };
  for (const double lower_end : {-1e-12, 0.0, 1e-12}) {
    const ClipPolygon out = clipped(lower_end);
    ASSERT_EQ(out.size(), 4) << "lower end " << lower_end;
    for (int k = 0; k < out.size(); ++k) EXPECT_TRUE(out[k].y() == 0 || out[k].y() == 1) << "lower end " << lower_end;
  }
}

// F48's other half: a corner 5e-11 outside, within the wider band, between
// two ends 1e-12 outside, within the plane's band. Its edges lie in the
// plane to rounding, and it crosses at its foot (1, 1), as it does when its
// neighbours round to the plane's inner side; taking each neighbour as its
// edge's crossing lost the corner, and the polygon its right side's middle.
TEST(SutherlandHodgman, AnOutsideCornerWithinTheWiderBandKeepsItsFootBesideEndsOnThePlane) {
  ClipPolygon pentagon, out;
  for (const Vec3& p : {Vec3(0, 0, 0), Vec3(1 + 1e-12, 0, 0), Vec3(1 + 5e-11, 1, 0), Vec3(1 + 1e-12, 2, 0), Vec3(0, 2, 0)})
    pentagon.push(p);
  clip_to_plane(pentagon, Plane{Vec3(1, 0, 0), 1.0}, out, 1e-11, 1e-10);
  bool foot = false;
  for (int k = 0; k < out.size(); ++k) foot |= out[k] == Vec3(1, 1, 0);
  EXPECT_TRUE(foot);
}

// F52: a corner within the wider band inside the plane, its edge to a
// corner outside both bands lying 1e-9 rad off the plane. The wider band is
// the world's rounding that a corner carries; so far in, the corner is the
// edge's crossing, as its foot is when it rounds outside; the top edge
// still crosses, near (1, 1). Interpolating put
// a crossing 5e-2 along the edge from a corner 5e-11 inside (far out, a
// face beside the deepest corner: a contact 8658 from it in one frame).
TEST(SutherlandHodgman, AnInsideCornerWithinTheWiderBandIsItsEdgesCrossing) {
  for (const double corner : {-5e-11, -1e-12, 0.0, 1e-12, 5e-11}) {
    ClipPolygon square, out;
    for (const Vec3& p : {Vec3(0, 0, 0), Vec3(1 + corner, 0, 0), Vec3(1 + 1e-9, 1, 0), Vec3(0, 1, 0)}) square.push(p);
    clip_to_plane(square, Plane{Vec3(1, 0, 0), 1.0}, out, 1e-11, 1e-10);
    ASSERT_EQ(out.size(), 4) << "corner " << corner;
    for (int k = 0; k < out.size(); ++k)
      EXPECT_TRUE(out[k].y() == 0 || out[k].y() > 0.999) << "corner " << corner << ": a crossing at y " << out[k].y();
  }
}

// A sliver of the incident face at the end of the side's edge: a point on
// the plane at the edge's end, and two 1e-9 outside, one beside the end and
// one whose foot lies 0.5 past it. Past the edge's end a foot is no point of
// the side: the outside end is interpolated towards its inside neighbour
// instead, which is the end itself (F36: a contact 0.23 past the sharp
// corner of a sliver 3.1e-7 rad wide, 2e9 from the origin).
TEST(SutherlandHodgman, AFootPastTheEndOfTheSidesEdgeIsNoCrossing) {
  ClipPolygon sliver, out;
  for (const Vec3& p : {Vec3(1, 0, 0), Vec3(1 + 1e-9, 0, 0), Vec3(1 + 1e-9, -0.5, 0)}) sliver.push(p);
  const SideEdge edge{Vec3(1, 0, 0), Vec3(1, 1, 0)};
  ASSERT_TRUE(clip_to_plane(sliver, Plane{Vec3(1, 0, 0), 1.0}, out, 0, 1e-6, &edge));
  ASSERT_GT(out.size(), 0);
  for (int k = 0; k < out.size(); ++k) EXPECT_NEAR(out[k].y(), 0, 1e-9) << "point " << k;
}

// A triangle whose edge from (0, 0) to (3, 3.3) leaves the corner of the
// planes x <= 1 and y <= 1 through y = 1 first (at x = 0.909), and crosses
// x = 1 at y = 1.1, inside y's band of 0.2. The crossing x = 1 made is no
// corner of the triangle: taking it to its foot (1, 1) would lose the point
// where the edge leaves, and the answer would follow the planes' order (O8:
// a needle's contact 1.8e-8 deep dropped in one numbering, vertex-order).
TEST(SutherlandHodgman, TheOrderOfThePlanesKeepsTheCrossingsOfTwoSides) {
  ClipPolygon triangle;
  for (const Vec3& p : {Vec3(0, 0, 0), Vec3(3, 3.3, 0), Vec3(-1, 0.5, 0)}) triangle.push(p);
  const Plane x_side{Vec3(1, 0, 0), 1.0}, y_side{Vec3(0, 1, 0), 1.0};
  const auto clip_in_order = [&](const Plane& first, const Plane& second) {
    ClipPolygon once, twice;
    clip_to_plane(triangle, first, once, 0, 0.2);
    clip_to_plane(once, second, twice, 0, 0.2);
    return twice;
  };
  const ClipPolygon x_first = clip_in_order(x_side, y_side), y_first = clip_in_order(y_side, x_side);
  const auto holds = [](const ClipPolygon& polygon, const Vec3& p) {
    for (int k = 0; k < polygon.size(); ++k)
      if ((polygon[k] - p).norm() < 1e-12) return true;
    return false;
  };
  const Vec3 where_the_edge_leaves(1 / 1.1, 1, 0);
  EXPECT_TRUE(holds(y_first, where_the_edge_leaves));
  EXPECT_TRUE(holds(x_first, where_the_edge_leaves));
  for (int k = 0; k < x_first.size(); ++k) EXPECT_TRUE(holds(y_first, x_first[k])) << "point " << k;
  for (int k = 0; k < y_first.size(); ++k) EXPECT_TRUE(holds(x_first, y_first[k])) << "point " << k;
}

TEST(PointRemoval, DropsPointsOutsideWithoutAddingCrossings) {
  ClipPolygon square = unit_square();
  remove_points_outside(square, Plane{Vec3(1, 0, 0), 0.5});
  ASSERT_EQ(square.size(), 2);
  EXPECT_EQ(square[0].x(), 0);
  EXPECT_EQ(square[1].x(), 0);
}

TEST(ClosestPointOnPolygon, InsideProjectsOntoThePlaneOutsideClampsToTheBoundary) {
  const Vec3 loop[] = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};
  EXPECT_VEC_NEAR(closest_point_on_polygon(Vec3(0.3, 0.4, 2), loop, 4, Vec3::UnitZ()), Vec3(0.3, 0.4, 0), 0);
  EXPECT_VEC_NEAR(closest_point_on_polygon(Vec3(2, 0.5, -1), loop, 4, Vec3::UnitZ()), Vec3(1, 0.5, 0), 0);
  EXPECT_VEC_NEAR(closest_point_on_polygon(Vec3(-1, -1, 0), loop, 4, Vec3::UnitZ()), Vec3(0, 0, 0), 0);
}

TEST(PolygonReduction, DropsTheFlattestCornersFirst) {
  ClipPolygon polygon = unit_square();
  polygon.push(Vec3(0, 0.5, 0));  // on the square's left edge: no area at all
  reduce_polygon(polygon, 4);
  ASSERT_EQ(polygon.size(), 4);
  for (int k = 0; k < 4; ++k) EXPECT_NE(polygon[k], Vec3(0, 0.5, 0));
}

// A cloud in no loop order (the incident faces' and F27's points) keeps its
// outline's corners, counter-clockwise about the normal; the points inside
// it and on its edges go (F55).
TEST(PolygonOutline, KeepsTheCornersOfACloudCounterClockwiseAboutTheNormal) {
  ClipPolygon cloud;
  for (const Vec3& p : {Vec3(0.5, 0.5, 0.3), Vec3(1, 1, 0), Vec3(0, 0.5, 0), Vec3(0, 0, 0.1), Vec3(0.2, 0.7, -0.2),
                        Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0), Vec3(0.5, 0, 0.2)})
    cloud.push(p);
  ClipPolygon scratch;
  ClipPolygon up = cloud;
  keep_outline(up, Vec3(0, 0, 1), scratch);
  ASSERT_EQ(up.size(), 4);
  for (int k = 0; k < 4; ++k) {
    const Vec3 edge = up[(k + 1) % 4] - up[k], next = up[(k + 2) % 4] - up[(k + 1) % 4];
    EXPECT_GT(edge.cross(next).z(), 0) << "corner " << k;
    EXPECT_TRUE(std::abs(up[k].x() - 0.5) == 0.5 && std::abs(up[k].y() - 0.5) == 0.5) << up[k].transpose();
  }
  ClipPolygon down = cloud;
  keep_outline(down, Vec3(0, 0, -1), scratch);
  ASSERT_EQ(down.size(), 4);
  EXPECT_LT((down[1] - down[0]).cross(down[2] - down[1]).z(), 0);
}

TEST(PolygonOutline, LeavesTwoPointsAsTheyAre) {
  ClipPolygon two, scratch;
  two.push(Vec3(0, 0, 0)), two.push(Vec3(1, 0, 0));
  keep_outline(two, Vec3(0, 0, 1), scratch);
  EXPECT_EQ(two.size(), 2);
}

TEST(ClipPolygon, RefusesToGrowPastItsCapacity) {
  ClipPolygon polygon;
  for (int k = 0; k < kMaxPolygonVertices; ++k) ASSERT_TRUE(polygon.push(Vec3::Zero()));
  EXPECT_FALSE(polygon.push(Vec3::Zero()));
}

}  // namespace
}  // namespace mfz

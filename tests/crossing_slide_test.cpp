// Where a relation lets a contact slide: along an incident edge that grazes
// a side plane of the reference face, by the rounding over the sine of the
// angle between them, no further than the edge (props/crossing_slide.h).
#include "crossing_slide.h"

#include <gtest/gtest.h>

#include "test_support.h"

namespace mfz {
namespace {

// A's box [-1, 1]^3 is the reference hull, its top face the reference face
// (n = +z). B's edge P -> Q runs along the side plane x = 1 through A's top
// edge there, 4e-9 of its length across it, 0.1 below the top face, and
// crosses it at y = 0.
constexpr double kAcross = 2e-9;
const Vec3 kP(1 - kAcross, -0.5, 0.9), kQ(1 + kAcross, 0.5, 0.9);
const Vec3 kOnB(1, 0, 0.9), kOnA(1, 0, 1), kN(0, 0, 1);

Scene grazing_scene() {
  const CaseFile c =
      test::make_case(test::box_points(1, 1, 1), Pose{}, {kP, kQ, Vec3(0, 0, 3), Vec3(0.3, 0.1, 3.5)}, Pose{});
  return *make_scene(c).scene;
}

double sine_of_edge() { return (kQ - kP).normalized().x(); }

// The slide with B incident; the other way round, A's top edge grazes the
// side plane through B's edge as closely, and slides as far.
const props::CrossingSlide* b_incident(const std::vector<props::CrossingSlide>& slides) {
  for (const props::CrossingSlide& slide : slides)
    if (!slide.incident_is_a) return &slide;
  return nullptr;
}

TEST(CrossingSlide, AGrazingCrossingSlidesAlongItsEdgeByTheRoundingOverTheSine) {
  const Scene s = grazing_scene();
  const double rounding = 1e-12;
  const auto slides = props::crossing_slides(s, kN, kOnA, kOnB, 1e-12, rounding, 1e-6);
  ASSERT_EQ(slides.size(), 2u);
  ASSERT_TRUE(b_incident(slides));
  const props::CrossingSlide& slide = *b_incident(slides);
  EXPECT_NEAR(std::abs(slide.along_incident.y()), 1, 1e-12);
  // The point on the reference face follows the edge's shadow on its plane.
  EXPECT_NEAR(slide.along_reference.z(), 0, 1e-15);
  EXPECT_NEAR(slide.along_reference.y(), slide.along_incident.y(), 1e-15);
  const double reach = rounding / sine_of_edge();
  EXPECT_NEAR(slide.most, reach, 1e-9 * reach);
  EXPECT_NEAR(slide.least, -reach, 1e-9 * reach);
}

TEST(CrossingSlide, ASlideStopsAtTheIncidentEdgesEnds) {
  const Scene s = grazing_scene();
  // Rounding 1e-8 over a sine of 4e-9 reaches 2.5 along an edge that ends
  // 0.5 either side of the crossing.
  const auto slides = props::crossing_slides(s, kN, kOnA, kOnB, 1e-12, 1e-8, 1e-6);
  ASSERT_TRUE(b_incident(slides));
  EXPECT_NEAR(b_incident(slides)->most, 0.5, 1e-9);
  EXPECT_NEAR(b_incident(slides)->least, -0.5, 1e-9);
}

TEST(CrossingSlide, NoSlideWhereTheReachIsWithinThePlainTolerance) {
  const Scene s = grazing_scene();
  // Rounding 1e-15 over 4e-9 moves the crossing 2.5e-7: the 1e-6 the points
  // are compared to already covers it.
  EXPECT_TRUE(props::crossing_slides(s, kN, kOnA, kOnB, 1e-12, 1e-15, 1e-6).empty());
}

TEST(CrossingSlide, NoSlideForAPointOnNoEdge) {
  const Scene s = grazing_scene();
  // Inside B's face, not on its edge: no crossing of an edge to slide along.
  const Vec3 inside_b = (kP + kQ + Vec3(0, 0, 3)) / 3;
  EXPECT_TRUE(props::crossing_slides(s, kN, Vec3(inside_b.x(), inside_b.y(), 1), inside_b, 1e-12, 1e-8, 1e-6).empty());
  // On B's edge, its partner in the middle of A's top face: on no side plane.
  EXPECT_TRUE(props::crossing_slides(s, kN, Vec3(0, 0, 1), kOnB, 1e-12, 1e-8, 1e-6).empty());
}

TEST(CrossingSlide, ASteepEdgeSlidesByTheRoundingAlone) {
  // B's edge from (0.5, 0, 0.5) to (1.5, 0, 1.5) crosses the side plane
  // x = 1 at 45 degrees, on A's top edge: rounding over sin 45.
  const CaseFile c = test::make_case(test::box_points(1, 1, 1), Pose{},
                                     {Vec3(0.5, 0, 0.5), Vec3(1.5, 0, 1.5), Vec3(0, 1, 3), Vec3(0, -1, 3)}, Pose{});
  const Scene s = *make_scene(c).scene;
  const auto slides = props::crossing_slides(s, kN, Vec3(1, 0, 1), Vec3(1, 0, 1), 1e-12, 1e-7, 1e-9);
  ASSERT_FALSE(slides.empty());
  for (const props::CrossingSlide& slide : slides) {
    EXPECT_LE(slide.most, 1e-7 * std::sqrt(2.0) * (1 + 1e-9));
    EXPECT_GE(slide.least, -1e-7 * std::sqrt(2.0) * (1 + 1e-9));
  }
}

}  // namespace
}  // namespace mfz

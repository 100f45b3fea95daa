// The case-file shrinker: it drops every point the failure does not need
// and rounds what is left, and never keeps a step that loses the failure.
#include <gtest/gtest.h>

#include "case_shrinker.h"
#include "finding_minimiser.h"
#include "geometry/hull.h"
#include "test_support.h"

namespace mfz::props {
namespace {

int significant_digits(double x) {
  for (int digits = 1; digits <= 17; ++digits) {
    char text[64];
    std::snprintf(text, sizeof text, "%.*g", digits, x);
    if (std::strtod(text, nullptr) == x) return digits;
  }
  return 17;
}

// A failure that needs one thing only: hull A reaches past x = 0.4.
bool reaches_past(const CaseFile& c) {
  if (!build_hull(c.points_a).hull || !build_hull(c.points_b).hull) return false;
  for (const Vec3& p : c.points_a)
    if (p.x() > 0.4) return true;
  return false;
}

TEST(CaseShrinker, DropsDuplicatesAndInteriorPointsAndRoundsTheRest) {
  CaseFile c = test::make_case(test::box_points(0.5123456789, 0.5123456789, 0.5123456789), {},
                               test::box_points(1, 1, 1), {Vec3(3, 0, 0), Quat::Identity()});
  c.points_a.push_back(c.points_a[3]);                        // a duplicate
  c.points_a.push_back(Vec3(0.01234567, -0.0234567, 0.1));    // an interior point
  ASSERT_TRUE(reaches_past(c));
  const int steps = shrink_case_file(c, reaches_past, 10);
  EXPECT_GT(steps, 0);
  EXPECT_EQ(c.points_a.size(), 4u) << "a tetrahedron is the least hull";
  EXPECT_EQ(c.points_b.size(), 4u);
  ASSERT_TRUE(reaches_past(c)) << "the shrunk case must still fail";
  for (const Vec3& p : c.points_a)
    for (int k = 0; k < 3; ++k) EXPECT_LE(significant_digits(p(k)), 2) << p.transpose();
}

TEST(CaseShrinker, RoundsPosesAsFarAsTheFailureAllows) {
  CaseFile c = test::make_case(test::tetrahedron_points(), {Vec3(0.123456789, 2.5, -7.25), Quat::Identity()},
                               test::tetrahedron_points(), {Vec3(3.3333333, 0, 0), test::about(Vec3(0, 0, 1), 0.1)});
  // Fails while B stays more than 3 to the right of A (and B's quaternion is
  // not zero, which make_scene refuses).
  const auto apart = [](const CaseFile& k) {
    return k.pose_b.orientation.norm() > 0 && k.pose_b.position.x() - k.pose_a.position.x() > 3;
  };
  shrink_case_file(c, apart, 10);
  EXPECT_EQ(c.pose_a.position, Vec3::Zero());
  EXPECT_EQ(c.pose_b.position.x(), 3.2) << "A moved to the origin first; B's offset 3.2098765 rounds to 3.2, 3 fails";
  EXPECT_EQ(c.pose_b.orientation.coeffs(), Quat::Identity().coeffs()) << "x, y, z to 0, w to one digit";
}

TEST(CaseShrinker, MovesTheCaseSoThatASitsAtTheOriginWithTheIdentityRotation) {
  const Quat turn = test::about(Vec3(1, 2, 3).normalized(), 0.7);
  CaseFile c = test::make_case(test::tetrahedron_points(), {Vec3(5, -2, 1), turn}, test::tetrahedron_points(),
                               {Vec3(8, -2, 1), turn});
  // Fails while B is more than 2.5 from A, whatever the frame: a rigid motion
  // keeps it (a zero quaternion, which make_scene refuses, does not fail).
  const auto apart = [](const CaseFile& k) {
    return k.pose_a.orientation.norm() > 0 && k.pose_b.orientation.norm() > 0 &&
           (k.pose_b.position - k.pose_a.position).norm() > 2.5;
  };
  shrink_case_file(c, apart, 10);
  EXPECT_EQ(c.pose_a.position, Vec3::Zero());
  EXPECT_EQ(c.pose_a.orientation.coeffs(), Quat::Identity().coeffs());
  EXPECT_NEAR(c.pose_b.position.norm(), 3, 0.5);
}

TEST(CaseShrinker, KeepsACaseThatCannotShrink) {
  CaseFile c = test::make_case(test::tetrahedron_points(), {}, test::tetrahedron_points(), {});
  const CaseFile before = c;
  EXPECT_EQ(shrink_case_file(c, [](const CaseFile&) { return false; }, 10), 0);
  EXPECT_EQ(c.points_a, before.points_a);
  EXPECT_EQ(c.points_b, before.points_b);
}

}  // namespace
// A finding of 1.77 L once shrank to one of 7.4e-9 L: the same name, another
// failure. Shrinking keeps a step only at the same order of error.
TEST(ShrinkingKeepsTheFailure, OnlyAStepFailingTheSameCheckBySameOrderOfMarginCounts) {
  const props::Finding original{"on-surface", "", "", 1.77, 1e-9};
  EXPECT_TRUE(props::same_failure(original, {"on-surface", "", "", 0.9, 1e-9}));
  EXPECT_TRUE(props::same_failure(original, {"on-surface", "", "", 0.2, 1e-9}));
  EXPECT_FALSE(props::same_failure(original, {"on-surface", "", "", 0.15, 1e-9}));
  EXPECT_FALSE(props::same_failure(original, {"on-surface", "", "", 7.4e-9, 1e-9}));
  EXPECT_FALSE(props::same_failure(original, {"within-both-hulls", "", "", 1.77, 1e-9}));
  const props::Finding relation{"rigid-motion", "the normals differ", "relation rigid-motion 1 0 0 0 0 0 0"};
  EXPECT_TRUE(props::same_failure(relation, {"rigid-motion", "contact 0 lies 0.1 from the other run's", ""}));
}

}  // namespace mfz::props

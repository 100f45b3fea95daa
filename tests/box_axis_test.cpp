// The box path (generator/box_axis.h): two boxes whose face axis and
// incident face, or whose edge axis, clear every tie are answered without
// the bounded SAT, the significant-face rules and F27's faces. It must
// answer as the general path does, to the bit, and leave every tie and near
// miss to it.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cstring>
#include <iomanip>
#include <optional>
#include <random>
#include <vector>

#include "case/case_file.h"
#include "families.h"
#include "generator/box_axis.h"
#include "generator/clipping_generator.h"
#include "geometry/hull.h"
#include "test_support.h"

namespace mfz {
namespace {

ClippingSteps steps_with_box_path(bool on) {
  ClippingSteps steps;
  steps.box_path = on;
  return steps;
}

// Both answers, field by field, to the bit; the contacts in their order.
::testing::AssertionResult same_bits(const mfz_manifold& x, const mfz_manifold& y) {
  const auto same = [](double p, double q) { return std::memcmp(&p, &q, sizeof p) == 0; };
  const auto same_vec = [&](const mfz_vec3& p, const mfz_vec3& q) { return same(p.x, q.x) && same(p.y, q.y) && same(p.z, q.z); };
  if (x.colliding != y.colliding || x.contact_count != y.contact_count)
    return ::testing::AssertionFailure() << "colliding " << x.colliding << "/" << y.colliding << ", contacts "
                                         << x.contact_count << "/" << y.contact_count;
  // Apart, the separating axis is free (the contract's), and SAT's memory
  // of the pair's last axis may report another (sat.h).
  if (!x.colliding && x.contact_count == 0) return ::testing::AssertionSuccess();
  if (!same_vec(x.normal, y.normal) || !same(x.penetration, y.penetration))
    return ::testing::AssertionFailure() << std::setprecision(17) << "normal (" << x.normal.x << ", " << x.normal.y
                                         << ", " << x.normal.z << ") / (" << y.normal.x << ", " << y.normal.y << ", "
                                         << y.normal.z << "), penetration " << x.penetration << " / "
                                         << y.penetration;
  for (int i = 0; i < x.contact_count; ++i)
    if (!same_vec(x.contacts[i].point_on_a, y.contacts[i].point_on_a) ||
        !same_vec(x.contacts[i].point_on_b, y.contacts[i].point_on_b) ||
        !same(x.contacts[i].penetration, y.contacts[i].penetration))
      return ::testing::AssertionFailure() << "contact " << i << " differs";
  return ::testing::AssertionSuccess();
}

struct PathAnswers {
  bool box_path = false;  // the box path answered
  AxisKind kind = AxisKind::face_a;  // with this kind of axis
  mfz_manifold general{}, boxed{};
};

PathAnswers both_paths(const mfz_hull& a, const Pose& pose_a, const mfz_hull& b, const Pose& pose_b) {
  static const ClippingSteps general = steps_with_box_path(false), boxed = steps_with_box_path(true);
  PathAnswers answers;
  generate_clipping_manifold(a, pose_a.to_abi(), b, pose_b.to_abi(), answers.general, nullptr, general);
  generate_clipping_manifold(a, pose_a.to_abi(), b, pose_b.to_abi(), answers.boxed, nullptr, boxed);
  // The frame the generator works in (F21): A's position at the origin.
  const Pose local_a{Vec3::Zero(), pose_a.orientation}, local_b{pose_b.position - pose_a.position, pose_b.orientation};
  BoxAxis axis;
  answers.box_path = clear_box_axis(PosedHull(a, local_a), PosedHull(b, local_b), axis);
  answers.kind = axis.sat.kind;
  return answers;
}

Quat turned(std::mt19937& random, double tilt) {
  std::uniform_real_distribution<double> angle(0, 2 * M_PI);
  return test::about(Vec3::UnitZ(), angle(random)) * test::about(Vec3::UnitX(), tilt) *
         test::about(Vec3::UnitZ(), angle(random));
}

// Boxes resting on boxes, tilted from nothing to 11 degrees, sunk from a
// hair to a fifth of B (one in five past its own thickness), anywhere over
// A's top (overhanging its rim), at the origin and far from it: the pairs
// the box path is for, and its edges.
TEST(BoxPath, AnswersAsTheGeneralPathToTheBitOnBoxesRestingOnBoxes) {
  std::mt19937 random(20261129);
  std::uniform_real_distribution<double> unit(0, 1);
  const auto between = [&](double low, double high) { return low + (high - low) * unit(random); };
  int pairs = 0, boxed = 0, edges = 0, with_contacts = 0;
  for (int k = 0; k < 6000; ++k) {
    const Vec3 ha(between(0.5, 2), between(0.5, 2), between(0.2, 1)), hb(between(0.2, 0.8), between(0.2, 0.8),
                                                                          between(0.2, 0.8));
    const Hull hull_a = *build_hull(test::box_points(ha.x(), ha.y(), ha.z())).hull;
    const Hull hull_b = *build_hull(test::box_points(hb.x(), hb.y(), hb.z())).hull;
    const double tilts[] = {0, 1e-9, 1e-4, 0.01, 0.1};
    const double tilt = k % 6 < 5 ? tilts[k % 6] * unit(random) : between(0, 0.2);
    const Quat orientation = turned(random, tilt);
    const Mat3 r = orientation.toRotationMatrix();
    const double reach = std::abs(r(2, 0)) * hb.x() + std::abs(r(2, 1)) * hb.y() + std::abs(r(2, 2)) * hb.z();
    // One pair in five sunk up to one and a half times its own thickness.
    const double sunk = between(1e-6, k % 5 == 4 ? 3.0 : 0.2) * hb.minCoeff();
    const Vec3 far = k % 7 == 0 ? Vec3(1e4, -3e3, 2e3) : Vec3::Zero();
    const Pose pose_a{far, Quat::Identity()};
    const Pose pose_b{far + Vec3(between(-1.2, 1.2) * ha.x(), between(-1.2, 1.2) * ha.y(), ha.z() + reach - sunk),
                      orientation};
    const PathAnswers answers = both_paths(hull_a.view(), pose_a, hull_b.view(), pose_b);
    ++pairs;
    boxed += answers.box_path;
    edges += answers.box_path && answers.kind == AxisKind::edge_edge;
    with_contacts += answers.boxed.contact_count > 0;
    ASSERT_TRUE(same_bits(answers.boxed, answers.general))
        << "pair " << k << ", tilt " << tilt << "\n"
        << format_case(test::make_case(test::box_points(ha.x(), ha.y(), ha.z()), pose_a,
                                       test::box_points(hb.x(), hb.y(), hb.z()), pose_b));
  }
  EXPECT_GT(boxed, pairs / 4) << "the box path should answer many of these pairs";
  EXPECT_GT(edges, pairs / 100) << "and some of them by an edge axis";
  EXPECT_LT(boxed, pairs) << "some pairs (edge axes, ties) are the general path's";
  EXPECT_GT(with_contacts, pairs / 2);
}

// Every box family of the property suite (cubes, boxes, slabs, needles,
// anisotropic boxes), every placement, overlap, tilt, frame and scale.
RC_GTEST_PROP(BoxPath, AnswersAsTheGeneralPathToTheBitOnEveryBoxFamily, ()) {
  std::string error;
  static const std::vector<std::string> boxes = *props::hull_families_named("boxes", error);
  const props::GeneratedCase c = *props::any_case(std::numeric_limits<double>::infinity(), boxes);
  const test::PosedCase posed(c.file);
  RC_PRE(posed.built);
  const PathAnswers answers = both_paths(posed.view_a, posed.pose_a, posed.view_b, posed.pose_b);
  RC_TAG(!answers.box_path ? "general path" : answers.kind == AxisKind::edge_edge ? "box path, edge" : "box path, face");
  RC_ASSERT(same_bits(answers.boxed, answers.general));
}

struct TwoBoxes {
  Hull a, b;
  TwoBoxes(const std::vector<Vec3>& points_a, const std::vector<Vec3>& points_b)
      : a(*build_hull(points_a).hull), b(*build_hull(points_b).hull) {}
  bool boxed(const Pose& pose_b) const { return axis(pose_b).has_value(); }
  // The kind of axis the box path answers with, if it answers.
  std::optional<AxisKind> axis(const Pose& pose_b) const {
    BoxAxis axis;
    const mfz_hull view_a = a.view(), view_b = b.view();
    const Pose pose_a{Vec3::Zero(), Quat::Identity()};
    if (!clear_box_axis(PosedHull(view_a, pose_a), PosedHull(view_b, pose_b), axis)) return std::nullopt;
    return axis.sat.kind;
  }
};

TEST(BoxPath, TakesABoxRestingTiltedOnABox) {
  const TwoBoxes boxes(test::box_points(2, 2, 1), test::box_points(0.5, 0.5, 0.5));
  EXPECT_TRUE(boxes.boxed({Vec3(0.1, 0.2, 1.49), test::about(Vec3(1, 2, 0).normalized(), 0.003)}));
}

// F14: A's top and B's bottom parallel, their overlaps equal: the larger
// face is the reference, which the bounded SAT decides.
TEST(BoxPath, LeavesParallelFacesToTheGeneralPath) {
  const TwoBoxes boxes(test::box_points(2, 2, 1), test::box_points(0.5, 0.5, 0.5));
  EXPECT_FALSE(boxes.boxed({Vec3(0.1, 0.2, 1.49), test::about(Vec3::UnitZ(), 0.3)}));
}

// Two cubes crossing at their edges, clear of every face: the box path
// answers with the edge pair's axis, as the general path does.
TEST(BoxPath, TakesTwoBoxesCrossingAtTheirEdges) {
  const TwoBoxes boxes(test::box_points(1, 1, 1), test::box_points(1, 1, 1));
  const Quat crossed = test::about(Vec3::UnitX(), M_PI / 4) * test::about(Vec3::UnitY(), M_PI / 4);
  const Pose pose_b{Vec3(1.9, 0, 1.9), crossed};
  EXPECT_EQ(boxes.axis(pose_b), AxisKind::edge_edge);
  const PathAnswers answers = both_paths(boxes.a.view(), {}, boxes.b.view(), pose_b);
  EXPECT_TRUE(same_bits(answers.boxed, answers.general));
  EXPECT_EQ(answers.boxed.contact_count, 1);
}

// Three pairs the property above found, each answered wrongly once a guard
// of the edge axis was taken out: two slabs corner to corner whose edge
// axis is shallower than a face by about F3's bias (the slack's size lies
// between the span and twice it); two needles whose edge axes nearly tie;
// a slab touching a box to one ulp along an edge axis, 1.2e4 out.
TEST(BoxPath, LeavesEdgeAxesNearATieOrTouchingToTheGeneralPath) {
  using test::box_points;
  const CaseFile cases[] = {
      test::make_case(box_points(0.5, 0.25, 5e-4),
                      {Vec3::Zero(), Quat(-0.9510565162951535, -0.2795163884141089, 0.09317212947136964,
                                          -0.09317212947136964)},
                      box_points(0.5, 0.3, 5e-4),
                      {Vec3(0.869067665091304, 0.5504815547707751, 0.4960974509333098),
                       Quat(0.2811230512809393, 0.029421030531509185, 0.9584692743592336, -0.037958966137696226)}),
      test::make_case(box_points(5e-4, 5e-4, 0.5),
                      {Vec3::Zero(), Quat(0.9914448613738104, 0.07535933221454362, 0.07535933221454362,
                                          -0.07535933221454362)},
                      box_points(5e-4, 5e-4, 0.5),
                      {Vec3(-0.06778189255376812, 0.0800051254010513, -0.48376676715271333),
                       Quat(0.027555819016946245, -0.820964158457984, 0.561013277854387, 0.1025798685744765)}),
      test::make_case(box_points(5800, 5200, 100),
                      {Vec3::Zero(), Quat(0.6018150231520484, 0.3571606579421926, -0.7143213158843852, 0)},
                      box_points(5000, 3500, 5),
                      {Vec3(627.7016167021605, 2158.299074397845, -11982.668301354697),
                       Quat(-0.6626200482157376, -0.600500508226451, 0.4003336721509673, 0.20016683607548366)})};
  for (const CaseFile& c : cases) {
    const test::PosedCase posed(c);
    ASSERT_TRUE(posed.built);
    const PathAnswers answers = both_paths(posed.view_a, posed.pose_a, posed.view_b, posed.pose_b);
    EXPECT_FALSE(answers.box_path) << format_case(c);
    EXPECT_TRUE(same_bits(answers.boxed, answers.general)) << format_case(c);
  }
}

// Two faces of the incident box equally turned to the reference face: F11
// clips both. Turned about z too, so that no edge of B is parallel to one
// of A's and the pair is left for its faces' tie, not for parallel edges.
TEST(BoxPath, LeavesTiedIncidentFacesToTheGeneralPath) {
  const TwoBoxes boxes(test::box_points(2, 2, 1), test::box_points(0.5, 0.5, 0.5));
  const double reach = 0.5 * std::sqrt(2.0);
  const Quat on_its_edge = test::about(Vec3::UnitZ(), 0.3) * test::about(Vec3::UnitX(), M_PI / 4);
  EXPECT_FALSE(boxes.boxed({Vec3(0, 0, 1 + reach - 0.01), on_its_edge}));
}

TEST(BoxPath, LeavesApartTouchingAndShearedPairsToTheGeneralPath) {
  const TwoBoxes boxes(test::box_points(2, 2, 1), test::box_points(0.5, 0.5, 0.5));
  const Quat tilt = test::about(Vec3(1, 2, 0).normalized(), 0.003);
  const double reach = 0.5 * (std::abs(tilt.toRotationMatrix()(2, 0)) + std::abs(tilt.toRotationMatrix()(2, 1)) +
                              std::abs(tilt.toRotationMatrix()(2, 2)));
  EXPECT_FALSE(boxes.boxed({Vec3(0.1, 0.2, 1.6), tilt})) << "apart";
  EXPECT_FALSE(boxes.boxed({Vec3(0.1, 0.2, 1 + reach), tilt})) << "touching";
  std::vector<Vec3> sheared = test::box_points(0.5, 0.5, 0.5);
  for (Vec3& p : sheared) p.x() += 0.3 * p.z();
  const TwoBoxes leaning(test::box_points(2, 2, 1), sheared);
  EXPECT_FALSE(leaning.boxed({Vec3(0.1, 0.2, 1.49), tilt})) << "a parallelepiped, not a box";
}

}  // namespace
}  // namespace mfz

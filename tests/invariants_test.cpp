// Every invariant is shown to fire on a purpose-built wrong manifold, and to
// stay quiet on the right one. Each wrong manifold starts from the correct
// answer for a box resting on a slab and breaks one thing.
#include "harness/invariants.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "case/case_file.h"
#include "geometry/tolerances.h"
#include "oracles/contact_region.h"
#include "test_support.h"

namespace mfz {
namespace {

using test::box_points;

// The status of the check named `name` in `v`; a test failure where there is none.
CheckStatus status_in(const Verdict& v, const std::string& name) {
  for (const InvariantCheck& c : v.checks)
    if (c.name == name) return c.status;
  ADD_FAILURE() << "no check named " << name;
  return CheckStatus::skipped;
}

class InvariantFires : public ::testing::Test {
 protected:
  // B, a unit cube, rests 0.1 deep on the 4 x 4 x 1 slab A: n = +z, four contacts.
  InvariantFires()
      : run_(test::run_builtin(test::make_case(box_points(2, 2, 0.5), {}, box_points(0.5, 0.5, 0.5),
                                               {Vec3(0, 0, 0.9), Quat::Identity()}))) {}

  mfz_manifold good() const { return run_.manifold; }

  CheckStatus status_of(const std::string& name, const mfz_manifold& m) const {
    return status_in(check_manifold(run_.scene, run_.oracles, 0, m), name);
  }

  void expect_fires(const std::string& name, const mfz_manifold& wrong) const {
    EXPECT_EQ(status_of(name, good()), CheckStatus::pass) << name << " must pass on the right manifold";
    EXPECT_EQ(status_of(name, wrong), CheckStatus::fail) << name << " must fire on the wrong one";
  }

  static void shift_contact(mfz_manifold& m, int i, const Vec3& by) {
    m.contacts[i].point_on_a = to_abi(to_vec(m.contacts[i].point_on_a) + by);
    m.contacts[i].point_on_b = to_abi(to_vec(m.contacts[i].point_on_b) + by);
  }

  CaseRun run_;
};

TEST_F(InvariantFires, FiniteOnANanContact) {
  mfz_manifold m = good();
  m.contacts[1].point_on_b.y = std::numeric_limits<double>::quiet_NaN();
  expect_fires("finite", m);
}

TEST_F(InvariantFires, FiniteOnAFieldLeftPoisoned) {
  mfz_manifold m = good();
  m.contact_count = -1;
  expect_fires("finite", m);
  m = good();
  m.colliding = 7;
  expect_fires("finite", m);
}

TEST_F(InvariantFires, UnitNormalOnALongNormal) {
  mfz_manifold m = good();
  m.normal.z = 1.001;
  expect_fires("unit-normal", m);
}

TEST_F(InvariantFires, NegativePenetrationOnAPositivePenetration) {
  mfz_manifold m = good();
  m.penetration = 0.1;
  expect_fires("negative-penetration", m);
}

TEST_F(InvariantFires, NegativePenetrationOnAContactDeeperThanTheManifold) {
  mfz_manifold m = good();
  m.contacts[0].penetration = -0.2;
  m.contacts[0].point_on_b.z = m.contacts[0].point_on_a.z - 0.2;
  expect_fires("negative-penetration", m);
}

TEST_F(InvariantFires, NegativePenetrationOnAContactWithZeroPenetration) {
  mfz_manifold m = good();
  m.contacts[2].penetration = 0;
  expect_fires("negative-penetration", m);
}

TEST_F(InvariantFires, PairConsistencyOnSwappedPoints) {
  mfz_manifold m = good();
  std::swap(m.contacts[0].point_on_a, m.contacts[0].point_on_b);  // the tutorial's swapped branch
  expect_fires("pair-consistency", m);
}

TEST_F(InvariantFires, OnSurfaceOnAContactSunkIntoBothHulls) {
  mfz_manifold m = good();
  shift_contact(m, 0, Vec3(0, 0, 0.05));  // on A now lies 0.05 above A's top: off A's surface
  expect_fires("on-surface", m);
}

// The box and slab have right-angled corners only: a point 3e-9 L off is off.
TEST_F(InvariantFires, OnSurfaceOnAContactJustPastThePointTolerance) {
  mfz_manifold m = good();
  shift_contact(m, 0, Vec3(0, 0, 3e-9 * run_.scene.scale));
  expect_fires("on-surface", m);
}

TEST_F(InvariantFires, WithinBothHullsOnAContactOutsideItsOwnHull) {
  mfz_manifold m = good();
  shift_contact(m, 3, Vec3(-0.3, 0, 0));  // beyond B's side by 0.3
  expect_fires("within-both-hulls", m);
}

TEST_F(InvariantFires, HasContactsOnAnEmptyManifold) {
  mfz_manifold m = good();
  m.contact_count = 0;
  expect_fires("has-contacts", m);
}

TEST_F(InvariantFires, AgreesWithGjkOnAMissedCollision) {
  mfz_manifold m = good();
  m.colliding = 0;
  m.contact_count = 0;
  expect_fires("agrees-with-gjk", m);
}

TEST_F(InvariantFires, DepthExactOnAShallowDepth) {
  mfz_manifold m = good();
  m.penetration = -0.09;
  expect_fires("depth-exact", m);
}

TEST_F(InvariantFires, DepthWithinEpaBoundsOnADepthBelowEpas) {
  mfz_manifold m = good();
  m.penetration = -0.05;
  expect_fires("depth-within-epa-bounds", m);
}

TEST_F(InvariantFires, DepthWithinEpaBoundsOnADepthAboveTheOverlapAlongEpasDirection) {
  mfz_manifold m = good();
  m.penetration = -0.2;
  expect_fires("depth-within-epa-bounds", m);
}

TEST_F(InvariantFires, NormalAgreesWithEpaOnATiltedNormal) {
  mfz_manifold m = good();
  m.normal = to_abi(Vec3(0.1, 0, 1).normalized());
  expect_fires("normal-agrees-with-epa", m);
}

TEST_F(InvariantFires, NormalRealisesDepthOnASidewaysNormal) {
  mfz_manifold m = good();
  m.normal = {1, 0, 0};
  expect_fires("normal-realises-depth", m);
}

TEST_F(InvariantFires, SeparatesOnAnUpsideDownNormal) {
  mfz_manifold m = good();
  m.normal = {0, 0, -1};
  expect_fires("separates", m);
}

TEST_F(InvariantFires, SeparatesOnADepthTooShortToSeparate) {
  mfz_manifold m = good();
  m.penetration = -0.0999;
  expect_fires("separates", m);
}

TEST_F(InvariantFires, SeparatesOnADepthLongerThanNeeded) {
  mfz_manifold m = good();
  m.penetration = -0.1001;
  expect_fires("separates", m);
}

TEST(InvariantVerdict, ARefusalIsNotAPass) {
  const CaseRun run = test::run_builtin(test::make_case(box_points(1, 1, 1), {}, box_points(1, 1, 1),
                                                        {Vec3(0, 0, 1.5), Quat::Identity()}));
  const Verdict v = check_manifold(run.scene, run.oracles, 3, run.manifold);
  EXPECT_TRUE(v.refused());
}

// The property suite reads a failure's detail only; explain and replay print
// every check's.
TEST_F(InvariantFires, APassingCheckIsDescribedOnlyWhenItsDetailIsWritten) {
  mfz_manifold wrong = good();
  wrong.penetration = -0.2;  // deeper than the exact 0.1: depth-exact fails
  const auto detail_of = [&](const mfz_manifold& m, PassDetails details, const std::string& name) {
    for (const InvariantCheck& c : check_manifold(run_.scene, run_.oracles, 0, m, {}, details).checks)
      if (c.name == name) return c.detail;
    return std::string("no such check");
  };
  EXPECT_EQ(detail_of(good(), PassDetails::written, "depth-exact"), "depth 0.1, exact 0.1");
  EXPECT_EQ(detail_of(good(), PassDetails::left_out, "depth-exact"), "");
  EXPECT_EQ(detail_of(good(), PassDetails::left_out, "on-surface"), "");
  EXPECT_EQ(detail_of(wrong, PassDetails::left_out, "depth-exact"), "depth 0.2, exact 0.1");
}

// A relation's run is reported by its first failing check, in the
// contract's order, with that check's detail: a contact shifted 0.05 up
// under a normal turned sideways fails pair-consistency before on-surface,
// a deeper depth fails depth-exact, and a right manifold fails nothing.
TEST_F(InvariantFires, ATransformedRunIsReportedByItsFirstFailingCheck) {
  EXPECT_FALSE(check_transformed_manifold(run_.scene, run_.oracles, 1, good()));
  mfz_manifold off = good();
  shift_contact(off, 0, Vec3(0, 0, 0.05));
  EXPECT_EQ(status_of("on-surface", off), CheckStatus::fail);
  off.normal = to_abi(Vec3(1, 0, 0));
  EXPECT_EQ(status_of("pair-consistency", off), CheckStatus::fail);
  const std::optional<InvariantCheck> first = check_transformed_manifold(run_.scene, run_.oracles, 1, off);
  ASSERT_TRUE(first);
  EXPECT_EQ(first->name, "pair-consistency");
  EXPECT_EQ(first->status, CheckStatus::fail);
  EXPECT_NE(first->detail, "");
  mfz_manifold deeper = good();
  deeper.penetration = -0.2;
  const std::optional<InvariantCheck> depth = check_transformed_manifold(run_.scene, run_.oracles, 1, deeper);
  ASSERT_TRUE(depth);
  EXPECT_EQ(depth->name, "depth-exact");
  EXPECT_EQ(depth->detail, "depth 0.2, exact 0.1");
}

// Where the least axis is an edge pair of nearly parallel edges, depth-exact
// gives the depth the room the frame's rounding leaves along that axis: two
// needles 2,300 long 1e-8 rad apart (h31). A depth half that room away
// passes, one twice the room away fails; on the box resting on a slab,
// whose least axis is a face's, there is no room.
TEST(DepthExact, TakesTheRoomOfTheLeastEdgePairAndNoMore) {
  const CaseParse parsed = read_case_file(test::corpus_path(
      "regressions/h31-two-needles-1e-8-rad-apart-an-edge-pair-s-depth-known-to-its-rounding-over-the-sine.case"));
  ASSERT_TRUE(parsed.value) << parsed.error;
  const CaseRun run = test::run_builtin(*parsed.value);
  const LeastEdgePair& pair = run.oracles.least_edge_pair;
  ASSERT_TRUE(pair.present);
  EXPECT_LT(pair.sine, 1e-7);
  EXPECT_GT(pair.shorter_edge, 1000);
  const double room = pair.depth_room(run.scene.rounding());
  EXPECT_GT(room, 100 * run.scene.length_tolerance(tol::kDepth));
  const auto with_depth = [&](double depth) {
    mfz_manifold m = run.manifold;
    m.penetration = -depth;
    for (int i = 0; i < m.contact_count; ++i) m.contacts[i].penetration = std::max(m.contacts[i].penetration, -depth);
    return status_in(check_manifold(run.scene, run.oracles, 0, m), "depth-exact");
  };
  const double exact = run.oracles.exact.signed_depth;
  EXPECT_EQ(with_depth(exact + 0.5 * room), CheckStatus::pass);
  EXPECT_EQ(with_depth(exact + 2 * room), CheckStatus::fail);
  const CaseRun box = test::run_builtin(test::make_case(box_points(2, 2, 0.5), {}, box_points(0.5, 0.5, 0.5),
                                                        {Vec3(0, 0, 0.9), Quat::Identity()}));
  EXPECT_FALSE(box.oracles.least_edge_pair.present);
  EXPECT_EQ(box.oracles.least_edge_pair.depth_room(box.scene.rounding()), 0);
}

TEST(InvariantVerdict, EveryContractInvariantIsChecked) {
  const CaseRun run = test::run_builtin(test::make_case(box_points(1, 1, 1), {}, box_points(1, 1, 1),
                                                        {Vec3(0, 0, 1.5), Quat::Identity()}));
  ASSERT_EQ(run.verdict.checks.size(), invariant_names().size());
  for (size_t k = 0; k < invariant_names().size(); ++k) EXPECT_EQ(run.verdict.checks[k].name, invariant_names()[k]);
}

// A needle 1e-6 wide and 22 long has face corners of sine 6.4e-8, whose tips
// doubles resolve only to the world's rounding over that sine; a cube's point
// tolerance is the contract's kPoint L and rounding.
TEST(InvariantTolerance, APointIsPlacedAsWellAsTheSharpestFaceCornerIsResolved) {
  const std::vector<Vec3> needle = {Vec3(0, 0, 0), Vec3(1e-6, 22, 0), Vec3(-1e-6, 22, 0), Vec3(0, 22, 1e-6)};
  const CaseRun needles = test::run_builtin(test::make_case(needle, {Vec3(0, 0.5, 0), Quat::Identity()},
                                                            box_points(1, 1, 1), {Vec3(0, -0.9, 0), Quat::Identity()}));
  const Scene& s = needles.scene;
  EXPECT_NEAR(s.sharpest_corner, std::sqrt(2.0) * 1e-6 / 22, 1e-9);
  EXPECT_DOUBLE_EQ(s.point_tolerance(),
                   s.length_tolerance(tol::kPoint) + tol::world_rounding(s.world_extent) / s.sharpest_corner);
  EXPECT_GT(s.point_tolerance(), 10 * s.length_tolerance(tol::kPoint));

  const CaseRun cubes = test::run_builtin(test::make_case(box_points(1, 1, 1), {}, box_points(1, 1, 1),
                                                          {Vec3(0, 0, 1.9), Quat::Identity()}));
  EXPECT_DOUBLE_EQ(cubes.scene.sharpest_corner, 1);
  EXPECT_DOUBLE_EQ(cubes.scene.point_tolerance(),
                   cubes.scene.length_tolerance(tol::kPoint) + tol::world_rounding(cubes.scene.world_extent));
}

// Far from the origin the corner term grows with the coordinates, but never
// past kSharpCornerCap L.
TEST(InvariantTolerance, TheSharpCornerTermIsCapped) {
  const std::vector<Vec3> needle = {Vec3(0, 0, 0), Vec3(1e-8, 1, 0), Vec3(-1e-8, 1, 0), Vec3(0, 1, 1e-8)};
  const CaseRun far = test::run_builtin(test::make_case(needle, {Vec3(3e5, 0.5, 0), Quat::Identity()},
                                                        box_points(0.5, 0.5, 0.5), {Vec3(3e5, -0.45, 0), Quat::Identity()}));
  const Scene& s = far.scene;
  EXPECT_DOUBLE_EQ(s.point_tolerance(), s.length_tolerance(tol::kPoint) + tol::kSharpCornerCap * s.scale);
}

// An octagonal prism tilted 0.03 rad rests 0.05 deep on a slab, deepest
// along the edge between its corners at -22.5 and 22.5 degrees: the
// first-touching region is a strip along that edge, the whole intersection
// about the octagon's middle. The eight contacts are the octagon's corners.
class ReducedManifold : public ::testing::Test {
 protected:
  ReducedManifold() : run_(test::run_builtin(tilted_octagon_on_slab())) {}

  static CaseFile tilted_octagon_on_slab() {
    std::vector<Vec3> prism;
    const double pi = std::acos(-1.0), r = 0.5, h = 0.25, tilt = 0.03;
    for (int k = 0; k < 8; ++k)
      for (double z : {-h, h})
        prism.emplace_back(r * std::cos(pi * (k - 0.5) / 4), r * std::sin(pi * (k - 0.5) / 4), z);
    const double centre = 0.45 + r * std::cos(pi / 8) * std::sin(tilt) + h * std::cos(tilt);
    return test::make_case(box_points(2, 2, 0.5), {}, prism,
                           {Vec3(0, 0, centre), Quat(Eigen::AngleAxisd(tilt, Vec3::UnitY()))});
  }

  // The manifold keeping only the contacts under the octagon's corners `kept`.
  mfz_manifold keeping(std::initializer_list<int> kept) const {
    mfz_manifold m = run_.manifold;
    int count = 0;
    for (int corner : kept)
      for (int i = 0; i < run_.manifold.contact_count; ++i) {
        const Vec3 p = to_vec(run_.manifold.contacts[i].point_on_a);
        const double pi = std::acos(-1.0), angle = std::atan2(p.y(), p.x());
        if (std::abs(std::remainder(angle - pi * (corner - 0.5) / 4, 2 * pi)) < 0.05)
          m.contacts[count++] = run_.manifold.contacts[i];
      }
    EXPECT_EQ(count, static_cast<int>(kept.size()));
    m.contact_count = count;
    return m;
  }

  CheckStatus spans(const mfz_manifold& m, int max_contacts) const {
    Profile profile;
    profile.max_contacts = max_contacts;
    return status_in(check_manifold(run_.scene, run_.oracles, 0, m, profile), "spans-contact-region");
  }

  CaseRun run_;
};

TEST_F(ReducedManifold, TheFullManifoldSpansTheFirstTouchingStrip) {
  ASSERT_EQ(run_.manifold.contact_count, 8);
  EXPECT_EQ(spans(run_.manifold, 0), CheckStatus::pass);
}

// A reducer keeps four corners of the overlap, and the square of largest
// area leaves out one end of the deepest edge: it misses the strip's
// centroid and encloses the whole intersection's, the contract's region.
// Held to a full manifold it fails; declaring max-contacts=4 it passes (h13:
// a correct reducer flagged within minutes).
TEST_F(ReducedManifold, FourCornersOfLargestAreaPassAtTheDeclaredMaxContacts) {
  const mfz_manifold square = keeping({1, 3, 5, 7});
  EXPECT_EQ(spans(square, 0), CheckStatus::fail);
  EXPECT_EQ(spans(square, 4), CheckStatus::pass);
}

// Four corners side by side, as `count = min(count, 4)` keeps them, miss
// both centroids, on the shallow side or beside the deepest edge: the
// declared max-contacts excuses which four, not where they lie.
TEST_F(ReducedManifold, FourCornersOnOneSideFailEvenAtTheDeclaredMaxContacts) {
  EXPECT_EQ(spans(keeping({3, 4, 5, 6}), 4), CheckStatus::fail);
  EXPECT_EQ(spans(keeping({1, 2, 3, 4}), 4), CheckStatus::fail);
}

// Fewer contacts than declared is no reduction: the manifold is held to the
// first-touching strip.
TEST_F(ReducedManifold, FewerContactsThanDeclaredAreHeldToTheFirstTouchingStrip) {
  EXPECT_EQ(spans(keeping({1, 3, 5, 7}), 8), CheckStatus::fail);
}

// Leaving a pass's detail out may spare the work behind its numbers, never
// change a verdict. The eight contacts slid across the strip so that they
// miss its centroid by a fraction of its drift (from 0.99 to 0.995 of the
// depth) up to ten drifts: spans-contact-region gives the same status and
// error either way, passing those within four drifts, failing the rest.
TEST_F(ReducedManifold, LeavingTheDetailOutChangesNoVerdictOnTheStrip) {
  const Scene& s = run_.scene;
  const Vec3 n = to_vec(run_.manifold.normal).normalized();
  const double depth = run_.oracles.exact.signed_depth, slack = s.length_tolerance(tol::kRegionSlack);
  const Eigen::Vector2d centroid = contact_region(s, n, 0.99 * depth * n, slack).centroid;
  const double drift = (contact_region(s, n, 0.995 * depth * n, slack).centroid - centroid).norm();
  ASSERT_GT(drift, 1e-5);
  Vec3 u, v;
  plane_basis(n, u, v);
  // Outward across the deepest edge, which the centroid lies beside.
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (int i = 0; i < run_.manifold.contact_count; ++i) {
    const Vec3 p = to_vec(run_.manifold.contacts[i].point_on_a);
    mean += Eigen::Vector2d(u.dot(p), v.dot(p)) / run_.manifold.contact_count;
  }
  const Eigen::Vector2d out2 = (centroid - mean).normalized();
  const Vec3 out = out2.x() * u + out2.y() * v;
  double edge = -INFINITY;
  for (int i = 0; i < run_.manifold.contact_count; ++i)
    edge = std::max(edge, out.dot(to_vec(run_.manifold.contacts[i].point_on_a)));
  const double inside_by = edge - out2.dot(centroid);
  const auto spans_check = [&](const mfz_manifold& m, PassDetails details) {
    for (const InvariantCheck& c : check_manifold(s, run_.oracles, 0, m, {}, details).checks)
      if (c.name == "spans-contact-region") return c;
    return InvariantCheck{};
  };
  for (const double drifts : {-1.0, 0.5, 2.0, 3.5, 6.0, 10.0}) {
    mfz_manifold m = run_.manifold;
    for (int i = 0; i < m.contact_count; ++i)
      for (mfz_vec3* p : {&m.contacts[i].point_on_a, &m.contacts[i].point_on_b})
        *p = to_abi(to_vec(*p) - (inside_by + drifts * drift) * out);
    const InvariantCheck written = spans_check(m, PassDetails::written);
    const InvariantCheck left_out = spans_check(m, PassDetails::left_out);
    EXPECT_EQ(written.status, drifts <= 4 ? CheckStatus::pass : CheckStatus::fail) << drifts << " drifts";
    EXPECT_EQ(left_out.status, written.status) << drifts << " drifts";
    EXPECT_EQ(left_out.error, written.error) << drifts << " drifts";
    EXPECT_EQ(written.error > 0, drifts > 0) << drifts << " drifts";
  }
}

// Two plates 0.1 thick, sunk through each other (A's bottom and B's bottom
// are edges, their tops faces at one height): the built-in clips eleven
// points under A's top face, two of them the full-depth ends of the
// first-touching strip along B's lowest edge. The contract passes the four
// of largest area; four picked one at a time (the deepest, the farthest from
// it, the largest triangle, the largest quadrilateral) keep one end of the
// strip and the far side, and miss the whole intersection's centroid too
// (O23: the reducing variant reduced so, and was flagged once moved).
class PlatesSunkThroughEachOther : public ::testing::Test {
 protected:
  PlatesSunkThroughEachOther()
      : run_(test::run_builtin(test::make_case(
            {{0.91, 0.41, -0.05}, {-0.7, -0.7, -0.05}, {1.9, 0, 0.05}, {1.0624665, 1.5751714, 0.05}, {-2, 1, 0.05}},
            {}, {{1, 0, -0.05}, {-0.1045, 1, -0.05}, {-0.7, -0.7, 0}, {1.9, 0, 0.05}, {1.7357364, 0.8, 0.05},
                 {1, 1.6, 0.05}, {-1.4, 1.3, 0.05}},
            {}))) {}

  // The manifold keeping the contacts at (x, y) on A's top face.
  mfz_manifold keeping(std::initializer_list<Eigen::Vector2d> kept) const {
    mfz_manifold m = run_.manifold;
    int count = 0;
    for (const Eigen::Vector2d& xy : kept)
      for (int i = 0; i < run_.manifold.contact_count; ++i)
        if ((to_vec(run_.manifold.contacts[i].point_on_a).head<2>() - xy).norm() < 1e-3)
          m.contacts[count++] = run_.manifold.contacts[i];
    EXPECT_EQ(count, static_cast<int>(kept.size()));
    m.contact_count = count;
    return m;
  }

  CheckStatus spans(const mfz_manifold& m) const {
    Profile profile;
    profile.max_contacts = 4;
    return status_in(check_manifold(run_.scene, run_.oracles, 0, m, profile), "spans-contact-region");
  }

  CaseRun run_;
};

TEST_F(PlatesSunkThroughEachOther, TheFourOfLargestAreaPassFourPickedOneAtATimeDoNot) {
  ASSERT_EQ(to_vec(run_.manifold.normal), Vec3::UnitZ());
  ASSERT_EQ(run_.manifold.contact_count, 11);
  EXPECT_EQ(spans(keeping({{1, 1.563439}, {-1.225493, 0.801408}, {-1.338484, 1.124241}, {1.171734, 0.186735}})),
            CheckStatus::pass);
  EXPECT_EQ(spans(keeping({{-0.1045, 1}, {1.570287, 0.6201}, {1, 1.563439}, {1.171734, 0.186735}})),
            CheckStatus::fail);
}

// EPA's depth within its tolerance over the exact depth, and the
// generator's within depth-exact's under it: each is right by its own
// check, so EPA's bound holds the depth to both tolerances (h26: 1.2e15
// from the origin, a depth 0.215 under the exact one against an EPA 1.114e-6
// L over it failed by 1.12e-6 L against 1.11e-6 L). Past both, it fails.
TEST_F(InvariantFires, EpasLowerBoundHoldsTheDepthToEpasToleranceAndDepthExactsTogether) {
  ASSERT_TRUE(run_.oracles.ccd.epa_ok);
  const double exact = run_.oracles.exact.signed_depth;
  const double tol_epa = run_.scene.length_tolerance(tol::kEpa), tol_depth = run_.scene.length_tolerance(tol::kDepth);
  const auto epa_bounds = [&](double depth, double epa_depth) {
    OracleAnswers oracles = run_.oracles;
    oracles.ccd.epa_depth = epa_depth;
    mfz_manifold m = good();
    m.penetration = -depth;
    return status_in(check_manifold(run_.scene, oracles, 0, m), "depth-within-epa-bounds");
  };
  EXPECT_EQ(epa_bounds(exact - 0.9 * tol_depth, exact + tol_epa - 0.01 * tol_depth), CheckStatus::pass);
  EXPECT_EQ(epa_bounds(exact - 0.9 * tol_depth, exact + tol_epa), CheckStatus::pass);
  EXPECT_EQ(epa_bounds(exact - 3 * tol_depth, exact + tol_epa - 0.01 * tol_depth), CheckStatus::fail);
}

TEST(InvariantVerdict, TouchingCasesAcceptEitherCollidingAnswer) {
  for (int colliding : {0, 1}) {
    const CaseRun run = test::run_builtin(test::make_case(box_points(1, 1, 1), {}, box_points(1, 1, 1),
                                                          {Vec3(0.3, 0, 2), Quat::Identity()}));
    ASSERT_TRUE(run.oracles.touching);
    mfz_manifold m = run.manifold;
    m.colliding = colliding;
    m.contact_count = 0;
    m.penetration = 0;
    EXPECT_EQ(check_manifold(run.scene, run.oracles, 0, m).first_violation(), nullptr) << "colliding " << colliding;
  }
}

// A tetrahedron's bottom edge lies flat 0.01 deep in a slab's top face and
// runs out past its rim at x = 1: the face axis ties with the edge pair of
// that edge and the rim, along z, and the region is the edge's part over
// the face, 0.5 wide. Under a float profile the pair's one point, where the
// edge crosses the rim, is an answer the contract lets a generator give
// (h24: the float variant's edge pair, its normal the face's to the bit
// once rounded to float); in double, a normal that is the face's to the bit
// is the face's contact. The edge's inner end alone, the deepest vertex on
// no edge of the slab, is asked to span the region either way.
class EdgeFlatOnAFaceAcrossItsRim : public ::testing::Test {
 protected:
  EdgeFlatOnAFaceAcrossItsRim()
      : run_(test::run_builtin(test::make_case(
            box_points(1, 1, 0.25), {},
            {{0.5, 0, 0.24}, {1.5, 0, 0.24}, {1.0, 0.4, 0.6}, {0.8, -0.2, 0.9}}, {}))) {}

  CheckStatus spans_with_one_contact(const Vec3& on_b, double precision_epsilon) const {
    mfz_manifold m = run_.manifold;
    m.contact_count = 1;
    m.contacts[0].point_on_b = to_abi(on_b);
    m.contacts[0].point_on_a = to_abi(Vec3(on_b + Vec3(0, 0, 0.01)));
    m.contacts[0].penetration = -0.01;
    Scene scene = run_.scene;
    scene.precision_epsilon = precision_epsilon;
    Profile profile;
    profile.precision_epsilon = precision_epsilon;
    return status_in(check_manifold(scene, run_.oracles, 0, m, profile), "spans-contact-region");
  }

  static constexpr double kFloat = 0x1p-23, kDouble = 0;
  CaseRun run_;
};

TEST_F(EdgeFlatOnAFaceAcrossItsRim, TheBuiltInsTwoEndsSpanTheRegion) {
  ASSERT_EQ(to_vec(run_.manifold.normal), Vec3::UnitZ());
  ASSERT_NEAR(run_.manifold.penetration, -0.01, 1e-12);
  EXPECT_GE(run_.manifold.contact_count, 2);
  EXPECT_EQ(spans_with_one_contact(Vec3(0.75, 0, 0.24), kDouble), CheckStatus::pass);
}

TEST_F(EdgeFlatOnAFaceAcrossItsRim, UnderAFloatProfileTheEdgePairsOnePointAtTheRimIsNotAskedToSpanTheRegion) {
  EXPECT_EQ(spans_with_one_contact(Vec3(1, 0, 0.24), kFloat), CheckStatus::skipped);
}

TEST_F(EdgeFlatOnAFaceAcrossItsRim, InDoubleOnePointAtTheRimIsAFaceContactAndFailsToSpanTheRegion) {
  EXPECT_EQ(spans_with_one_contact(Vec3(1, 0, 0.24), kDouble), CheckStatus::fail);
}

TEST_F(EdgeFlatOnAFaceAcrossItsRim, TheDeepestVertexAloneFailsToSpanTheRegionUnderEitherPrecision) {
  EXPECT_EQ(spans_with_one_contact(Vec3(0.5, 0, 0.24), kFloat), CheckStatus::fail);
  EXPECT_EQ(spans_with_one_contact(Vec3(0.5, 0, 0.24), kDouble), CheckStatus::fail);
}

}  // namespace
}  // namespace mfz

// Hand-computed manifolds of the built-in generator, exact to 1e-12.
#include "generator/clipping_generator.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "case/case_file.h"
#include "case/scene.h"
#include "generator/coplanar_patch.h"
#include "geometry/tolerances.h"
#include "geometry/hull.h"
#include "test_support.h"

namespace mfz {
namespace {

using test::about;
using test::box_points;
using test::make_case;
using test::run_builtin;

constexpr double kExact = 1e-12;

struct Expected {
  Vec3 on_a, on_b;
  double penetration;
};

// Contacts come in the clipper's loop order; compare them as a set.
void expect_contacts(const mfz_manifold& m, const std::vector<Expected>& expected) {
  ASSERT_EQ(m.contact_count, static_cast<int>(expected.size()));
  for (const Expected& e : expected) {
    bool found = false;
    for (int i = 0; i < m.contact_count && !found; ++i)
      found = (to_vec(m.contacts[i].point_on_a) - e.on_a).norm() <= kExact &&
              (to_vec(m.contacts[i].point_on_b) - e.on_b).norm() <= kExact &&
              std::abs(m.contacts[i].penetration - e.penetration) <= kExact;
    EXPECT_TRUE(found) << "no contact with on A " << e.on_a.transpose() << ", on B " << e.on_b.transpose();
  }
}

void expect_all_invariants_hold(const CaseRun& run) {
  const InvariantCheck* failed = run.verdict.first_violation();
  EXPECT_EQ(failed, nullptr) << failed->name << ": " << failed->detail;
}

TEST(ClippingGenerator, BoxRestingOnLargerBoxGivesItsFourBottomCorners) {
  const CaseRun run = run_builtin(make_case(box_points(2, 2, 0.5), {}, box_points(0.5, 0.5, 0.5),
                                            {Vec3(0, 0, 0.9), Quat::Identity()}));
  const mfz_manifold& m = run.manifold;
  EXPECT_EQ(m.colliding, 1);
  EXPECT_VEC_NEAR(to_vec(m.normal), Vec3(0, 0, 1), kExact);
  EXPECT_NEAR(m.penetration, -0.1, kExact);
  std::vector<Expected> corners;
  for (double x : {-0.5, 0.5})
    for (double y : {-0.5, 0.5}) corners.push_back({Vec3(x, y, 0.5), Vec3(x, y, 0.4), -0.1});
  expect_contacts(m, corners);
  expect_all_invariants_hold(run);
}

TEST(ClippingGenerator, BoxTurned45DegreesAboutTheNormalGivesAnOctagon) {
  const CaseRun run = run_builtin(make_case(box_points(1, 1, 0.5), {}, box_points(1, 1, 0.5),
                                            {Vec3(0, 0, 0.9), about(Vec3::UnitZ(), M_PI / 4)}));
  const double s = std::sqrt(2.0) - 1;  // where the turned square's edges cross x = +-1
  std::vector<Expected> octagon;
  for (const auto& [x, y] : std::vector<std::pair<double, double>>{
           {1, s}, {1, -s}, {-1, s}, {-1, -s}, {s, 1}, {-s, 1}, {s, -1}, {-s, -1}})
    octagon.push_back({Vec3(x, y, 0.5), Vec3(x, y, 0.4), -0.1});
  EXPECT_NEAR(run.manifold.penetration, -0.1, kExact);
  expect_contacts(run.manifold, octagon);
  expect_all_invariants_hold(run);
}

TEST(ClippingGenerator, BoxBelowSlabPointsTheNormalDownAndKeepsContactsOnBothSurfaces) {
  // A rests under B: n runs from A to B, i.e. downwards.
  const CaseRun run = run_builtin(make_case(box_points(0.5, 0.5, 0.5), {Vec3(0, 0, 0.9), Quat::Identity()},
                                            box_points(2, 2, 0.5), {}));
  EXPECT_VEC_NEAR(to_vec(run.manifold.normal), Vec3(0, 0, -1), kExact);
  std::vector<Expected> corners;
  for (double x : {-0.5, 0.5})
    for (double y : {-0.5, 0.5}) corners.push_back({Vec3(x, y, 0.4), Vec3(x, y, 0.5), -0.1});
  expect_contacts(run.manifold, corners);
  expect_all_invariants_hold(run);
}

TEST(ClippingGenerator, TetrahedronTipInAFaceGivesOneContactAtTheTip) {
  const CaseRun run = run_builtin(test::make_case(
      box_points(3, 3, 1), {Vec3(0, 0, -1), Quat::Identity()},
      {{0, 0, 0}, {1, 0, 1}, {-0.5, std::sqrt(0.75), 1}, {-0.5, -std::sqrt(0.75), 1}},
      {Vec3(0, 0, -0.1), Quat::Identity()}));
  EXPECT_NEAR(run.manifold.penetration, -0.1, kExact);
  expect_contacts(run.manifold, {{Vec3(0, 0, 0), Vec3(0, 0, -0.1), -0.1}});
  expect_all_invariants_hold(run);
}

TEST(ClippingGenerator, TipOfAIntoFaceOfBFlipsReferenceAndIncident) {
  // A's tip points up into B's bottom face: B's face is the reference face.
  ClipTrace trace;
  const CaseFile c = make_case({{0, 0, 0}, {1, 0, -1}, {-0.5, std::sqrt(0.75), -1}, {-0.5, -std::sqrt(0.75), -1}},
                               {}, box_points(3, 3, 1), {Vec3(0, 0, 0.9), Quat::Identity()});
  const CaseRun run = run_builtin(c);
  const mfz_hull a = run.scene.hull_a.view(), b = run.scene.hull_b.view();
  mfz_manifold m;
  generate_clipping_manifold(a, run.scene.abi_pose_a(), b, run.scene.abi_pose_b(), m, &trace);
  EXPECT_TRUE(trace.flipped);
  // The trace names each hull's support vertex, B's too, though SAT's face
  // of B is the reference face and the generator needs no support there.
  ASSERT_GE(trace.support_a, 0);
  ASSERT_GE(trace.support_b, 0);
  EXPECT_VEC_NEAR(run.scene.world_a[static_cast<size_t>(trace.support_a)], Vec3(0, 0, 0), kExact);
  EXPECT_NEAR(run.scene.world_b[static_cast<size_t>(trace.support_b)].z(), -0.1, kExact);
  EXPECT_VEC_NEAR(to_vec(m.normal), Vec3(0, 0, 1), kExact);
  expect_contacts(m, {{Vec3(0, 0, 0), Vec3(0, 0, -0.1), -0.1}});
  expect_all_invariants_hold(run);
}

TEST(ClippingGenerator, EdgeCrossingEdgeGivesOneContactWhereTheEdgesCross) {
  const double half_diagonal = std::sqrt(2.0);
  const CaseRun run = run_builtin(make_case(box_points(1, 1, 1), {Vec3::Zero(), about(Vec3::UnitY(), M_PI / 4)},
                                            box_points(1, 1, 1),
                                            {Vec3(0, 0, 2 * half_diagonal - 0.1), about(Vec3::UnitX(), M_PI / 4)}));
  EXPECT_EQ(run.manifold.colliding, 1);
  EXPECT_VEC_NEAR(to_vec(run.manifold.normal), Vec3(0, 0, 1), kExact);
  EXPECT_NEAR(run.manifold.penetration, -0.1, kExact);
  // A's top edge runs along y at x = 0, B's bottom edge along x at y = 0: they
  // cross above the origin, A's at height sqrt(2), B's 0.1 below it (F3).
  expect_contacts(run.manifold, {{Vec3(0, 0, half_diagonal), Vec3(0, 0, half_diagonal - 0.1), -0.1}});
  expect_all_invariants_hold(run);
}

TEST(ClippingGenerator, SeparatedBoxesAreNotColliding) {
  const CaseRun run = run_builtin(make_case(box_points(0.5, 0.5, 0.5), {}, box_points(0.5, 0.5, 0.5),
                                            {Vec3(1.5, 0.2, 0), Quat::Identity()}));
  EXPECT_EQ(run.manifold.colliding, 0);
  EXPECT_EQ(run.manifold.contact_count, 0);
  expect_all_invariants_hold(run);
}

TEST(ClippingGenerator, ExactlyTouchingBoxesHaveZeroDepthAndNoContacts) {
  const CaseRun run = run_builtin(make_case(box_points(2, 2, 0.5), {}, box_points(0.5, 0.5, 0.5),
                                            {Vec3(0.25, 0, 1), Quat::Identity()}));
  EXPECT_TRUE(run.oracles.touching);
  EXPECT_EQ(run.manifold.colliding, 1) << "no axis separates strictly: the tutorial reports a collision";
  EXPECT_EQ(run.manifold.penetration, 0.0);
  EXPECT_EQ(run.manifold.contact_count, 0) << "the tutorial makes no contacts unless p < 0";
  expect_all_invariants_hold(run);
}

TEST(ClippingGenerator, JustSeparatedAndJustOverlappingAreEitherSideOfTouching) {
  for (const double gap : {1e-6, -1e-6}) {
    const CaseRun run = run_builtin(make_case(box_points(2, 2, 0.5), {}, box_points(0.5, 0.5, 0.5),
                                              {Vec3(0.25, 0, 1 + gap), Quat::Identity()}));
    EXPECT_EQ(run.manifold.colliding, gap < 0 ? 1 : 0) << "gap " << gap;
    EXPECT_EQ(run.manifold.contact_count, gap < 0 ? 4 : 0) << "gap " << gap;
    expect_all_invariants_hold(run);
  }
}

TEST(ClippingGenerator, ContactsAreCappedAtTheAbiCapacity) {
  // A 100-gon prism turned 1.8 degrees on another: the clipped polygon has
  // 200 points, more than a manifold holds.
  std::vector<Vec3> prism;
  for (int k = 0; k < 100; ++k) {
    const double t = 2 * M_PI * k / 100;
    prism.emplace_back(std::cos(t), std::sin(t), -0.5);
    prism.emplace_back(std::cos(t), std::sin(t), 0.5);
  }
  const CaseRun run = run_builtin(make_case(prism, {}, prism, {Vec3(0, 0, 0.9), about(Vec3::UnitZ(), M_PI / 100)}));
  EXPECT_EQ(run.manifold.contact_count, MFZ_MAX_CONTACTS);
  expect_all_invariants_hold(run);
}

// A needle 1.3e-8 thin and 16000 long has 45 edges within the world's
// rounding of its reach along an edge axis, 13 of them crossing B's edge.
// Every one is tried, so the hull's numbering does not choose the contacts:
// capped at the first 32, the needle numbered backwards kept none of the 13,
// and a clipped face put a contact 6.7 off A (F34, vertex-order).
TEST(ClippingGenerator, EverySupportingEdgeIsTriedWhateverTheHullsNumbering) {
  const CaseParse parsed = read_case_file(
      test::corpus_path("regressions/f34-a-needle-1e-8-thin-across-an-edge-off-surface-after-renumbering.case"));
  ASSERT_TRUE(parsed.value) << parsed.error;
  const Scene s = *make_scene(*parsed.value).scene;
  const auto manifold = [&](const Hull& a, const Hull& b) {
    mfz_manifold m{};
    EXPECT_EQ(generate_clipping_manifold(a.view(), s.abi_pose_a(), b.view(), s.abi_pose_b(), m), 0);
    return m;
  };
  const mfz_manifold as_given = manifold(s.hull_a, s.hull_b);
  const mfz_manifold renumbered = manifold(s.hull_a.renumbered(), s.hull_b.renumbered());
  EXPECT_EQ(as_given.contact_count, 13);
  ASSERT_EQ(renumbered.contact_count, as_given.contact_count);
  // The same crossings, reached from the edges' other ends: equal to the
  // rounding of coordinates 4466 from the origin.
  const double rounding = 1e-9 * s.scale;
  for (int i = 0; i < as_given.contact_count; ++i) {
    const Vec3 p = to_vec(as_given.contacts[i].point_on_a);
    double nearest = INFINITY;
    for (int j = 0; j < renumbered.contact_count; ++j)
      nearest = std::min(nearest, (to_vec(renumbered.contacts[j].point_on_a) - p).norm());
    EXPECT_LE(nearest, rounding) << "contact " << i;
  }
}

// The contact counts of a regression case's scene as given and with both
// poses moved by `move`: equal when a kept point's column is drawn alike.
template <class Move>
std::pair<int, int> contact_counts_as_given_and_moved(const std::string& regression, Move move) {
  const CaseParse parsed = read_case_file(test::corpus_path("regressions/" + regression));
  EXPECT_TRUE(parsed.value) << parsed.error;
  if (!parsed.value) return {-1, -1};
  const Scene s = *make_scene(*parsed.value).scene;
  mfz_manifold as_given{}, moved{};
  EXPECT_EQ(generate_clipping_manifold(s.hull_a.view(), s.abi_pose_a(), s.hull_b.view(), s.abi_pose_b(), as_given), 0);
  EXPECT_EQ(generate_clipping_manifold(s.hull_a.view(), move(s.pose_a).to_abi(), s.hull_b.view(),
                                       move(s.pose_b).to_abi(), moved),
            0);
  return {as_given.contact_count, moved.contact_count};
}

// A needle cone 2000 long whose ridge runs 1.5e-4 rad off B's reference face:
// the first-touching region reaches 0.5 up the ridge. The incident face (a
// rim face of the crumpled base, 5.7 degrees off) and F27's faces gave 65
// points, one past the ABI's 64, and only the incident face's three were
// kept, within 0.003 of the base (F55, spans-contact-region, open as O21).
TEST(ClippingGenerator, PastTheAbisCapacityTheContactsKeepTheOutlineOfEveryFaceBelowTheReferencePlane) {
  const CaseParse parsed = read_case_file(test::corpus_path(
      "regressions/f55-past-the-abi-s-64-contacts-a-needle-cone-s-ridge-lost-the-points-f27-s-faces-gave.case"));
  ASSERT_TRUE(parsed.value) << parsed.error;
  const Scene s = *make_scene(*parsed.value).scene;
  mfz_manifold out{};
  ASSERT_EQ(generate_clipping_manifold(s.hull_a.view(), s.abi_pose_a(), s.hull_b.view(), s.abi_pose_b(), out), 0);
  ASSERT_GT(out.contact_count, 3);
  double highest = -1;
  for (int i = 0; i < out.contact_count; ++i) highest = std::max(highest, out.contacts[i].point_on_a.z);
  EXPECT_GT(highest, 0.49);  // up the ridge to where it leaves B's face
}

// A thin wedge 5e15 from the origin: the far end of its 2000-long edge
// stands 63 beside the column of the corner kept at its near end, within the
// world's rounding of the poses (about 72) that F30's column allows. The
// world turned about a skew axis has the same rounding, so the turned run
// drops that end too; measured on the largest coordinate, which the turn
// made smaller, it kept it, 2000 from every contact (F35, rigid-motion).
TEST(ClippingGenerator, AKeptPointsColumnIsAsWideInATurnedWorld) {
  const Quat turn(Eigen::AngleAxisd(0.9, Vec3(1, 2, 3).normalized()));
  const auto [as_given, turned] = contact_counts_as_given_and_moved(
      "f35-a-thin-wedge-5e15-out-gains-a-contact-2000-away-when-moved.case",
      [&](const Pose& p) { return Pose{turn * p.position, (turn * p.orientation).normalized()}; });
  EXPECT_EQ(as_given, 3);
  EXPECT_EQ(turned, as_given);
}

// A slab's edge 1e-3 long, 4.4e-6 rad off the normal, 3e5 from the origin:
// its far end stands 4.4e-9 beside the column of the point kept at its
// deeper end, between the world's rounding there (4.3e-9) and 2.7e4 further
// out (4.6e-9). The column is the same in both frames, and drops that end
// in both (F46, far-from-origin, open as O13).
TEST(ClippingGenerator, AKeptPointsColumnIsAsWideMovedFurtherFromTheOrigin) {
  const Vec3 out(15407.9289055036, -20543.905207338135, 7703.9644527518);
  const auto [as_given, moved_out] = contact_counts_as_given_and_moved(
      "f46-a-slab-s-edge-4e-9-beside-a-kept-point-s-column-far-out-adds-a-point-in-one-frame.case",
      [&](const Pose& p) { return Pose{p.position + out, p.orientation}; });
  EXPECT_EQ(as_given, 3);
  EXPECT_EQ(moved_out, as_given);
}

// A needle 9900 long across n, its long edge 2.7e-4 rad from B's edge:
// turned and moved 7.6e3 out, the axis those edges make leaves the far end
// 2.5e-10 below the near one. Within 1e-9 of the needle's span the edge
// still supports A, and the pair crosses: one contact in both frames, where
// the moved run clipped faces on the edge axis and gave six, three of them
// 0.118 off B (F47, rigid-motion, open as O14).
TEST(ClippingGenerator, TheEdgeAnAxisCameFromStillSupportsItsHullTurnedAndMovedOut) {
  const Quat turn(0.9004471023526769, 0.11624942883566838, 0.23249885767133677, 0.3487482865070052);
  const Vec3 shift(6930.000350000071, -2970.0001500000303, 1980.0001000000204);
  const auto [as_given, moved] = contact_counts_as_given_and_moved(
      "f47-a-needle-across-n-turned-and-moved-out-lost-the-edge-its-axis-came-from.case",
      [&](const Pose& p) { return Pose{turn * p.position + shift, (turn * p.orientation).normalized()}; });
  EXPECT_EQ(as_given, 1);
  EXPECT_EQ(moved, as_given);
}

// The sides kept once per call are the sides computed as each is clipped
// against, to the bit: a 6-gon's kept, a 100-gon's (past kKeptPrismSides)
// computed, and a tilted square clipped against each gives the same points
// either way, within the same bands (read from the kept loop's largest
// coordinate, or measured on the loop).
TEST(ClippingGenerator, TheReferencePrismsKeptSidesClipAsTheSidesComputedOnEachClip) {
  for (const int corners : {3, 6, kKeptPrismSides, 100}) {
    ClipPolygon loop, incident;
    for (int k = 0; k < corners; ++k) {
      const double t = 2 * M_PI * k / corners;
      loop.push(Vec3(std::cos(t), std::sin(t), 0));
    }
    for (const Vec3& p : {Vec3(0.3, -1.2, -0.01), Vec3(1.4, 0.1, -0.02), Vec3(0.2, 1.3, 0.01), Vec3(-0.9, 0, 0.02)})
      incident.push(p);
    ClipFace reference;
    reference.normal = Vec3(0, 0, 1);
    reference.polygon = &loop;
    reference.world_resolution = 1;
    ClipPolygon computed = incident, kept = incident;
    ASSERT_TRUE(clip_to_reference_prism(reference, computed, nullptr));
    PrismSides sides;
    keep_prism_sides(reference, sides);
    EXPECT_EQ(sides.count, corners <= kKeptPrismSides ? corners : 0);
    const SideBands computed_bands = side_bands(reference, incident);
    reference.sides = &sides;
    const SideBands kept_bands = side_bands(reference, incident);
    EXPECT_EQ(kept_bands.on_plane, computed_bands.on_plane) << corners << " corners";
    EXPECT_EQ(kept_bands.near_plane, computed_bands.near_plane) << corners << " corners";
    // A polygon smaller than the loop: the loop's coordinate sets the band.
    ClipPolygon small;
    for (int k = 0; k < incident.size(); ++k) small.push(0.01 * incident[k]);
    EXPECT_EQ(side_bands(reference, small).on_plane, tol::world_rounding(1.0)) << corners << " corners";
    ASSERT_TRUE(clip_to_reference_prism(reference, kept, nullptr));
    ASSERT_EQ(kept.size(), computed.size()) << corners << " corners";
    ASSERT_GT(kept.size(), 4) << corners << " corners: the square is clipped";
    for (int k = 0; k < kept.size(); ++k) EXPECT_EQ(kept[k], computed[k]) << corners << " corners, point " << k;
  }
}

// The incident polygon clipped against the prism over `loop` (its normal
// and the world's magnitude given), the sides computed on the clip (first)
// and kept beforehand (second): both must clip alike.
std::pair<ClipPolygon, ClipPolygon> clipped_by_computed_and_kept_sides(const ClipPolygon& loop, const Vec3& normal,
                                                                       double world_resolution,
                                                                       const ClipPolygon& incident) {
  ClipFace reference;
  reference.normal = normal;
  reference.polygon = &loop;
  reference.world_resolution = world_resolution;
  PrismSides sides;
  keep_prism_sides(reference, sides);
  ClipPolygon computed = incident, kept = incident;
  EXPECT_TRUE(clip_to_reference_prism(reference, computed, nullptr));
  reference.sides = &sides;
  EXPECT_TRUE(clip_to_reference_prism(reference, kept, nullptr));
  return {computed, kept};
}

// A reference loop whose corner at (1, 1) holds an edge 4e-13 long, turned
// the wrong way as rounding leaves such an edge (the loop reflex there):
// its side, turned past its neighbour's, would cut the corner (0, 1) off
// the unit square. It is held at its neighbour's normal, on the sides kept
// and the sides computed alike, and the square is clipped whole. A hull
// whose two corners 3e-13 apart made such an edge gave a side turned one
// way in one argument order and another way swapped, contacts 0.89 apart
// (F64, swap-symmetry, manifuzz fuzz --max-points 8).
TEST(ClippingGenerator, ASideThroughAnEdgeTooShortForTheRoundingTurnsNoFurtherThanItsNeighbours) {
  ClipPolygon loop, incident;
  for (const Vec3& p : {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(1 - 4e-13, 1 - 1e-13, 0), Vec3(0, 1, 0)})
    loop.push(p);
  for (const Vec3& p : {Vec3(-0.5, -0.5, -0.1), Vec3(1.5, -0.5, -0.1), Vec3(1.5, 1.5, -0.1), Vec3(-0.5, 1.5, -0.1)})
    incident.push(p);
  const auto [computed, kept] = clipped_by_computed_and_kept_sides(loop, Vec3(0, 0, 1), 1, incident);
  for (const ClipPolygon* clipped : {&computed, &kept}) {
    bool corner = false;
    for (int k = 0; k < clipped->size(); ++k)
      corner = corner || ((*clipped)[k] - Vec3(0, 1, -0.1)).norm() < 1e-9;
    EXPECT_TRUE(corner) << (clipped == &computed ? "computed" : "kept") << " sides cut the corner (0, 1) off";
    for (int k = 0; k < clipped->size(); ++k) EXPECT_LE((*clipped)[k].x() + (*clipped)[k].y(), 2 + 1e-9);
  }
}

// A sliver loop 14,142 long and 1.2e-8 wide, in a frame whose rounding is
// 15.6 (1.1e15 from the origin): its edges are too short for a sharp
// corner's cap, and its sides, 1.7e-12 rad apart, cross anywhere. The
// loop's extent caps hold the clip to within the rounding of the loop, on
// the sides kept and computed alike; an incident face 5e10 across, all
// around the sliver, was clipped to a point 3e8 beyond its end (F65).
TEST(ClippingGenerator, AReferenceSliverTooShortForItsCornersCapsClipsWithinItsExtent) {
  const Vec3 far(6.7e14, -8.9e14, 3.4e14);
  ClipPolygon loop, incident;
  for (const Vec3& p : {Vec3(-5000, -5000, 0), Vec3(4999.99999998268, 5000, 0), Vec3(0, 0, 0)}) loop.push(far + p);
  for (const Vec3& p : {Vec3(5e10, 0, -1), Vec3(-5e10, -5e10, -1), Vec3(0, 3e8, -1)}) incident.push(far + p);
  const double world = 1.1e15, rounding = tol::world_rounding(world);
  const auto [computed, kept] = clipped_by_computed_and_kept_sides(loop, Vec3(0, 0, 1), world, incident);
  const Vec3 along = Vec3(1, 1, 0).normalized();
  for (const ClipPolygon* clipped : {&computed, &kept})
    for (int k = 0; k < clipped->size(); ++k) {
      const Vec3 p = (*clipped)[k] - far;
      EXPECT_LE(std::abs(p.dot(along)), 7071.07 + 2 * rounding) << (clipped == &computed ? "computed" : "kept");
      EXPECT_LE(std::abs(p.dot(Vec3(-1, 1, 0).normalized())), 2 * rounding) << (clipped == &computed ? "computed" : "kept");
    }
}

// A reference sliver 1.6e9 long whose tip has a sine of 6.1e-4, and an
// incident triangle whose edge runs 1e-9 rad off the side through the
// sliver's upper edge, its end 10 past the tip and on the lower side's
// plane. F53's band keeps that edge whole in the upper side (its end
// 6.1e-3 outside it), and the lower side keeps the end as on its plane:
// the clip kept a point 10 beyond the tip, off the hull (F66,
// vertex-order). Every clipped point lies within the sliver's extent.
TEST(ClippingGenerator, AnEdgeHeldInASidePlaneIsCappedAtTheAcuteCornerItRunsPast) {
  const double tip = 1641134911.7389433;
  ClipPolygon loop, incident;
  for (const Vec3& v : {Vec3(-5e5, -5e5, -5e5), Vec3(5e5, 5e5, -5e5), Vec3(tip, -5e5, -5e5)}) loop.push(v);
  for (const Vec3& p : {Vec3(1641134921.7450404, -5e5, 0), Vec3(5e5, 5e5, 5e5), Vec3(0, -5e5, 5e5)})
    incident.push(p);
  const double world = tip, rounding = tol::world_rounding(world);
  const auto [computed, kept] = clipped_by_computed_and_kept_sides(loop, Vec3(0, 0, -1), world, incident);
  for (const auto& [clipped, which] : {std::pair{&computed, "computed"}, std::pair{&kept, "kept"}}) {
    ASSERT_GE(clipped->size(), 3) << which;
    for (int k = 0; k < clipped->size(); ++k) EXPECT_LE((*clipped)[k].x(), tip + 1e3 * rounding) << which << " sides, point " << k;
  }
}

// An incident edge 6000 long in the side plane x = 1e4 of a square
// reference face, tilted 2.3e-13 from it: its ends stand 7e-10 either side,
// five times the frame's rounding at the origin and far inside it 1e8 out.
// The edge lies in the plane in both frames and is kept whole; interpolated
// at the origin, it was cut at its middle, and a contact there stood in one
// frame only (F53, far-from-origin, open as O19).
TEST(ClippingGenerator, AnIncidentEdgeInASidePlaneTiltedBelowCoplanarityIsKeptWholeInEveryFrame) {
  for (const double out : {0.0, 1e8}) {
    const Vec3 at(out, 0, 0);
    ClipPolygon loop, incident;
    for (const Vec3& v : {Vec3(0, 0, 0), Vec3(1e4, 0, 0), Vec3(1e4, 1e4, 0), Vec3(0, 1e4, 0)}) loop.push(v + at);
    for (const Vec3& p : {Vec3(1e4 - 7e-10, 2e3, -1), Vec3(1e4 + 7e-10, 8e3, -1), Vec3(5e3, 5e3, -1)})
      incident.push(p + at);
    const auto [computed, kept] = clipped_by_computed_and_kept_sides(loop, Vec3(0, 0, 1), loop[2].norm(), incident);
    for (const auto& [clipped, which] : {std::pair{&computed, "computed"}, std::pair{&kept, "kept"}}) {
      ASSERT_EQ(clipped->size(), 3) << which << " sides, " << out << " out";
      for (int k = 0; k < clipped->size(); ++k)
        EXPECT_LE(((*clipped)[k] - incident[k]).norm(), 1e-6) << which << " sides, " << out << " out, point " << k;
    }
  }
}

// A needle face 28 long, its base 3.4e-13 wide (a tip of sine 1.2e-14),
// 5e5 from the origin, and a triangle across its tip. The two long sides'
// crossing, rounded, lay 4.97e-4 past the tip, and the clip kept a point
// there, outside the hull; the tip's cap holds the clip to it (F45, open
// as O12).
TEST(ClippingGenerator, ATriangleAcrossTheTipOfANeedleFaceFarOutIsClippedAtTheTip) {
  const Vec3 at(290195.14842605474, -386991.9424289519, 145111.51946893);
  ClipPolygon loop, incident;
  for (const Vec3& v : {Vec3(27.890015221084642, 27.890015221084642, 0), Vec3(27.89001522108361, 27.890015221084642, 28),
                        Vec3(27.89001522108395, 27.890015221084642, 28)})
    loop.push(v + at);
  for (const Vec3& p : {Vec3(290223.03843785997, -386964.05241714668, 145111.51996892999),
                        Vec3(290223.03843785997, -386964.05241714668, 145111.51896893),
                        Vec3(290223.03893785999, -386964.05241714668, 145111.51946893)})
    incident.push(p);
  const auto [computed, kept] = clipped_by_computed_and_kept_sides(loop, Vec3(0, 1, 0), at.norm(), incident);
  for (const auto& [clipped, which] : {std::pair{&computed, "computed"}, std::pair{&kept, "kept"}}) {
    ASSERT_FALSE(clipped->empty());
    // The needle runs up +z from its tip, loop[0].
    for (int k = 0; k < clipped->size(); ++k)
      EXPECT_LE(loop[0].z() - (*clipped)[k].z(), 1e-9) << which << " sides, point " << k;
  }
}

TEST(SharpCornerCap, OnlyANeedlesTipHasOneAndTheWholeFaceLiesBehindIt) {
  ClipPolygon needle;
  // A tip of sine 2e-6: its sides cross up to 7e-9 from it.
  for (const Vec3& v : {Vec3(0, 0, 0), Vec3(1, 1e-6, 0), Vec3(1, -1e-6, 0)}) needle.push(v);
  const double rounding = tol::world_rounding(1);
  Plane cap;
  ASSERT_TRUE(sharp_corner_cap(needle, 0, rounding, cap));
  EXPECT_NEAR(cap.normal.dot(Vec3(-1, 0, 0)), 1, 1e-12);
  for (int k = 0; k < needle.size(); ++k) EXPECT_LE(cap.signed_distance(needle[k]), rounding) << "corner " << k;
  EXPECT_FALSE(sharp_corner_cap(needle, 1, rounding, cap)) << "a corner of nearly 90 degrees";
  EXPECT_FALSE(sharp_corner_cap(needle, 2, rounding, cap)) << "a corner of nearly 90 degrees";
}

TEST(SharpCornerCap, OrdinaryCornersNearTheOriginHaveNone) {
  ClipPolygon square, sliver;
  for (const Vec3& v : {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)}) square.push(v);
  // A corner of sine 1e-3: the sides cross within 1e-12 of it.
  for (const Vec3& v : {Vec3(0, 0, 0), Vec3(1, 1e-3, 0), Vec3(1, 0, 0)}) sliver.push(v);
  Plane cap;
  for (int k = 0; k < 4; ++k) EXPECT_FALSE(sharp_corner_cap(square, k, tol::world_rounding(1), cap)) << "corner " << k;
  for (int k = 0; k < 3; ++k) EXPECT_FALSE(sharp_corner_cap(sliver, k, tol::world_rounding(1), cap)) << "corner " << k;
  // Moved 1e6 out, the same sliver's sides may cross 1.4e-5 from its tip.
  EXPECT_TRUE(sharp_corner_cap(sliver, 0, tol::world_rounding(1e6), cap));
}

TEST(SharpCornerCap, ACornerBesideAnEdgeTooShortForItsDirectionHasNone) {
  // The edge from corner 1 to corner 2 is 1e-13 long: its direction is
  // rounding, and a cap leaning on it could cut the face.
  ClipPolygon loop;
  for (const Vec3& v : {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1 - 1e-13, 1e-14, 0), Vec3(0, 1, 0)}) loop.push(v);
  Plane cap;
  EXPECT_FALSE(sharp_corner_cap(loop, 1, tol::world_rounding(1), cap));
  EXPECT_FALSE(sharp_corner_cap(loop, 2, tol::world_rounding(1), cap));
}

// A side every point lies inside is passed over. Clipping against every
// side in turn, as Sutherland-Hodgman does, must give the same points,
// crossing marks and all: polygons wholly inside a 64-gon, crossing it,
// with corners inside a side's band (on the side, kept as they are) and
// just beyond it (clipped), each already carrying a crossing mark.
TEST(ClippingGenerator, SidesThatClipNothingArePassedOverWithThePolygonEverySideInTurnGives) {
  const int corners = 64;
  ClipPolygon loop;
  for (int k = 0; k < corners; ++k) {
    const double t = 2 * M_PI * k / corners;
    loop.push(Vec3(std::cos(t), std::sin(t), 0));
  }
  ClipFace reference;
  reference.normal = Vec3(0, 0, 1);
  reference.polygon = &loop;
  reference.world_resolution = 1;
  PrismSides sides;
  keep_prism_sides(reference, sides);
  reference.sides = &sides;
  // The band of side 0, whose outward normal is the bisector of the first
  // two corners: a corner within it is on the side, one beyond it out.
  const Vec3 out0 = sides.plane[0].normal;
  const double on_side = sides.plane[0].offset;
  int passed_over = 0, clipped = 0;
  for (int n = 0; n < 48; ++n) {
    const double reach = 0.2 + 0.03 * n;  // 0.2 to 1.61: inside the 64-gon, then across it
    const double turn = 0.37 * n;
    ClipPolygon incident;
    for (int k = 0; k < 5; ++k) {
      const double t = turn + 2 * M_PI * k / 5;
      incident.push(Vec3(reach * std::cos(t), reach * std::sin(t), 0.01 * k), k % 2 == 1);
    }
    if (n % 3 == 1) {
      const SideBands bands = side_bands(reference, incident);
      incident.push(out0 * (on_side + 0.5 * bands.on_plane), true);  // on side 0, within its band
    }
    if (n % 3 == 2) incident.push(out0 * (on_side + 1e-9));  // beyond side 0's band
    ClipPolygon every_side = incident, scratch;
    const SideBands bands = side_bands(reference, every_side);
    for (int k = 0; k < corners; ++k) {
      ASSERT_TRUE(clip_to_plane(every_side, sides.plane[k], scratch, bands.on_plane, bands.near_plane, &sides.edge[k]));
      every_side.take(scratch);
    }
    ClipPolygon skipping = incident;
    ASSERT_TRUE(clip_to_reference_prism(reference, skipping, nullptr));
    ASSERT_EQ(skipping.size(), every_side.size()) << "polygon " << n;
    for (int k = 0; k < skipping.size(); ++k) {
      EXPECT_EQ(skipping[k], every_side[k]) << "polygon " << n << ", point " << k;
      EXPECT_EQ(skipping.is_crossing(k), every_side.is_crossing(k)) << "polygon " << n << ", point " << k;
    }
    (reach < 0.99 && n % 3 != 2 ? passed_over : clipped) += 1;
  }
  EXPECT_GT(passed_over, 10);
  EXPECT_GT(clipped, 10);
}

// A face_polygon step that is not the built-in's own: F27's shortcuts
// stand for the built-in's steps only, so through it every face is clipped.
ClippingSteps every_face_clipped() {
  ClippingSteps steps;
  steps.face_polygon = [](const PosedHull& hull, int face, ClipPolygon& out) { coplanar_patch(hull, face, out); };
  return steps;
}

// The corners of an n-gon prism about z.
std::vector<Vec3> prism_points(int sides, double radius, double half_height) {
  std::vector<Vec3> corners;
  for (int k = 0; k < sides; ++k) {
    const double angle = 2 * M_PI * k / sides;
    for (const double z : {-half_height, half_height})
      corners.push_back(Vec3(radius * std::cos(angle), radius * std::sin(angle), z));
  }
  return corners;
}

// The other faces below the reference plane (F27) that lie wholly beside
// one side of the prism are passed over before their patch is gathered.
// Through a face_polygon step that is not the built-in's own, the shortcut
// stands aside and every face is clipped: each answer must be the same
// bytes. Deep pairs of 32- and 128-point hulls, where most of the near
// half of the incident hull reaches below a small reference face, and
// boxes, whose sides stand beside it.
TEST(ClippingGenerator, FacesBesideTheReferencePrismArePassedOverWithTheContactsOfClippingThem) {
  const ClippingSteps every_face = every_face_clipped();
  const ClippingSteps builtin;
  int contacts = 0;
  for (const int points : {32, 128}) {
    const Hull a = *build_hull(test::sphere_points(points, 5u * points)).hull;
    const Hull b = *build_hull(test::sphere_points(points, 9u * points)).hull;
    const mfz_hull va = a.view(), vb = b.view();
    for (int k = 0; k < 40; ++k) {
      const mfz_pose pa = Pose{Vec3::Zero(), Quat::Identity()}.to_abi();
      const Vec3 at = 0.6 * Vec3(std::cos(0.7 * k), std::sin(1.3 * k), std::cos(2.9 * k));
      const mfz_pose pb = Pose{at, test::about(Vec3(1, 2, 3 + k), 0.37 * k)}.to_abi();
      mfz_manifold passed_over{}, clipped{};
      ASSERT_EQ(generate_clipping_manifold(va, pa, vb, pb, passed_over, nullptr, builtin), 0);
      ASSERT_EQ(generate_clipping_manifold(va, pa, vb, pb, clipped, nullptr, every_face), 0);
      ASSERT_EQ(passed_over.contact_count, clipped.contact_count) << points << " points, pose " << k;
      EXPECT_EQ(std::memcmp(passed_over.contacts, clipped.contacts, sizeof(mfz_contact) * clipped.contact_count), 0)
          << points << " points, pose " << k;
      contacts += clipped.contact_count;
    }
  }
  EXPECT_GT(contacts, 200);
}

// The faces beside a box's incident face lean toward the reference face and
// reach below its plane by the incident face's edge alone: their corners
// below it are held already, to the bit, and F27 passes over them without
// clipping. Through a face_polygon step that is not the built-in's own,
// every such face is clipped, and each answer must be the same bytes: boxes
// resting face to face, tilted up to 8 degrees, some astride the lower
// box's edge, the same box with its faces split in triangles (coplanar
// patches, which are clipped whole), a 32-gon prism standing on a box, and
// 8-point hulls pressed
// into it, whose faces beside the incident face reach below the plane by
// corners of their own or cross the prism's sides.
Hull wobbled_fans(const Hull& h, double wobble);

TEST(ClippingGenerator, FacesReachingBelowByHeldCornersAlonePassedOverWithTheContactsOfClippingThem) {
  const ClippingSteps every_face = every_face_clipped();
  const ClippingSteps builtin;
  const std::vector<Vec3> prism = prism_points(32, 0.25, 0.3);
  const Hull below = *build_hull(test::box_points(1, 0.8, 0.5)).hull;
  const mfz_hull va = below.view();
  const mfz_pose pa = Pose{Vec3::Zero(), Quat::Identity()}.to_abi();
  int contacts = 0;
  const Hull box = *build_hull(test::box_points(0.4, 0.3, 0.35)).hull;
  for (const Hull& above : {box, wobbled_fans(box, 0.0), *build_hull(prism).hull,
                            *build_hull(test::sphere_points(8, 11)).hull, *build_hull(test::sphere_points(8, 23)).hull}) {
    const mfz_hull vb = above.view();
    for (int k = 0; k < 48; ++k) {
      const double tilt = (k % 8) * M_PI / 180;
      const Quat turn = test::about(Vec3::UnitZ(), 0.61 * k) * test::about(Vec3(std::cos(k), std::sin(k), 0), tilt);
      // Half of them astride the lower box's edge at x = 1.
      const Vec3 at(k % 2 ? 0.9 : 0.5 * std::sin(1.3 * k), 0.3 * std::cos(0.7 * k), 0.5 + 0.3 + 0.02 * std::sin(k));
      const mfz_pose pb = Pose{at, turn}.to_abi();
      mfz_manifold passed_over{}, clipped{};
      ASSERT_EQ(generate_clipping_manifold(va, pa, vb, pb, passed_over, nullptr, builtin), 0);
      ASSERT_EQ(generate_clipping_manifold(va, pa, vb, pb, clipped, nullptr, every_face), 0);
      ASSERT_EQ(passed_over.contact_count, clipped.contact_count) << "pose " << k;
      EXPECT_EQ(std::memcmp(passed_over.contacts, clipped.contacts, sizeof(mfz_contact) * clipped.contact_count), 0)
          << "pose " << k;
      contacts += clipped.contact_count;
    }
  }
  EXPECT_GT(contacts, 200);
}

// Every face of `h` as a fan of triangles, each normal turned by up to
// `wobble` rad about an axis of its own: coplanar patches whose triangles'
// normals are within tol::kCoplanarSine of some and not of others, so that
// the patch gathered depends on the triangle it starts from.
Hull wobbled_fans(const Hull& h, double wobble) {
  std::vector<Vec3> vertices;
  std::vector<std::vector<int>> loops;
  std::vector<Vec3> normals;
  for (int i = 0; i < h.vertex_count(); ++i) vertices.push_back(h.vertex(i));
  for (int f = 0; f < h.face_count(); ++f)
    for (int k = 1; k + 1 < h.face_size(f); ++k) {
      loops.push_back({h.face_vertex(f, 0), h.face_vertex(f, k), h.face_vertex(f, k + 1)});
      const Vec3 axis = h.face_normal(f).cross(Vec3(std::cos(1.7 * k), std::sin(2.3 * k), 0.3)).normalized();
      normals.push_back(test::about(axis, wobble * std::sin(0.9 * k)) * h.face_normal(f));
    }
  return Hull::from_faces(vertices, loops, normals);
}

// A triangulated face is met by F27 once per triangle, and each triangle
// gathers the patch: a loop met again is not clipped again. Through a
// face_polygon step that is not the built-in's own, every triangle is
// clipped, and each answer must be the same bytes: a small triangulated
// 32-gon prism, cube and sphere hull deep below a large face or astride
// its edge, the triangles' normals exactly the face's, or wobbling by 0.65
// and 0.8 of the coplanar sine (patches that differ from triangle to
// triangle) and by twice it (patches of one or two triangles). A patch's
// faces are passed by unclipped only where they share one normal to the
// bit: passed by whatever their normals, the 0.65 wobble's pose 13 kept
// 30 of its 31 contacts (ClippedPatchFaces).
TEST(ClippingGenerator, ATriangulatedPatchMetAgainFromAnotherTriangleIsClippedOnceWithTheSameContacts) {
  const ClippingSteps every_face = every_face_clipped();
  const ClippingSteps builtin;
  const std::vector<Vec3> prism = prism_points(32, 0.1, 0.05);
  const Hull slab = *build_hull(test::box_points(10, 10, 1)).hull;
  const mfz_hull va = slab.view();
  const mfz_pose pa = Pose{Vec3::Zero(), Quat::Identity()}.to_abi();
  int contacts = 0;
  for (const double wobble : {0.0, 0.65 * tol::kCoplanarSine, 0.8 * tol::kCoplanarSine, 2 * tol::kCoplanarSine}) {
    for (const Hull& whole : {*build_hull(prism).hull, *build_hull(test::box_points(0.1, 0.1, 0.1)).hull,
                              *build_hull(test::sphere_points(48, 7)).hull}) {
      const Hull b = wobbled_fans(whole, wobble);
      const mfz_hull vb = b.view();
      for (int k = 0; k < 16; ++k) {
        // Half of them astride the slab's edge, whose side plane cuts the
        // triangles: their points are theirs alone, not the corners'.
        const Vec3 at(k % 2 ? 10 + 0.05 * std::cos(0.7 * k) : 0.3 * std::cos(0.7 * k), 0.3 * std::sin(1.3 * k), 0.97);
        const mfz_pose pb = Pose{at, test::about(Vec3(1, 2, 3 + k), 0.37 * k)}.to_abi();
        mfz_manifold once{}, every{};
        ASSERT_EQ(generate_clipping_manifold(va, pa, vb, pb, once, nullptr, builtin), 0);
        ASSERT_EQ(generate_clipping_manifold(va, pa, vb, pb, every, nullptr, every_face), 0);
        ASSERT_EQ(once.contact_count, every.contact_count) << "wobble " << wobble << ", pose " << k;
        EXPECT_EQ(std::memcmp(once.contacts, every.contacts, sizeof(mfz_contact) * every.contact_count), 0)
            << "wobble " << wobble << ", pose " << k;
        contacts += every.contact_count;
      }
    }
  }
  EXPECT_GT(contacts, 500);
}

// The faces of the coplanar patch around `face`, ascending.
std::vector<int> patch_members(const PosedHull& hull, int face) {
  int loop[kMaxPatchLoop], faces[kMaxPatchFaces], members = 0;
  patch_loop(hull, face, loop, members, faces);
  std::vector<int> sorted = members > 1 ? std::vector<int>(faces, faces + members) : std::vector<int>{face};
  std::sort(sorted.begin(), sorted.end());
  return sorted;
}

// F60: a patch is every face joined to its first by flat steps, so it is
// the same faces from whichever of them it is gathered, and no face is in
// two patches. Gathered against its first face's normal, a 32-gon prism's
// fanned caps, their triangles' normals wobbling by 0.65 and 0.8 of the
// coplanar sine, gave patches that depended on the triangle they started
// from (O28's disc of 43 triangles gave 43 patches of 29 to 31 corners).
TEST(CoplanarPatch, IsTheSameFacesFromWhicheverOfThemItIsGathered) {
  int shared = 0;
  for (const double wobble : {0.0, 0.65 * tol::kCoplanarSine, 0.8 * tol::kCoplanarSine, 2 * tol::kCoplanarSine}) {
    const Hull fans = wobbled_fans(*build_hull(prism_points(32, 0.1, 0.05)).hull, wobble);
    const mfz_hull view = fans.view();
    const Pose pose{Vec3(0.3, -0.2, 0.1), about(Vec3(1, 2, 3), 0.4)};
    const PosedHull hull(view, pose);
    for (int f = 0; f < hull.face_count(); ++f) {
      const std::vector<int> patch = patch_members(hull, f);
      ASSERT_TRUE(std::binary_search(patch.begin(), patch.end(), f));
      for (const int g : patch) {
        EXPECT_EQ(patch_members(hull, g), patch) << "wobble " << wobble << ", faces " << f << " and " << g;
        shared += g != f;
      }
    }
  }
  EXPECT_GT(shared, 1000);  // the caps' triangles do share patches
}

// F61: a fanned 300-gon cap is one patch of 298 triangles from whichever
// of them it is gathered, its loop the cap's 300 corners. With room for 256
// faces the gather stopped at a wedge of the cap, which the triangle it
// started from chose.
TEST(CoplanarPatch, AFannedCapOf300SidesIsOnePatchOfEveryTriangle) {
  const Hull fans = fan_triangulated(*build_hull(prism_points(300, 2, 0.5)).hull);
  const mfz_hull view = fans.view();
  const Pose pose{Vec3(0.3, -0.2, 0.1), about(Vec3(1, 2, 3), 0.4)};
  const PosedHull hull(view, pose);
  int caps = 0;
  for (int f = 0; f < hull.face_count(); ++f) {
    if (std::abs(std::abs(fans.face_normal(f).z()) - 1) > 1e-12) continue;  // a side
    int loop[kMaxPatchLoop], members = 0;
    ASSERT_EQ(patch_loop(hull, f, loop, members), 300) << "face " << f;
    EXPECT_EQ(members, 298) << "face " << f;
    ++caps;
  }
  EXPECT_EQ(caps, 2 * 298);
}

// The hulls the harness takes (1,024 points at most) have faces of up to
// 1,023 corners, and two faces clip to as many points as they have corners
// together. With room for 512, a box on a 508-gon face and two 256-gon
// prisms cap to cap were refused (status 1), and so were a box on a 520-gon
// face, either way round, and two 257-gon prisms here (F61, found by hand:
// the families make faces of 64 corners at most). Not larger: under the
// sanitizers a 1,000-gon face and 300-gon prisms took this test 24 s.
TEST(ClippingGenerator, FacesOfMoreThan512CornersTogetherAreClippedNotRefused) {
  const Hull base = *build_hull(test::pyramid_points(520, 3, -2)).hull;  // the base on top, facing +z
  const Hull box = *build_hull(test::box_points(0.5, 0.5, 0.5)).hull;
  const Hull cap = *build_hull(prism_points(257, 2, 0.5)).hull;
  struct Pair {
    const Hull &a, &b;
    Vec3 at;
    int contacts;  // a box's four corners; a polygon of caps' crossings reduced to the ABI's 64
  };
  for (const Pair& pair : {Pair{base, box, Vec3(0.2, 0.1, 0.45), 4}, Pair{box, base, Vec3(-0.2, -0.1, -0.45), 4},
                           Pair{cap, cap, Vec3(0.3, 0.1, 0.95), MFZ_MAX_CONTACTS}}) {
    const mfz_hull va = pair.a.view(), vb = pair.b.view();
    const mfz_pose pa = Pose{}.to_abi(), pb = Pose{pair.at, Quat::Identity()}.to_abi();
    mfz_manifold out{};
    ASSERT_EQ(generate_clipping_manifold(va, pa, vb, pb, out, nullptr, ClippingSteps{}), 0) << pair.at.transpose();
    EXPECT_EQ(out.contact_count, pair.contacts) << pair.at.transpose();
    EXPECT_NEAR(out.penetration, -0.05, 1e-12) << pair.at.transpose();
  }
}

// A square pyramid whose base, of area 1, lies 0.9 deep in a frustum whose
// top, of area 1 too, ties with it for the axis: a face of each along z,
// the same overlap, the same area. The frustum's sloping sides reach below
// the base's plane inside its prism, and the pyramid's sides face away
// from the frustum's top. Whichever hull comes first, the contacts are the
// base's square over the top's, and the sloping sides' points (F50: with
// the pyramid second, F27 reached only into it, and found none).
TEST(ClippingGenerator, AFaceOfEachTiedWithEqualAreasGivesTheSameContactsWhicheverHullComesFirst) {
  const std::vector<Vec3> pyramid = {{-0.5, -0.5, -0.5}, {0.5, -0.5, -0.5}, {0.5, 0.5, -0.5}, {-0.5, 0.5, -0.5},
                                     {0, 0, 0.5}};
  std::vector<Vec3> frustum;
  for (const double x : {-0.5, 0.5})
    for (const double y : {-0.5, 0.5}) frustum.push_back({x, y, 0.4}), frustum.push_back({3 * x, 3 * y, -1.6});
  const Pose at_origin{Vec3::Zero(), Quat::Identity()}, beside{Vec3(0.3, 0.2, 0), Quat::Identity()};
  const CaseRun first = run_builtin(make_case(pyramid, at_origin, frustum, beside));
  const CaseRun second = run_builtin(make_case(frustum, beside, pyramid, at_origin));
  ASSERT_NEAR(first.manifold.penetration, -0.9, kExact);
  ASSERT_NEAR(second.manifold.penetration, -0.9, kExact);
  EXPECT_VEC_NEAR(to_vec(first.manifold.normal), Vec3(0, 0, -1), kExact);
  std::vector<Expected> swapped;
  for (int i = 0; i < second.manifold.contact_count; ++i) {
    const mfz_contact& c = second.manifold.contacts[i];
    swapped.push_back({to_vec(c.point_on_b), to_vec(c.point_on_a), c.penetration});
  }
  expect_contacts(first.manifold, swapped);
  // The squares' overlap, 0.7 by 0.8, and points of the sloping sides.
  EXPECT_GT(first.manifold.contact_count, 4);
  expect_all_invariants_hold(first);
  expect_all_invariants_hold(second);
}

// A sliver face of A 2e14 long, parallel to a face of B, whose hull reaches
// 2.8e17 from A: an edge of each spans the face's normal, and its overlap is
// the face's to the rounding of the vertices, about 60 in any projection.
// Turned and shifted 2e17, the pair came out 16 shallower than the face, past
// a margin taken of the projections (1.2e9), and its one point replaced the
// sliver's three contacts 2e14 apart (F38, rigid-motion).
TEST(ClippingGenerator, AFaceWinsAnEdgePairInItsPlaneByTheRoundingOfTheVerticesNotOfTheirProjections) {
  const CaseParse parsed = read_case_file(
      test::corpus_path("regressions/f38-an-edge-pair-in-a-slivers-face-beat-the-face-by-rounding-2e17-out.case"));
  ASSERT_TRUE(parsed.value) << parsed.error;
  const Scene s = *make_scene(*parsed.value).scene;
  const Quat turn(0.9004471023526769, 0.11624942883566838, 0.23249885767133677, 0.3487482865070052);
  const Vec3 shift(196000000673400000, -84000000288600000, 56000000192400000);
  const auto moved = [&](const Pose& p) { return Pose{turn * p.position + shift, (turn * p.orientation).normalized()}; };
  mfz_manifold m{};
  ASSERT_EQ(generate_clipping_manifold(s.hull_a.view(), moved(s.pose_a).to_abi(), s.hull_b.view(),
                                       moved(s.pose_b).to_abi(), m),
            0);
  double span = 0;
  for (int i = 0; i < m.contact_count; ++i)
    for (int j = 0; j < i; ++j)
      span = std::max(span, (to_vec(m.contacts[i].point_on_a) - to_vec(m.contacts[j].point_on_a)).norm());
  EXPECT_EQ(m.contact_count, 3);
  EXPECT_GT(span, 1e14) << "the contacts lie together: an edge pair's point, not the sliver's face";
}

// F41: a needle 0.5 long lies on the top face of a slab 5e-4 thick. An
// edge pair 4.6e-12 rad off the face normal comes out 9e-13 shallower than
// the face; F3's bias is a fraction of the hulls' size, so the face wins
// and its clip gives the needle's two points on the face, not the pair's
// one point at the face's edge.
TEST(ClippingGenerator, AFaceWinsAnEdgePairByTheBiasOfTheHullsSizeNotOfTheirThicknessAlongIt) {
  const CaseParse parsed = read_case_file(test::corpus_path(
      "regressions/f41-a-needle-on-a-slab-5e-4-thick-took-an-edge-axis-tilted-4-6e-12-from-its-face.case"));
  ASSERT_TRUE(parsed.value) << parsed.error;
  const Scene s = *make_scene(*parsed.value).scene;
  const mfz_hull a = s.hull_a.view(), b = s.hull_b.view();
  const PosedHull posed_a(a, s.pose_a), posed_b(b, s.pose_b);
  const SatResult sat = run_sat(posed_a, posed_b);
  EXPECT_EQ(sat.kind, AxisKind::face_a);
  mfz_manifold m{};
  ASSERT_EQ(generate_clipping_manifold(a, s.abi_pose_a(), b, s.abi_pose_b(), m), 0);
  ASSERT_EQ(m.contact_count, 2);
  EXPECT_GT((to_vec(m.contacts[0].point_on_a) - to_vec(m.contacts[1].point_on_a)).norm(), 0.29);
}

}  // namespace
}  // namespace mfz

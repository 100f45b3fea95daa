// The bounds of m . v over an edge arc that let SAT drop whole rows of edge
// pairs: checked against the arc sampled densely, kArcBoundMargin past its
// ends included. A bound claimed where a sample breaks it would drop a row
// that holds the axis; one refused where the arc clears it by far is a row
// kept for nothing.
#include <gtest/gtest.h>

#include "generator/arc_bounds.h"
#include "geometry/hull.h"
#include "test_support.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace mfz {
namespace {

// The least of m . v over unit m on the arc from p to q, and `past` radians
// beyond each end, sampled.
double least_on_arc(const Vec3& p, const Vec3& q, const Vec3& v, double past) {
  const Vec3 circle = p.cross(q);
  if (circle.norm() == 0) return p.dot(v);
  const Vec3 onward = circle.cross(p).normalized();  // p's tangent towards q
  const double angle = std::atan2(circle.norm(), p.dot(q));
  constexpr int kSamples = 400;
  double least = std::numeric_limits<double>::infinity();
  for (int s = 0; s <= kSamples; ++s) {
    const double phi = -past + (angle + 2 * past) * s / kSamples;
    least = std::min(least, (std::cos(phi) * p + std::sin(phi) * onward).dot(v));
  }
  return least;
}

// A box with a point raised 1e-7 above its top's centre: the four faces
// round it meet at dihedral angles near zero, arcs too short to have an
// inside (held by a margin past their ends).
std::vector<Vec3> box_with_a_flat_peak() {
  std::vector<Vec3> points = test::box_points(1, 1, 1);
  points.push_back(Vec3(0.1, 0.2, 1 + 1e-7));
  return points;
}

// A wedge whose edge at y = 0 is a knife: its two faces' normals nearly
// opposite, an arc almost a half circle with a vanishing sine, which no
// margin of its ends holds.
std::vector<Vec3> knife_wedge() {
  std::vector<Vec3> points;
  for (const double x : {-1.0, 1.0})
    for (const Vec3& p : {Vec3(x, 0, 0), Vec3(x, 1, 1e-4), Vec3(x, 1, -1e-4)}) points.push_back(p);
  return points;
}

struct Tally {
  long claimed = 0, refused = 0, refused_though_clear = 0, short_arcs = 0;
};

// For random centres, shared vectors and floors: every claimed bound holds
// on every sample, and every bound the samples clear by 5% of |v|_1 (far
// more than the margin's and the sampling's slack) is claimed.
void check_bounds(const PosedHull& posed, std::mt19937& random, Tally& tally) {
  const EdgeArcs arcs(posed);
  ASSERT_TRUE(arcs.complete());
  std::normal_distribution<double> gauss;
  std::uniform_real_distribution<double> unit(-1, 1);
  const auto vector = [&] { return Vec3(gauss(random), gauss(random), gauss(random)); };
  for (int trial = 0; trial < 20; ++trial) {
    const Vec3 centre = 2 * vector(), shared = vector();
    const double vertex_floor = 1.5 * unit(random), shared_floor = 1.5 * unit(random);
    double margin[kMaxArcs];
    arcs_above(arcs, centre, vertex_floor, shared, shared_floor, margin);
    for (int i = 0; i < arcs.size(); ++i) {
      const EdgeArc& arc = arcs[i];
      const Vec3 to_vertex = posed.world_vertex(arc.v0) - centre;
      const double least_vertex = least_on_arc(arc.n_face, arc.n_twin, to_vertex, kArcBoundMargin);
      const double least_shared = least_on_arc(arc.n_face, arc.n_twin, shared, kArcBoundMargin);
      tally.short_arcs += arc.n_face.cross(arc.n_twin).norm() < kArcBoundMargin;
      if (margin[i] > 0) {
        ++tally.claimed;
        EXPECT_GT(least_vertex, vertex_floor) << "arc " << i << " claimed above the vertex floor";
        EXPECT_GT(least_shared, shared_floor) << "arc " << i << " claimed above the shared floor";
        continue;
      }
      ++tally.refused;
      // A knife edge's arc (a sine too small to place the circle, ends
      // nearly opposite) is refused whatever it clears: too near to tell.
      const bool knife = arc.n_face.cross(arc.n_twin).norm() < kArcBoundMargin && arc.n_face.dot(arc.n_twin) < 0;
      const bool clear = !knife && least_vertex > vertex_floor + 0.05 * to_vertex.lpNorm<1>() &&
                         least_shared > shared_floor + 0.05 * shared.lpNorm<1>();
      tally.refused_though_clear += clear;
      EXPECT_FALSE(clear) << "arc " << i << " clears both floors by far, yet was refused";
    }
  }
}

TEST(ArcBounds, ClaimABoundOnlyWhereEverySampleOfTheArcClearsIt) {
  std::vector<std::vector<Vec3>> shapes = {test::box_points(1, 0.5, 0.25), box_with_a_flat_peak(), knife_wedge()};
  for (const int points : {8, 32, 128}) shapes.push_back(test::sphere_points(points, 13u * points));
  std::mt19937 random(20261124);
  std::normal_distribution<double> gauss;
  Tally tally;
  for (const auto& points : shapes) {
    const Hull hull = *build_hull(points).hull;
    const mfz_hull view = hull.view();
    for (int turn = 0; turn < 4; ++turn) {
      const Vec3 axis(gauss(random), gauss(random), gauss(random));
      const Pose pose{Vec3(gauss(random), gauss(random), gauss(random)), test::about(axis.normalized(), turn * 0.9)};
      check_bounds(PosedHull(view, pose), random, tally);
    }
  }
  // Both answers are given often, and the short arcs are reached.
  EXPECT_GT(tally.claimed, 1000);
  EXPECT_GT(tally.refused, 1000);
  EXPECT_GT(tally.short_arcs, 0);
}

// The knife's arc runs from (0, -e, 1) through (0, -1, 0) to (0, -e, -1):
// along v = (0, 1, 0) both ends give -e, above a floor of -0.5, and the
// arc's middle gives -1, below it.
TEST(ArcBounds, AKnifeEdgesArcIsNotTakenForItsEnds) {
  const Hull wedge = *build_hull(knife_wedge()).hull;
  const mfz_hull view = wedge.view();
  const Pose pose{Vec3::Zero(), Quat::Identity()};
  const PosedHull posed(view, pose);
  const EdgeArcs arcs(posed);
  ASSERT_TRUE(arcs.complete());
  double margin[kMaxArcs];
  arcs_above(arcs, Vec3::Zero(), -1e9, Vec3(0, 1, 0), -0.5, margin);
  int knives = 0;
  for (int i = 0; i < arcs.size(); ++i) {
    if (!(arcs[i].n_face.dot(arcs[i].n_twin) < -0.99)) continue;
    ++knives;
    EXPECT_LT(least_on_arc(arcs[i].n_face, arcs[i].n_twin, Vec3(0, 1, 0), 0), -0.99);
    EXPECT_FALSE(margin[i] > 0) << "the knife's arc was taken for its ends";
  }
  EXPECT_EQ(knives, 1);
}

}  // namespace
}  // namespace mfz

// Parallelepipeds (boxes, sheared or not) take SAT's short edge phase: one
// axis per pair of edge directions. Which hulls are parallelepipeds, and
// that the nine axes find what every edge pair finds.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "generator/sat.h"
#include "geometry/hull.h"
#include "geometry/hull_topology.h"
#include "geometry/parallelepiped.h"
#include "test_support.h"

namespace mfz {
namespace {

// The box's corners through a shear: x += sx y, y += sy z.
std::vector<Vec3> sheared_box_points(double hx, double hy, double hz, double sx, double sy) {
  std::vector<Vec3> points = test::box_points(hx, hy, hz);
  for (Vec3& p : points) p = Vec3(p.x() + sx * p.y(), p.y() + sy * p.z(), p.z());
  return points;
}

bool parallelepiped(const Hull& hull) {
  const mfz_hull view = hull.view();
  const Pose pose{Vec3(1, 2, 3), test::about(Vec3(1, 1, 0).normalized(), 0.7)};
  return is_parallelepiped(PosedHull(view, pose));
}

TEST(Parallelepiped, BoxesAndShearedBoxesAre) {
  EXPECT_TRUE(parallelepiped(*build_hull(test::box_points(1, 2, 3)).hull));
  EXPECT_TRUE(parallelepiped(*build_hull(test::box_points(1e-3, 5, 1e3)).hull));
  EXPECT_TRUE(parallelepiped(*build_hull(sheared_box_points(1, 1, 1, 0.4, -0.7)).hull));
}

// A unit box's corners, loops and normals, to be put together again with
// changes (Hull::from_faces, no validation).
struct BoxParts {
  std::vector<Vec3> vertices;
  std::vector<std::vector<int>> loops;
  std::vector<Vec3> normals;
  Hull box = *build_hull(test::box_points(1, 1, 1)).hull;
  BoxParts() {
    for (int i = 0; i < box.vertex_count(); ++i) vertices.push_back(box.vertex(i));
  }
  /// The box's own six loops and normals.
  void take_own_loops() {
    for (int f = 0; f < box.face_count(); ++f) {
      loops.emplace_back();
      for (int k = 0; k < box.face_size(f); ++k) loops.back().push_back(box.face_vertex(f, k));
      normals.push_back(box.face_normal(f));
    }
  }
};

TEST(Parallelepiped, ACubesLoopsWithACornerMovedAreNot) {
  // The box's own loops and normals, one corner pulled out by 1e-6: the
  // loops are still a cube's, the edges of two zones no longer parallel.
  BoxParts parts;
  parts.take_own_loops();
  EXPECT_TRUE(parallelepiped(Hull::from_faces(parts.vertices, parts.loops, parts.normals)));
  parts.vertices[0] *= 1 + 1e-6;
  EXPECT_FALSE(parallelepiped(Hull::from_faces(parts.vertices, parts.loops, parts.normals)));
}

TEST(Parallelepiped, BoxesTooThinOrTooLargeToMeasureAreNot) {
  // A box of zero height has no volume; one 1e200 across overflows the
  // measure, and takes the general path rather than a verdict of infinity.
  BoxParts parts;
  parts.take_own_loops();
  std::vector<Vec3> flat = parts.vertices, huge = parts.vertices;
  for (Vec3& p : flat) p.z() = 0;
  for (Vec3& p : huge) p *= 1e200;
  EXPECT_FALSE(parallelepiped(Hull::from_faces(flat, parts.loops, parts.normals)));
  EXPECT_FALSE(parallelepiped(Hull::from_faces(huge, parts.loops, parts.normals)));
  EXPECT_TRUE(parallelepiped(Hull::from_faces(parts.vertices, parts.loops, parts.normals)));
}

TEST(Parallelepiped, OtherLoopsAreNot) {
  // A triangulated box: its loops are not a cube's (twelve triangles).
  BoxParts parts;
  const Hull& box = parts.box;
  for (int f = 0; f < box.face_count(); ++f)
    for (int k = 1; k + 1 < box.face_size(f); ++k) {
      parts.loops.push_back({box.face_vertex(f, 0), box.face_vertex(f, k), box.face_vertex(f, k + 1)});
      parts.normals.push_back(box.face_normal(f));
    }
  EXPECT_FALSE(parallelepiped(Hull::from_faces(parts.vertices, parts.loops, parts.normals)));
  // Eight points that are no box: a hull of other loops.
  EXPECT_FALSE(parallelepiped(*build_hull(test::sphere_points(8, 3)).hull));
  EXPECT_FALSE(parallelepiped(*build_hull(test::tetrahedron_points()).hull));
}

// The verdicts are remembered per hull, found by the address of its
// vertices: a caller that moves a corner in place between two calls gets
// the verdict of the new corners, not the one remembered.
TEST(Parallelepiped, AVerdictIsWorkedOutAgainWhenTheVerticesChangeInPlace) {
  const Hull box = *build_hull(test::box_points(1, 2, 3)).hull;
  std::vector<mfz_vec3> corners(box.view().vertices, box.view().vertices + box.vertex_count());
  mfz_hull view = box.view();
  view.vertices = corners.data();
  const Pose pose{Vec3(1, 2, 3), test::about(Vec3(1, 1, 0).normalized(), 0.7)};
  const auto verdicts = [&] {
    const PosedHull hull(view, pose);
    return std::make_pair(is_parallelepiped(hull), is_box(hull));
  };
  EXPECT_EQ(verdicts(), std::make_pair(true, true));
  // Sheared in place: still a parallelepiped, no longer a box.
  for (mfz_vec3& p : corners) p.x += 0.3 * p.z;
  EXPECT_EQ(verdicts(), std::make_pair(true, false));
  // A corner pulled out by 1e-6: neither.
  corners[0].x *= 1 + 1e-6;
  EXPECT_EQ(verdicts(), std::make_pair(false, false));
  corners.assign(box.view().vertices, box.view().vertices + box.vertex_count());
  EXPECT_EQ(verdicts(), std::make_pair(true, true));
}

Vec3 random_direction(std::mt19937& random) {
  std::normal_distribution<double> gauss;
  return Vec3(gauss(random), gauss(random), gauss(random)).normalized();
}

// The edge of `hull` that SAT named lies along the edge every pair named
// and supports the hull along `direction` (to the hull's rounding).
void expect_supporting_edge(const PosedHull& hull, int named, int every, const Vec3& direction, double scale) {
  const HullTopology& topology = *hull.topology();
  const TopologyEdge &x = topology.edge(named), &y = topology.edge(every);
  const Vec3 along_x = hull.world_vertex(x.v1) - hull.world_vertex(x.v0);
  const Vec3 along_y = hull.world_vertex(y.v1) - hull.world_vertex(y.v0);
  EXPECT_NEAR(along_x.normalized().cross(along_y.normalized()).norm(), 0.0, 1e-12);
  double top = -INFINITY;
  for (int i = 0; i < hull.vertex_count(); ++i) top = std::max(top, direction.dot(hull.world_vertex(i)));
  EXPECT_NEAR(direction.dot(hull.world_vertex(x.v0)), top, 1e-12 * scale);
  EXPECT_NEAR(direction.dot(hull.world_vertex(x.v1)), top, 1e-12 * scale);
}

// Pairs of boxes and sheared boxes of random proportions, resting face to
// face, tilted, crossed edge to edge and deep: the depth, the kind of axis
// and the separation every edge pair gives; an edge axis parallel to its
// own, named by edges that support it.
TEST(SatPruning, ParallelepipedsFindTheAxisEveryPairFindsWithOneAxisPerPairOfDirections) {
  std::mt19937 random(20261124);
  std::uniform_real_distribution<double> unit(0, 1);
  int overlapping = 0, edge_axes = 0;
  for (int trial = 0; trial < 600; ++trial) {
    const auto size = [&] { return 0.2 + 2 * unit(random); };
    const bool shear = trial % 3 == 2;
    const auto points = [&] {
      return shear ? sheared_box_points(size(), size(), size(), unit(random) - 0.5, unit(random) - 0.5)
                   : test::box_points(size(), size(), size());
    };
    const Hull a = *build_hull(points()).hull, b = *build_hull(points()).hull;
    const mfz_hull va = a.view(), vb = b.view();
    // Every fourth pair rests face to face, nearly aligned; the rest turn
    // freely.
    const bool resting = trial % 4 == 0;
    const Pose pa{Vec3::Zero(), resting ? test::about(random_direction(random), 0.02 * unit(random))
                                        : test::about(random_direction(random), 3 * unit(random))};
    const Vec3 offset = random_direction(random) * (0.3 + 2.5 * unit(random));
    const Pose pb{offset, resting ? test::about(random_direction(random), 0.02 * unit(random))
                                  : test::about(random_direction(random), 3 * unit(random))};
    const PosedHull posed_a(va, pa), posed_b(vb, pb);
    ASSERT_TRUE(is_parallelepiped(posed_a) && is_parallelepiped(posed_b)) << "trial " << trial;
    const SatResult zones = run_sat(posed_a, posed_b), every = run_sat_every_pair(posed_a, posed_b);
    ASSERT_EQ(zones.separated, every.separated) << "trial " << trial;
    if (every.separated) continue;
    ++overlapping;
    const double scale = std::max(a.diameter(), b.diameter()) + offset.norm();
    EXPECT_EQ(zones.kind, every.kind) << "trial " << trial;
    EXPECT_NEAR(zones.depth, every.depth, 1e-12 * scale) << "trial " << trial;
    EXPECT_NEAR(zones.normal.dot(every.normal), 1.0, 1e-12) << "trial " << trial;
    if (zones.kind != AxisKind::edge_edge || every.kind != AxisKind::edge_edge) continue;
    ++edge_axes;
    expect_supporting_edge(posed_a, zones.feature_a, every.feature_a, zones.normal, scale);
    expect_supporting_edge(posed_b, zones.feature_b, every.feature_b, -zones.normal, scale);
  }
  EXPECT_GT(overlapping, 300);
  EXPECT_GT(edge_axes, 40) << "edge axes should win some of the pairs";
}

}  // namespace
}  // namespace mfz

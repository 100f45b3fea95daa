// EdgePairBatch (generator/edge_pair_batch.h): SAT measures a pair with a
// chance on the batch's own projections, so they must be the ones the
// pair's full measure would make, to the bit.
#include "generator/edge_pair_batch.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include "test_support.h"

namespace mfz {
namespace {

bool same_bits(double x, double y) { return std::memcmp(&x, &y, sizeof x) == 0; }

// Edge pairs of two turned clouds, far from the origin so that rounding
// shows: each pair's axis is the cross product of two edges, as SAT adds it.
TEST(EdgePairBatch, APairIsProjectedOntoItsUnitAxisToTheBitsOfProject) {
  const Hull a = *build_hull(test::sphere_points(32, 7)).hull;
  const Hull b = *build_hull(test::sphere_points(40, 8)).hull;
  const mfz_hull view_a = a.view(), view_b = b.view();
  const Pose pose_a{Vec3(1e5, -3e4, 7), test::about(Vec3(1, 2, 3).normalized(), 0.7)};
  const Pose pose_b{Vec3(1e5 + 0.3, -3e4, 7.2), test::about(Vec3(-2, 1, 0.5).normalized(), 2.1)};
  const PosedHull posed_a(view_a, pose_a), posed_b(view_b, pose_b);
  std::mt19937 random(20261128);
  std::uniform_int_distribution<int> vertex_a(0, posed_a.vertex_count() - 1), vertex_b(0, posed_b.vertex_count() - 1);
  EdgePairBatch batch;
  std::vector<Vec3> axes;
  while (batch.has_room_for(1)) {
    const Vec3 edge_a = posed_a.world_vertex(vertex_a(random)) - posed_a.world_vertex(vertex_a(random));
    const Vec3 edge_b = posed_b.world_vertex(vertex_b(random)) - posed_b.world_vertex(vertex_b(random));
    axes.push_back(edge_a.cross(edge_b));
    batch.add(static_cast<int>(axes.size()) - 1, 0, axes.back());
  }
  batch.project(posed_a, posed_b);
  int spanning = 0;
  for (int k = 0; k < batch.size(); ++k) {
    const double length = axes[k].norm();
    ASSERT_TRUE(same_bits(batch.axis_length(k), length)) << "pair " << k;
    if (!(length > 0)) {
      EXPECT_EQ(batch.least_overlap(k), -std::numeric_limits<double>::infinity()) << "pair " << k;
      continue;
    }
    ++spanning;
    const Vec3 unit = axes[k] / length;
    const Interval ia = posed_a.project(unit), ib = posed_b.project(unit);
    ASSERT_TRUE(same_bits(batch.projection_a(k).min, ia.min) && same_bits(batch.projection_a(k).max, ia.max))
        << "pair " << k;
    ASSERT_TRUE(same_bits(batch.projection_b(k).min, ib.min) && same_bits(batch.projection_b(k).max, ib.max))
        << "pair " << k;
    EXPECT_TRUE(same_bits(batch.least_overlap(k), std::min(ia.max - ib.min, ib.max - ia.min))) << "pair " << k;
  }
  EXPECT_GT(spanning, EdgePairBatch::kCapacity / 2);
}

}  // namespace
}  // namespace mfz

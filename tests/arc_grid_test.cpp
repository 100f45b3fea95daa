// The grid on the Gauss sphere offers each arc of A every arc of B that
// crosses it, in ascending order, and far fewer than all; the climb on a
// hull's vertices ends at a furthest vertex.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "generator/arc_grid.h"
#include "geometry/hull.h"
#include "test_support.h"

namespace mfz {
namespace {

Hull cloud_hull(int points, unsigned seed) { return *build_hull(test::sphere_points(points, seed)).hull; }

Quat turn(unsigned seed) {
  std::mt19937 random(seed);
  std::normal_distribution<double> gauss;
  return Quat(Eigen::AngleAxisd(gauss(random), Vec3(gauss(random), gauss(random), gauss(random)).normalized()));
}

TEST(ArcGrid, OffersEveryPairTheGaussMapTestKeepsAndFewOthers) {
  long offered = 0, all = 0, slack_only = 0;
  // Fine cells (B has 128 points) against A's arcs long and short (8 and
  // 128 points): a long arc bulges out of its ends' box by 0.13 at 60 deg.
  for (unsigned seed = 1; seed <= 40; ++seed) {
    const Hull a = cloud_hull(seed % 2 ? 8 : 128, seed), b = cloud_hull(128, 100 + seed);
    const mfz_hull va = a.view(), vb = b.view();
    const Pose pa{Vec3::Zero(), turn(seed)}, pb{Vec3(0.5, 0.2, 0.1), turn(200 + seed)};
    const PosedHull posed_a(va, pa), posed_b(vb, pb);
    const EdgeArcs arcs_a(posed_a), arcs_b(posed_b);
    ASSERT_TRUE(arcs_a.complete() && arcs_b.complete());
    const ArcGrid grid(arcs_b);
    int near[kMaxArcs];
    for (int i = 0; i < arcs_a.size(); ++i) {
      const int count = grid.candidates(arcs_a[i], near);
      ASSERT_TRUE(std::is_sorted(near, near + count));
      ASSERT_EQ(std::adjacent_find(near, near + count), near + count) << "an arc offered twice";
      for (int j = 0; j < arcs_b.size(); ++j) {
        if (!may_span_minkowski_face(arcs_a[i], arcs_b[j]) || std::binary_search(near, near + count, j)) continue;
        // Left out, though the test keeps it: only a pair that the test's
        // slack lets through without its arcs crossing (near each other's
        // antipodes, or an end on the other's great circle but off its
        // arc). Arcs that cross, by the test without slack, are offered.
        const EdgeArc &x = arcs_a[i], &y = arcs_b[j];
        const double cba = -y.n_face.dot(x.across), dba = -y.n_twin.dot(x.across);
        const double adc = x.n_face.dot(y.across), bdc = x.n_twin.dot(y.across);
        ASSERT_FALSE(cba * dba < 0 && adc * bdc < 0 && cba * bdc > 0)
            << "seed " << seed << ": crossing arcs " << i << " and " << j << " not offered";
        ++slack_only;
      }
      offered += count;
      all += arcs_b.size();
    }
  }
  EXPECT_LT(slack_only * 100, offered);
  EXPECT_LT(offered * 5, all) << "the grid should offer under a fifth of the pairs";
}

TEST(ClimbToSupport, EndsAtAFurthestVertexFromAnyStart) {
  const Hull hull = cloud_hull(128, 7);
  const mfz_hull view = hull.view();
  const Pose pose{Vec3(1, 2, 3), turn(7)};
  const PosedHull posed(view, pose);
  std::mt19937 random(11);
  std::normal_distribution<double> gauss;
  for (int k = 0; k < 200; ++k) {
    const Vec3 d = Vec3(gauss(random), gauss(random), gauss(random)).normalized();
    const int start = k % hull.vertex_count();
    const int climbed = posed.climb_to_support(d, start);
    double furthest = -1e300;
    for (int i = 0; i < hull.vertex_count(); ++i) furthest = std::max(furthest, d.dot(posed.world_vertex(i)));
    EXPECT_EQ(d.dot(posed.world_vertex(climbed)), furthest) << "direction " << k << " from vertex " << start;
  }
}

}  // namespace
}  // namespace mfz

// A row's edge pairs bounded in vector lanes (generator/pair_bounds.h):
// each pair's verdict is the one SAT's bound of a single pair gives with
// the same vertices and threshold, to the bit, thresholds set at the bounds
// themselves and one ulp either side included.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "generator/pair_bounds.h"

namespace mfz {
namespace {

// SAT's single bound of a pair before it climbs (sat.cpp's
// pair_is_hopeless), as it is written there with Vec3: against m the
// balls' bound and the last climbs' ends' bound, then along m the edges'
// bound. None where the edges are parallel (no axis).
std::vector<double> bounds_of(const RowOfPairs& row, const Vec3& b0, const Vec3& edge_b) {
  const Vec3 axis = row.edge_a.cross(edge_b);
  const double length = axis.norm();
  if (!(length > 0)) return {};
  const Vec3 m = (axis.dot(row.out_of_a) >= 0 ? axis : Vec3(-axis)) / length;
  return {m.dot(row.centres) + row.inner_a + row.inner_b, m.dot(row.back_b) - m.dot(row.back_a),
          m.dot(row.vertex_a) - m.dot(b0)};
}

// Hopeless when a bound against m and the bound along m both pass the
// threshold.
bool single_pair_hopeless(const RowOfPairs& row, const Vec3& b0, const Vec3& edge_b) {
  const std::vector<double> bound = bounds_of(row, b0, edge_b);
  if (bound.empty()) return false;
  return (bound[0] > row.threshold || bound[1] > row.threshold) && bound[2] > row.threshold;
}

struct Pairs {
  std::vector<double> b0_x, b0_y, b0_z, edge_x, edge_y, edge_z;
  std::vector<Vec3> b0, edge;
  explicit Pairs(int count) {
    for (auto* column : {&b0_x, &b0_y, &b0_z, &edge_x, &edge_y, &edge_z}) column->assign(count + 4, 0.0);
  }
  void set(int k, const Vec3& first, const Vec3& along) {
    b0.push_back(first), edge.push_back(along);
    b0_x[k] = first.x(), b0_y[k] = first.y(), b0_z[k] = first.z();
    edge_x[k] = along.x(), edge_y[k] = along.y(), edge_z[k] = along.z();
  }
  PairColumns columns() const {
    return {b0_x.data(), b0_y.data(), b0_z.data(), edge_x.data(), edge_y.data(), edge_z.data()};
  }
};

TEST(PairBounds, APairIsHopelessInLanesExactlyWhereTheSingleBoundSaysSo) {
  std::mt19937 random(20261129);
  std::normal_distribution<double> gauss;
  const auto vector = [&] { return Vec3(gauss(random), gauss(random), gauss(random)); };
  long hopeless = 0, left = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const int count = 1 + trial % 23;  // whole fours and tails of one to three
    RowOfPairs row;
    row.edge_a = vector(), row.vertex_a = vector(), row.out_of_a = vector(), row.centres = vector();
    row.inner_a = std::abs(gauss(random)), row.inner_b = std::abs(gauss(random));
    row.back_a = vector(), row.back_b = vector();
    Pairs pairs(count);
    for (int k = 0; k < count; ++k) {
      // Every seventh pair's edge parallel to A's: no axis, never hopeless.
      const Vec3 along = k % 7 == 3 ? Vec3(-2.5 * row.edge_a) : vector();
      pairs.set(k, vector(), along);
    }
    // The threshold at one of the bounds of a pair, or an ulp either side.
    const std::vector<double> at = bounds_of(row, pairs.b0[0], pairs.edge[0]);
    const double chosen = at.empty() ? 0.0 : at[trial % 3];
    row.threshold = trial % 5 == 0 ? chosen
                    : trial % 5 == 1 ? std::nextafter(chosen, -INFINITY)
                    : trial % 5 == 2 ? std::nextafter(chosen, INFINITY)
                                     : gauss(random);
    std::vector<int64_t> flags(count + 4, -1);
    bound_pairs_in_lanes(row, pairs.columns(), count, flags.data());
    for (int k = 0; k < count; ++k) {
      const bool expected = single_pair_hopeless(row, pairs.b0[k], pairs.edge[k]);
      ASSERT_EQ(flags[k], expected ? 1 : 0) << "trial " << trial << " pair " << k;
      hopeless += expected, left += !expected;
    }
  }
  EXPECT_GT(hopeless, 2000);
  EXPECT_GT(left, 2000);
}

}  // namespace
}  // namespace mfz

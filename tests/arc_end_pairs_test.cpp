// Edge pairs whose axis lies along a face normal at an arc's end
// (generator/arc_end_pairs.h): a row's pairs told in vector lanes are left
// out exactly where the single test leaves them out, on pairs that meet at
// an end to within a few times the test's sine, either side of it.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "generator/arc_end_pairs.h"
#include "geometry/tolerances.h"

namespace mfz {
namespace {

struct Arcs {
  std::vector<double> face_x, face_y, face_z, twin_x, twin_y, twin_z, across_x, across_y, across_z, edge_x, edge_y,
      edge_z;
  std::vector<EdgeArc> arc;
  std::vector<Vec3> edge;
  explicit Arcs(int count) {
    for (auto* column : {&face_x, &face_y, &face_z, &twin_x, &twin_y, &twin_z, &across_x, &across_y, &across_z,
                         &edge_x, &edge_y, &edge_z})
      column->assign(count + 4, 0.0);
  }
  void set(int k, const EdgeArc& y, const Vec3& along) {
    arc.push_back(y), edge.push_back(along);
    face_x[k] = y.n_face.x(), face_y[k] = y.n_face.y(), face_z[k] = y.n_face.z();
    twin_x[k] = y.n_twin.x(), twin_y[k] = y.n_twin.y(), twin_z[k] = y.n_twin.z();
    across_x[k] = y.across.x(), across_y[k] = y.across.y(), across_z[k] = y.across.z();
    edge_x[k] = along.x(), edge_y[k] = along.y(), edge_z[k] = along.z();
  }
  ArcEndColumns columns() const {
    return {face_x.data(), face_y.data(), face_z.data(), twin_x.data(), twin_y.data(), twin_z.data(),
            across_x.data(), across_y.data(), across_z.data(), edge_x.data(), edge_y.data(), edge_z.data()};
  }
};

EdgeArc arc_between(const Vec3& n_face, const Vec3& n_twin) {
  return {0, 1, 0, 1, n_face, n_twin, n_twin.cross(n_face)};
}

TEST(ArcEndPairs, ARowInLanesLeavesOutExactlyThePairsTheSingleTestLeavesOut) {
  std::mt19937 random(20261207);
  std::normal_distribution<double> gauss;
  std::uniform_real_distribution<double> unit(0, 1);
  const auto direction = [&] { return Vec3(gauss(random), gauss(random), gauss(random)).normalized(); };
  // Turned by `angle` about a random axis square to it.
  const auto tilted = [&](const Vec3& n, double angle) {
    const Vec3 about = n.cross(direction()).normalized();
    return Vec3(Eigen::AngleAxisd(angle, about) * n);
  };
  const double sine = tol::kAxisAlongFaceSine;
  long along = 0, across = 0, along_tilted = 0;
  for (int trial = 0; trial < 1500; ++trial) {
    const int count = 1 + trial % 23;  // whole fours and tails of one to three
    const EdgeArc x = arc_between(direction(), direction());
    // A's edge along its arc's circle pole, as a hull's edge lies, or off it.
    const Vec3 edge_a = (trial % 4 == 0 ? direction() : Vec3(x.across.normalized())) * (0.1 + 3 * unit(random));
    Arcs b(count);
    for (int k = 0; k < count; ++k) {
      // Most of B's arcs end within a few sines of -A's end (or of its other
      // end, or of its twin), so that both stages fall either side of their
      // bounds; the rest anywhere.
      const int kind = static_cast<int>(unit(random) * 5);
      const Vec3 end = kind == 0 ? Vec3(-x.n_face) : kind == 1 ? Vec3(-x.n_twin) : kind == 2 ? x.n_face : direction();
      const Vec3 n_face = kind == 4 ? direction() : tilted(end, 4 * sine * unit(random));
      const EdgeArc y = kind == 3 ? arc_between(direction(), tilted(x.n_face, 4 * sine * unit(random)))
                                  : arc_between(n_face, direction());
      // B's edge along its own pole, as a hull's lies, now and then parallel to A's.
      const Vec3 edge_b = k % 9 == 4 ? Vec3(-1.5 * edge_a) : Vec3(y.across.normalized() * (0.1 + 3 * unit(random)));
      b.set(k, y, edge_b);
    }
    std::vector<int64_t> flags(count + 4, -1);
    axes_along_arc_ends_in_lanes(x, edge_a, b.columns(), count, flags.data());
    for (int k = 0; k < count; ++k) {
      const bool expected = axis_along_arc_end(edge_a.cross(b.edge[k]), x, b.arc[k]);
      ASSERT_EQ(flags[k], expected ? 1 : 0) << "trial " << trial << " pair " << k;
      along += expected, across += !expected;
      along_tilted += expected && k % 9 != 4;
    }
  }
  EXPECT_GT(along, 2000);
  EXPECT_GT(across, 2000);
  EXPECT_GT(along_tilted, 1000) << "pairs along an end but not parallel";
}

}  // namespace
}  // namespace mfz

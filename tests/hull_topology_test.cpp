// A hull's topology, worked out once and kept per thread: each edge meets
// its two faces, each vertex its neighbours; equal loops share one entry,
// and loops that do not close into a polyhedron get none.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>

#include "geometry/hull.h"
#include "geometry/hull_topology.h"
#include "test_support.h"

namespace mfz {
namespace {

Hull box(double hx, double hy, double hz) { return *build_hull(test::box_points(hx, hy, hz)).hull; }

Hull random_hull(int points, unsigned seed) { return *build_hull(test::sphere_points(points, seed)).hull; }

TEST(HullTopology, EveryEdgeOfABoxMeetsTheFacesEitherSide) {
  const Hull hull = box(1, 1, 1);
  const mfz_hull view = hull.view();
  const HullTopology* topology = topology_of(view);
  ASSERT_NE(topology, nullptr);
  ASSERT_EQ(topology->edge_count(), 12);
  for (int e = 0; e < topology->edge_count(); ++e) {
    const TopologyEdge& edge = topology->edge(e);
    EXPECT_LT(edge.v0, edge.v1);
    // The face holds the step v0 -> v1, its twin the step v1 -> v0.
    const auto has_step = [&](int f, int from, int to) {
      for (int k = 0; k < hull.face_size(f); ++k)
        if (hull.face_vertex(f, k) == from && hull.face_vertex(f, (k + 1) % hull.face_size(f)) == to) return true;
      return false;
    };
    EXPECT_TRUE(has_step(edge.face, edge.v0, edge.v1));
    EXPECT_TRUE(has_step(edge.twin, edge.v1, edge.v0));
  }
}

TEST(HullTopology, TheFaceAcrossEachLoopStepIsItsTwinsFace) {
  const Hull hull = box(2, 1, 0.5);
  const HullTopology* topology = topology_of(hull.view());
  ASSERT_NE(topology, nullptr);
  for (int f = 0; f < hull.face_count(); ++f)
    for (int k = 0; k < hull.face_size(f); ++k) {
      const int g = topology->face_across_step(f, k);
      ASSERT_GE(g, 0);
      EXPECT_NE(g, f);
      // Across a box's edge the faces are perpendicular.
      EXPECT_NEAR(hull.face_normal(f).dot(hull.face_normal(g)), 0.0, 1e-12);
    }
}

TEST(HullTopology, EachCornerOfABoxHasItsThreeNeighbours) {
  const Hull hull = box(1, 2, 3);
  const HullTopology* topology = topology_of(hull.view());
  ASSERT_NE(topology, nullptr);
  for (int v = 0; v < hull.vertex_count(); ++v) {
    const std::set<int> neighbours(topology->neighbours_begin(v), topology->neighbours_end(v));
    ASSERT_EQ(neighbours.size(), 3u);
    for (int w : neighbours) {
      // Neighbours differ from the corner in exactly one coordinate.
      const Vec3 d = (hull.vertex(w) - hull.vertex(v)).cwiseAbs();
      EXPECT_EQ((d.array() > 1e-12).count(), 1);
    }
  }
}

TEST(HullTopology, EqualLoopsShareOneEntryWhateverTheCoordinates) {
  const Hull small = box(1, 1, 1), large = small.scaled(3), other = box(5, 0.1, 2).renumbered();
  // Scaling keeps the loops: one entry, reached with other coordinates.
  EXPECT_EQ(topology_of(small.view()), topology_of(large.view()));
  EXPECT_NE(topology_of(small.view()), topology_of(other.view()));
}

TEST(HullTopology, AnEvictedHullIsBuiltAgainTheSame) {
  const Hull hull = box(1, 1, 1);
  const HullTopology* first = topology_of(hull.view());
  ASSERT_NE(first, nullptr);
  const int edges = first->edge_count();
  std::vector<Hull> others;
  for (int k = 0; k < 2 * kTopologySlots; ++k)
    others.push_back(random_hull(8 + k, 1000 + k));
  for (const Hull& other : others) ASSERT_NE(topology_of(other.view()), nullptr);
  const HullTopology* again = topology_of(hull.view());
  ASSERT_NE(again, nullptr);
  EXPECT_EQ(again->edge_count(), edges);
}

TEST(HullTopology, LoopsThatDoNotCloseGetNone) {
  const Hull hull = box(1, 1, 1);
  mfz_hull open = hull.view();
  open.face_count -= 1;  // one face missing: its edges have one side
  EXPECT_EQ(topology_of(open), nullptr);
  std::vector<int32_t> twice(open.face_vertices, open.face_vertices + hull.view().face_offsets[hull.face_count()]);
  std::copy(twice.begin(), twice.begin() + 4, twice.begin() + 4);  // face 1 repeats face 0's loop
  mfz_hull repeated = hull.view();
  repeated.face_vertices = twice.data();
  EXPECT_EQ(topology_of(repeated), nullptr);
}

}  // namespace
}  // namespace mfz

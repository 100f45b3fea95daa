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

TEST(HullTopology, ACubesTwelveEdgesFallInThreeZonesOfParallelEdges) {
  const Hull hull = box(3, 2, 1);
  const HullTopology* topology = topology_of(hull.view());
  ASSERT_NE(topology, nullptr);
  ASSERT_TRUE(topology->has_cube_loops());
  std::set<int> seen;
  for (int z = 0; z < 3; ++z) {
    const TopologyEdge& first = topology->edge(topology->zone_edge(z, 0));
    const Vec3 direction = hull.vertex(first.v1) - hull.vertex(first.v0);
    for (int k = 0; k < 4; ++k) {
      const int e = topology->zone_edge(z, k);
      if (k > 0) {
        EXPECT_LT(topology->zone_edge(z, k - 1), e) << "a zone's edges ascend";
      }
      seen.insert(e);
      const TopologyEdge& edge = topology->edge(e);
      EXPECT_EQ(direction.cross(hull.vertex(edge.v1) - hull.vertex(edge.v0)).norm(), 0.0) << "zone " << z;
    }
  }
  EXPECT_EQ(seen.size(), 12u) << "each edge in one zone";
  EXPECT_LT(topology->zone_edge(0, 0), topology->zone_edge(1, 0));
  EXPECT_LT(topology->zone_edge(1, 0), topology->zone_edge(2, 0));
}

TEST(HullTopology, OnlyACubesLoopsHaveZones) {
  for (unsigned seed = 1; seed <= 20; ++seed) {
    const Hull hull = random_hull(8, seed);
    const HullTopology* topology = topology_of(hull.view());
    ASSERT_NE(topology, nullptr);
    // Eight points in general position make twelve triangles.
    EXPECT_FALSE(topology->has_cube_loops()) << "seed " << seed;
  }
  // A triangular prism with one corner cut off: eight corners of three
  // edges and six faces like a cube, but two triangles, two quadrilaterals
  // and two pentagons.
  const Hull cut = *build_hull({Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 0), Vec3(1, 0, 1), Vec3(0, 1, 1),
                                Vec3(0.3, 0, 1), Vec3(0, 0.3, 1), Vec3(0, 0, 0.7)})
                        .hull;
  ASSERT_EQ(cut.vertex_count(), 8);
  ASSERT_EQ(cut.face_count(), 6);
  ASSERT_EQ(cut.edges().size(), 12u);
  const HullTopology* topology = topology_of(cut.view());
  ASSERT_NE(topology, nullptr);
  EXPECT_FALSE(topology->has_cube_loops());
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

// Loops of `base` with every vertex renamed by a permutation: the same faces
// in the same order, so the face across each step is the same, under keys
// the store has never seen.
struct Relabelled {
  std::vector<int32_t> loops;
  mfz_hull view;
};

Relabelled relabelled(const Hull& base, unsigned seed) {
  const mfz_hull v = base.view();
  std::vector<int> name(v.vertex_count);
  for (int i = 0; i < v.vertex_count; ++i) name[i] = i;
  std::shuffle(name.begin(), name.end(), std::mt19937(seed));
  Relabelled r;
  for (int i = 0; i < v.face_offsets[v.face_count]; ++i) r.loops.push_back(name[v.face_vertices[i]]);
  r.view = v;
  r.view.face_vertices = r.loops.data();
  return r;
}

std::vector<int> across_of(const HullTopology& t, const Hull& hull) {
  std::vector<int> out;
  for (int f = 0; f < hull.face_count(); ++f)
    for (int k = 0; k < hull.face_size(f); ++k) out.push_back(t.face_across_step(f, k));
  return out;
}

// Hulls of 128 points, as many as the ring holds, written one after
// another; then looked up two at a time, as a generator call does: one from
// that cycle and one never seen before. Each hull of the cycle is then found
// just where the new one is about to be written. It must still read right
// after the new one was built, all the way round the ring and past its end.
TEST(HullTopology, AHeldTopologyOutlivesTheNextLookupAsTheRingTurns) {
  const Hull base = random_hull(128, 7);
  const HullTopology* first = topology_of(base.view());
  ASSERT_NE(first, nullptr);
  const std::vector<int> expected = across_of(*first, base);
  const int edges = first->edge_count();  // `first` itself is not held past the next lookups
  // An entry's size: a 40-byte header, then offsets, loops, the face across
  // each step, edges, neighbour offsets and neighbours, in 16-byte units.
  const size_t words = (base.face_count() + 1) + 2 * 2 * edges + 4 * edges + (base.vertex_count() + 1) + 2 * edges;
  const size_t entry = (40 + 4 * words + 15) / 16 * 16;
  const int fit = static_cast<int>(kTopologyStoreBytes / entry);
  unsigned fresh = 1u << 30;
  for (const int hulls : {fit - 1, fit, fit + 1}) {
    std::vector<Relabelled> cycle;
    for (int i = 0; i < hulls; ++i) cycle.push_back(relabelled(base, 1000 * hulls + i));
    for (const Relabelled& r : cycle) ASSERT_NE(topology_of(r.view), nullptr);
    for (int round = 0; round < 2; ++round)
      for (int i = 0; i < hulls; ++i) {
        const Relabelled unseen = relabelled(base, ++fresh);
        const HullTopology* a = topology_of(cycle[i].view);
        const HullTopology* b = topology_of(unseen.view);
        ASSERT_NE(a, nullptr);
        ASSERT_NE(b, nullptr);
        ASSERT_EQ(across_of(*a, base), expected) << hulls << " hulls, round " << round << ", hull " << i;
        ASSERT_EQ(a->edge_count(), edges);
        ASSERT_EQ(across_of(*b, base), expected) << hulls << " hulls, round " << round << ", hull " << i;
      }
  }
}

TEST(HullTopology, AHullLookedUpAgainIsFoundNotBuilt) {
  const Hull hull = random_hull(32, 11);
  const HullTopology* once = topology_of(hull.view());
  const Hull other = random_hull(40, 12);
  ASSERT_NE(topology_of(other.view()), nullptr);
  EXPECT_EQ(topology_of(hull.view()), once);
}

// An engine keeps each shape's loops where they are from call to call, and
// so does the benchmark: such a hull is found by where its loops lie,
// without hashing them, even when more than the last two hulls come
// between (the benchmark cycles through 2,048 a family; with the last two
// alone, every 8-point hull was hashed on every call, and 40% of the
// boxes' lookups, whose loops come in seven orders, were hashed).
TEST(HullTopology, AHullWhoseLoopsStayWhereTheyLieIsFoundWithoutHashing) {
  std::vector<Hull> hulls;
  for (unsigned seed = 0; seed < 16; ++seed) hulls.push_back(random_hull(32, 100 + seed));
  std::vector<const HullTopology*> first;
  for (const Hull& hull : hulls) first.push_back(topology_of(hull.view()));
  const uint64_t hashed = topology_lookups_hashed();
  for (int round = 0; round < 3; ++round)
    for (size_t i = 0; i < hulls.size(); ++i) ASSERT_EQ(topology_of(hulls[i].view()), first[i]);
  EXPECT_EQ(topology_lookups_hashed(), hashed);
}

// Whether each edge of `t` is a step of the loops `view` holds now, from v0
// to v1 in its face.
bool edges_follow_loops(const HullTopology& t, const mfz_hull& view) {
  for (int e = 0; e < t.edge_count(); ++e) {
    const TopologyEdge& edge = t.edge(e);
    const int begin = view.face_offsets[edge.face], end = view.face_offsets[edge.face + 1];
    bool found = false;
    for (int k = begin; k < end; ++k)
      found = found || (view.face_vertices[k] == edge.v0 && view.face_vertices[k + 1 < end ? k + 1 : begin] == edge.v1);
    if (!found) return false;
  }
  return true;
}

// The address is only where to look: loops rewritten in place are other
// loops, and get their own topology (a caller often builds the next hull
// where the last one lay).
TEST(HullTopology, LoopsRewrittenWhereOthersLayGetTheirOwnTopology) {
  const Hull base = random_hull(32, 21);
  Relabelled r = relabelled(base, 1);
  const HullTopology* before = topology_of(r.view);
  ASSERT_NE(before, nullptr);
  ASSERT_TRUE(edges_follow_loops(*before, r.view));
  const Relabelled other = relabelled(base, 2);
  std::copy(other.loops.begin(), other.loops.end(), r.loops.begin());  // the same address, other loops
  const HullTopology* after = topology_of(r.view);
  ASSERT_NE(after, nullptr);
  EXPECT_NE(after, before);
  EXPECT_TRUE(edges_follow_loops(*after, r.view));
}

// A case file's hull may have 1,024 points. With a topology for 128 at
// most, a larger hull's SAT had no edge arcs and measured every edge pair
// in full: 38.8 ms a call at 129 points, 2.1 s at 512.
TEST(HullTopology, AHullOfAsManyPointsAsACaseFileHoldsGetsItsTopology) {
  for (const int points : {129, 1024}) {
    const Hull hull = random_hull(points, 13);
    ASSERT_EQ(hull.vertex_count(), points);  // points on a sphere are all vertices
    const HullTopology* topology = topology_of(hull.view());
    ASSERT_NE(topology, nullptr) << points << " points";
    // A simplicial polyhedron: 3V - 6 edges, each vertex among its
    // neighbours' neighbours.
    EXPECT_EQ(topology->edge_count(), 3 * points - 6);
    for (int v = 0; v < points; ++v)
      for (const int* w = topology->neighbours_begin(v); w != topology->neighbours_end(v); ++w)
        EXPECT_NE(std::find(topology->neighbours_begin(*w), topology->neighbours_end(*w), v),
                  topology->neighbours_end(*w));
  }
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

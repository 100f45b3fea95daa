#pragma once
/// \file
/// What a hull's face loops say, worked out once per hull instead of once
/// per generator call: its edges in SAT's order with the faces either side,
/// the face across every loop step, each vertex's neighbours, and a cube's
/// edge zones. Loops alone decide it, so the loops are the key, compared in
/// full (never the address: the next hull a caller builds often lands where
/// the last one was freed).
///
/// Where it lives: each thread keeps a store of topologies, a ring of
/// kTopologyStoreBytes reserved on the thread's first generator call (one
/// allocation per thread, never one per call; pages are touched only as the
/// ring fills) with an index by a hash of the loops, and slots by where the
/// loops lie, looked in first (where only to look: the loops are still
/// compared in full). A generator called through the ABI reaches it without
/// allocating and without the caller handing anything over: a plugin's user does nothing, the same loops
/// passed again hit. The ring holds the last few thousand hulls (about 2,000
/// of 128 points, 60,000 of 8, 490 of 1,024), so a scene that cycles through
/// many shapes builds each once, as an engine keeps each shape's data; the
/// relations, the shrinker and the fuzzer's pose mutations call the same
/// hulls again and again, and every box has the same loops.
#include <cstddef>
#include <cstdint>

#include "manifuzz/abi.h"

namespace mfz {

/// Hulls up to this many vertices get a topology; larger ones take the
/// generator's slower path, which works from the loops directly. As many as
/// a case file's hull may have (1,024 points): with 128 here, SAT on a hull
/// of 129 vertices had no edge arcs and measured every edge pair in full,
/// 38.8 ms a call where 128 vertices took 0.14 ms, and 2.1 s at 512.
inline constexpr int kTopologyMaxVertices = 1024;
inline constexpr int kTopologyMaxFaces = 2 * kTopologyMaxVertices - 4;
inline constexpr int kTopologyMaxEdges = 3 * kTopologyMaxVertices - 6;
inline constexpr int kTopologyMaxSteps = 2 * kTopologyMaxEdges;
/// The ring's size, per thread.
inline constexpr size_t kTopologyStoreBytes = size_t{64} << 20;

/// An edge: the loop step v0 -> v1 (v0 < v1) of `face`; `twin` holds v1 -> v0.
struct TopologyEdge {
  int32_t v0, v1, face, twin;
};

/// A topology as the store keeps it: this header, then its arrays.
class HullTopology {
 public:
  /// The edges in SAT's order: faces in order, each loop's steps with v0 < v1.
  int edge_count() const { return edge_count_; }
  const TopologyEdge& edge(int i) const { return edges()[i]; }
  /// The face on the other side of step k -> k+1 of face f's loop.
  int face_across_step(int f, int k) const { return words()[across_at_ + words()[f] + k]; }
  /// The vertices joined to v by an edge.
  const int32_t* neighbours_begin(int v) const { return words() + neighbours_at_ + words()[neighbour_offsets_at_ + v]; }
  const int32_t* neighbours_end(int v) const { return words() + neighbours_at_ + words()[neighbour_offsets_at_ + v + 1]; }

  /// Loops that are a cube's (eight corners of three edges, six four-sided
  /// faces) put the twelve edges in three zones of four: the edges opposite
  /// one another across a face are in one zone. On a parallelepiped a
  /// zone's edges are parallel, so twelve edges give three directions
  /// (geometry/parallelepiped.h checks that). False for other loops.
  bool has_cube_loops() const { return cube_zones_[0][0] >= 0; }
  /// The k-th edge (0-3, ascending) of zone z (0-2, in order of their first
  /// edges); only when has_cube_loops().
  int zone_edge(int z, int k) const { return cube_zones_[z][k]; }
  /// A number no other topology built on this thread has (a topology moved
  /// within the store keeps it): what a memo of a hull's shape keys its
  /// loops by (geometry/parallelepiped.h), since a topology's address may
  /// hold another's once it is evicted.
  uint64_t serial() const { return serial_; }

 private:
  friend class TopologyStore;
  const int32_t* words() const { return reinterpret_cast<const int32_t*>(this + 1); }
  const TopologyEdge* edges() const { return reinterpret_cast<const TopologyEdge*>(words() + edges_at_); }

  int32_t vertex_count_, face_count_, step_count_, edge_count_;
  /// Where each array starts, in words after the header: the face offsets
  /// (at 0) and loops come first, as the hull gave them.
  int32_t loops_at_, across_at_, edges_at_, neighbour_offsets_at_, neighbours_at_, size_words_;
  int32_t cube_zones_[3][4];
  uint64_t serial_;
};

/// The topology of `hull` from this thread's store, built on a miss; nullptr
/// when the hull has more than kTopologyMaxVertices vertices or its loops do
/// not close into a polyhedron. A returned topology stays valid while two
/// other hulls are looked up on the thread (a generator call holds two).
const HullTopology* topology_of(const mfz_hull& hull);

/// How many of this thread's lookups hashed the loops: those neither found
/// where the same loops were last found at their address nor among the
/// last two hulls. For tests.
uint64_t topology_lookups_hashed();

}  // namespace mfz

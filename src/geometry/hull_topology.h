#pragma once
/// \file
/// What a hull's face loops say, worked out once per hull instead of once
/// per generator call: its edges in SAT's order with the faces either side,
/// the face across every loop step, and each vertex's neighbours. Loops alone
/// decide it, so the loops are the key, compared in full (never the address:
/// the next hull a caller builds often lands where the last one was freed).
///
/// Where it lives: each thread keeps the last kTopologySlots topologies in
/// fixed storage of its own, filled on the first call that brings a hull,
/// so a generator called through the ABI reaches them without allocating
/// and without the caller handing anything over. A plugin's user does
/// nothing: the same loops passed again hit. Repeated pairs are the
/// common case (the relations, the shrinker and the fuzzer's pose
/// mutations call the same hulls again and again, and every box has the
/// same loops).
#include <cstdint>

#include "manifuzz/abi.h"

namespace mfz {

/// Hulls up to this many vertices get a topology; larger ones take the
/// generator's slower path, which works from the loops directly.
inline constexpr int kTopologyMaxVertices = 128;
inline constexpr int kTopologyMaxFaces = 2 * kTopologyMaxVertices - 4;
inline constexpr int kTopologyMaxEdges = 3 * kTopologyMaxVertices - 6;
inline constexpr int kTopologyMaxSteps = 2 * kTopologyMaxEdges;
/// Topologies a thread keeps. A returned topology stays valid until this
/// many other hulls have been looked up on the thread; a generator call
/// holds two.
inline constexpr int kTopologySlots = 8;

/// An edge: the loop step v0 -> v1 (v0 < v1) of `face`; `twin` holds v1 -> v0.
struct TopologyEdge {
  int v0, v1, face, twin;
};

class HullTopology {
 public:
  /// The edges in SAT's order: faces in order, each loop's steps with v0 < v1.
  int edge_count() const { return edge_count_; }
  const TopologyEdge& edge(int i) const { return edges_[i]; }
  /// The face on the other side of step k -> k+1 of face f's loop.
  int face_across_step(int f, int k) const { return across_[offsets_[f] + k]; }
  /// The vertices joined to v by an edge.
  const int* neighbours_begin(int v) const { return neighbours_ + neighbour_offsets_[v]; }
  const int* neighbours_end(int v) const { return neighbours_ + neighbour_offsets_[v + 1]; }

 private:
  friend class TopologyCache;
  bool same_loops(const mfz_hull& hull) const;
  /// False when the hull does not fit or an edge is not in two faces once
  /// each way.
  bool build(const mfz_hull& hull);

  int vertex_count_ = -1, face_count_ = -1, step_count_ = 0;
  int32_t offsets_[kTopologyMaxFaces + 1];
  int32_t loops_[kTopologyMaxSteps];
  int across_[kTopologyMaxSteps];
  TopologyEdge edges_[kTopologyMaxEdges];
  int edge_count_ = 0;
  int neighbour_offsets_[kTopologyMaxVertices + 1];
  int neighbours_[kTopologyMaxSteps];
};

/// The topology of `hull` from this thread's cache, built on a miss; nullptr
/// when the hull has more than kTopologyMaxVertices vertices or its loops do
/// not close into a polyhedron.
const HullTopology* topology_of(const mfz_hull& hull);

}  // namespace mfz

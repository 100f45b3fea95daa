#pragma once
/// \file
/// B's edge arcs, negated, binned on a grid of cells over the cube around the
/// Gauss sphere, so that each arc of A meets only the arcs of B that pass
/// near it: the pairs that may_span_minkowski_face would test, without
/// testing all E_A x E_B of them (for hulls of 128 points, 140,000 tests
/// become a few thousand).
///
/// Each arc is boxed conservatively: it lies in the triangle of its ends and
/// the meeting point of the tangents there, and a margin covers the
/// near-crossings may_span_minkowski_face keeps (tol::kGaussArcSlack lets
/// arcs 3e-5 rad apart through; the margin is 30 times that). So every pair
/// whose arcs cross is offered, in the order SAT tried them before (B's arcs
/// ascending). The test's slack also keeps a few pairs whose arcs do not
/// cross (short arcs near each other's antipodes, an end on the other's
/// great circle but off its arc), which the grid leaves out: they span no
/// face of A - B, so their overlap exceeds the depth and they never won
/// (SAT's answer on the benchmark's 7,168 pairs, both orders, is the same
/// to the bit).
#include "generator/edge_arcs.h"

namespace mfz {

/// Below this many pairs the grid costs more than it saves.
inline constexpr int kArcGridMinPairs = 20000;

class ArcGrid {
 public:
  ArcGrid() = default;
  /// Bins the arcs of B, negated (B's Gauss map as A - B sees it).
  explicit ArcGrid(const EdgeArcs& arcs_b) { build(arcs_b); }
  /// The same, into this object (SAT keeps one per thread: 16 KB); an arc
  /// j with `left_out[j]` set is never offered (SAT leaves out the arcs
  /// whose every pair is hopeless).
  void build(const EdgeArcs& arcs_b, const bool* left_out = nullptr);
  /// The arcs of B whose boxes meet the box of A's arc `arc_a`, ascending,
  /// into `out` (room for every arc of B); returns how many.
  int candidates(const EdgeArc& arc_a, int* out) const;
  /// How many arcs were too long to bin: each is offered to every arc of A.
  int unbinned() const { return everywhere_count_; }

 private:
  struct Box {
    int lo[3], hi[3];  ///< cell ranges, inclusive; lo[0] < 0: everywhere
  };
  Box box_of(const Vec3& p, const Vec3& q) const;

  static constexpr int kMaxCellsPerArc = 8;
  static constexpr int kMaxCells = 8 * 8 * 8;
  int resolution_ = 1;  ///< cells per axis
  int arc_count_ = 0;
  int everywhere_[kMaxArcs];  ///< arcs too long to bin
  int everywhere_count_ = 0;
  int cell_start_[kMaxCells + 1];
  int entries_[kMaxArcs * kMaxCellsPerArc];
  mutable int stamp_[kMaxArcs];
  mutable int query_ = 0;
};

}  // namespace mfz

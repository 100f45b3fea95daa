#pragma once
/// \file
/// Edge pairs of two small hulls waiting for their overlap bound: SAT on
/// hulls of up to 64 vertices bounds a pair by its overlap itself (both
/// hulls projected onto the pair's axis), and gathers the pairs the
/// Gauss-map test keeps, row after row, to project them a batch at a time in
/// vector lanes. One pair at a time, a pair's bound (its axis, two
/// projections of eight points, the division) took 347 instructions, and
/// the bounds were 7% of an 8-point fuzz execution (callgrind); batched,
/// an 8-point call takes 5% fewer instructions.
///
/// The batch only moves the projections earlier: SAT then takes its pairs in
/// the order it found them and bounds each against its best axis at that
/// moment, as before, so every answer is the one a pair at a time gives.
/// A pair with a chance is measured on the batch's own projections, made
/// onto the unit axis the full measure uses: measuring projected both hulls
/// again, and on cylinders of 64 vertices, whose rims' pairs all tie with
/// a cap, that was 8% of a grown fuzz corpus's instructions.
#include <cmath>
#include <limits>

#include "geometry/posed_hull.h"

namespace mfz {

/// Each of `count` axes (columns x, y, z) divided by its length, which goes
/// to `length` (where that is zero, the axis bounds nothing and its columns
/// are not read again). The same bits as
/// Vec3's norm() and division, (x * x + y * y) + z * z, in vector lanes:
/// one pair at a time, each waited on its square root and its division,
/// and that wait was a tenth of an 8-point fuzz execution's SAT (perf on
/// fuzz_target_bench).
void normalise_axes(double* x, double* y, double* z, int count, double* length);

/// A batch of at most `Capacity` pairs, on the stack or wherever it lives.
template <int Capacity>
class EdgePairBatchOf {
 public:
  static constexpr int kCapacity = Capacity;

  int size() const { return count_; }
  bool has_room_for(int pairs) const { return count_ + pairs <= kCapacity; }
  void clear() { count_ = 0; }

  /// Arc i of A with arc j of B, whose edges' cross product is `axis`:
  /// made the unit axis `axis / |axis|` by project(), the bits SAT's full
  /// measure of the pair divides out, so that the projections here are the
  /// ones it would make (a zero axis bounds nothing).
  void add(int i, int j, const Vec3& axis) {
    arc_a_[count_] = i, arc_b_[count_] = j;
    axis_x_[count_] = axis.x(), axis_y_[count_] = axis.y(), axis_z_[count_] = axis.z();
    ++count_;
  }
  int arc_a(int k) const { return arc_a_[k]; }
  int arc_b(int k) const { return arc_b_[k]; }

  /// Both hulls projected onto every pair's axis. An empty batch projects
  /// nothing: SAT settles its batch at the end of every edge phase, and a
  /// hull too large to cache its world vertices, which never fills one,
  /// has no columns to read (ASan: a 129-point hull's projection read past
  /// the 128 cached, once such hulls had edge arcs).
  void project(const PosedHull& a, const PosedHull& b) {
    if (count_ == 0) return;
    normalise_axes(axis_x_, axis_y_, axis_z_, count_, length_);
    a.project_onto_axes(axis_x_, axis_y_, axis_z_, count_, min_a_, max_a_);
    b.project_onto_axes(axis_x_, axis_y_, axis_z_, count_, min_b_, max_b_);
  }

  /// Pair k's unit axis, and the length of the cross product it came from
  /// (once projected).
  Vec3 axis(int k) const { return {axis_x_[k], axis_y_[k], axis_z_[k]}; }
  double axis_length(int k) const { return length_[k]; }
  /// A's and B's projections onto pair k's unit axis: project()'s bits.
  Interval projection_a(int k) const { return {min_a_[k], max_a_[k]}; }
  Interval projection_b(int k) const { return {min_b_[k], max_b_[k]}; }

  /// Pair k's overlap, the lesser of its axis's two ways: the overlap the
  /// pair's full measure finds. Minus infinity (bounds nothing) for edges
  /// whose cross product vanishes.
  double least_overlap(int k) const {
    if (!(length_[k] > 0)) return -std::numeric_limits<double>::infinity();
    return std::min(max_a_[k] - min_b_[k], max_b_[k] - min_a_[k]);
  }

 private:
  int count_ = 0;
  int arc_a_[kCapacity], arc_b_[kCapacity];
  double axis_x_[kCapacity], axis_y_[kCapacity], axis_z_[kCapacity];
  double min_a_[kCapacity], max_a_[kCapacity], min_b_[kCapacity], max_b_[kCapacity];
  double length_[kCapacity];
};

/// SAT's batch for small hulls: more than a row of the largest hull's arcs.
using EdgePairBatch = EdgePairBatchOf<512>;

/// The nine pairs of edge directions of two parallelepipeds
/// (geometry/parallelepiped.h), a few hundred bytes on the call's stack.
using ParallelepipedPairs = EdgePairBatchOf<9>;

}  // namespace mfz

#pragma once
/// \file
/// A row's edge pairs on large hulls (one edge of A against each edge of B
/// whose arc may cross its own), bounded all at once in vector lanes by the
/// cheap half of SAT's bound of a single pair: each pair's unit axis m,
/// pointing out of A through A's edge; against m, the balls inside the
/// hulls about their centres, or the vertices where the last climbs ended;
/// along m, the two edges. A pair is hopeless when one bound against m and
/// the one along m both pass the threshold. The rest are bounded one at a
/// time, as before, climbing where these bounds do not tell.
///
/// Every bound here is the one SAT takes for a single pair, in the same
/// operations in the same order, so that a pair found hopeless here would
/// be found hopeless there with the same vertices; those vertices and the
/// threshold are the row's at its start, where SAT's single bound reads
/// them as they are at the pair, after the climbs of the pairs before it.
/// Any vertex bounds the overlap and the threshold only falls, so a pair
/// hopeless here is hopeless there too.
#include <cstdint>

#include "geometry/vec.h"

namespace mfz {

/// What a row's pairs share.
struct RowOfPairs {
  Vec3 edge_a;         ///< A's edge, v1 - v0 in world space
  Vec3 vertex_a;       ///< its first vertex
  Vec3 out_of_a;       ///< that vertex less A's centre: m points this way
  Vec3 centres;        ///< B's centre less A's
  double inner_a = 0;  ///< the radius of A's ball
  double inner_b = 0;  ///< and of B's
  Vec3 back_a;         ///< where the last climb on A against m ended
  Vec3 back_b;         ///< and on B along m
  double threshold = 0;  ///< a lower bound past this is hopeless
};

/// B's edges of a row's pairs as columns: first vertices and edge vectors
/// (v1 - v0), world space, padded with zeros to a whole four.
struct PairColumns {
  const double *b0_x, *b0_y, *b0_z;
  const double *edge_x, *edge_y, *edge_z;
};

/// hopeless[k] is 1 where pair k is hopeless by the bounds above, 0 where
/// they do not tell (and where the edges are parallel), for k below
/// `count` rounded up to a whole four.
void bound_pairs_in_lanes(const RowOfPairs& row, const PairColumns& b, int count, int64_t* hopeless);

}  // namespace mfz

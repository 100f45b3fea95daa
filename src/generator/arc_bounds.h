#pragma once
/// \file
/// Lower bounds of a linear function over each of a hull's edge arcs, for
/// every arc at once in vector lanes. SAT uses them to drop a whole row of
/// edge pairs (an edge of A against every edge of B) before looking for its
/// pairs: every pair in A's row has its axis m on A's arc, so a bound of
/// m . v over the arc bounds the pair's overlap.
#include "generator/edge_arcs.h"

namespace mfz {

/// How far past its ends an arc's bound looks: a pair's axis lies on its
/// arc where the arcs cross, and the Gauss-map test lets through pairs whose
/// arcs miss by up to 3e-5 rad; this is 30 times that.
inline constexpr double kArcBoundMargin = 1e-3;

/// For every arc i, margin[i] > 0 when m . (v0_i - centre) > vertex_floor
/// and m . shared > shared_floor for every unit vector m on arc i and on
/// kArcBoundMargin past its ends (v0_i is the arc's first vertex, in world
/// space); margin[i] <= 0 (or NaN) when not, or too near to tell. Writes
/// margin[i] for i below lanes_of(arcs.size()): past arcs.size(), of the
/// columns' padding, to be ignored.
void arcs_above(const EdgeArcs& arcs, const Vec3& centre, double vertex_floor, const Vec3& shared,
                double shared_floor, double* margin);

}  // namespace mfz

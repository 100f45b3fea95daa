#pragma once
/// \file
/// Edge pairs whose axis lies along a face normal at an end of either
/// pair's Gauss arc: where the arcs meet at an end, or an end of one lies
/// on the other's circle, the pair spans no face of A - B but that face's
/// own, and SAT drops it before projecting or bounding it (sat.cpp). Two
/// ways to ask: one pair at a time, and a whole row of one edge of A
/// against many edges of B in vector lanes, each lane the same operations
/// in the same order as the single test, so that both drop the same pairs.
#include <cstdint>

#include "generator/edge_arcs.h"

namespace mfz {

/// Whether the pair's axis (A's edge crossed with B's, unnormalised) lies
/// along a face normal at an end of arc x (A's) or arc y (B's), to
/// tol::kAxisAlongFaceSine. A pair of parallel edges, whose axis has no
/// length, is along every end.
bool axis_along_arc_end(const Vec3& axis, const EdgeArc& x, const EdgeArc& y);

/// B's side of a row's pairs as columns: each arc's ends and circle and its
/// edge vector (v1 - v0, world space), padded with zeros to a whole four.
struct ArcEndColumns {
  const double *face_x, *face_y, *face_z;
  const double *twin_x, *twin_y, *twin_z;
  const double *across_x, *across_y, *across_z;
  const double *edge_x, *edge_y, *edge_z;
};

/// along[k] is 1 where axis_along_arc_end holds for A's arc x (edge edge_a)
/// and B's arc k of `b`, 0 where not, for k below `count` rounded up to a
/// whole four.
void axes_along_arc_ends_in_lanes(const EdgeArc& x, const Vec3& edge_a, const ArcEndColumns& b, int count,
                                  int64_t* along);

}  // namespace mfz

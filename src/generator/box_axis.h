#pragma once
/// \file
/// The separating-axis test for two boxes where the geometry decides it
/// clearly: a face axis that beats every other face by more than a tie's
/// slack and every edge pair by more than F3's bias, with an incident face
/// more aligned than any other of its box by more than a tie; or an edge
/// pair that beats every face by more than F3's bias and every other edge
/// pair by more than rounding. Each box is its centre and three edge
/// directions, so an axis's overlap is a sum of three absolute dot products
/// per box, not a projection of eight corners: fifteen axes, no edge arcs,
/// no climbs. Where anything is close, it answers nothing and the bounded
/// SAT (sat.h) and the tie machinery decide as they always did.
///
/// What it answers is what the general path would: the winning face's
/// normal is the hull's own (PosedHull::world_face_normal), its depth the
/// same projections (PosedHull::project) the bounded SAT takes, and the
/// incident face the one the significant-face rules pick when nothing ties;
/// the winning edge pair's normal is the cross product of its zones' first
/// edges that SAT's parallelepiped phase takes, measured on the same
/// projections and named by the same supporting edges
/// (supporting_zone_edge).
#include "generator/sat.h"
#include "geometry/posed_hull.h"

namespace mfz {

/// An axis the geometry decides and, for a face axis, the other box's
/// incident face.
struct BoxAxis {
  SatResult sat;  ///< a face or edge axis, colliding, as run_sat gives it
  int incident_face = -1;  ///< a face axis's: the other hull's face most aligned against the normal
  /// F27's faces add nothing: the other box stands inside the sides of the
  /// prism over the reference face, so no face of it is clipped, and its
  /// corners off the incident face stand above the reference plane, so the
  /// points its faces leave below are the incident face's own corners.
  bool side_faces_add_nothing = false;
};

/// True, with `out`, when a and b are boxes (parallelepipeds whose three
/// edge directions are square to tol::kBoxSquareness, in their own frames), they collide deeper
/// than rounding, and the winning axis (and a face axis's incident face)
/// clear every rival by the margins above. False, `out` untouched, otherwise.
bool clear_box_axis(const PosedHull& a, const PosedHull& b, BoxAxis& out);

}  // namespace mfz

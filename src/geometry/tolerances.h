#pragma once
/// \file
/// Every tolerance of the project, in one place. Lengths are relative to the
/// case's scale L (the larger hull diameter, docs/contract.md); the harness turns
/// them into lengths with `CaseScale::length`, which also adds the resolution
/// of the world frame (see below). Unit vectors and angles use dimensionless
/// tolerances.
///
/// Refinement of the contract, and why: a case placed 1e6 L from the origin
/// cannot be represented better than one ulp of its coordinates, so every
/// length tolerance is k * L + kWorldUlps * eps * M, where M is the largest
/// absolute world coordinate of the case. For cases near the origin M <= L and
/// the second term is below 1e-13 L, so the tolerance is the contract's k * L.

#include <cstddef>
#include <limits>

namespace mfz::tol {

/// Resolution of the world frame, in ulps of the largest coordinate: a rigid
/// motion (a rotation of 9 products, a translation) and a dot product over
/// world points each lose a few ulps; 64 covers the chain with room.
inline constexpr double kWorldUlps = 64.0;
/// The world frame's resolution at coordinates of size `magnitude`:
/// kWorldUlps ulps of it.
inline constexpr double world_rounding(double magnitude) {
  return kWorldUlps * std::numeric_limits<double>::epsilon() * magnitude;
}

/// Input limit: a case whose world frame's rounding exceeds this (x L) is
/// refused (7e7 L from the origin): beyond it the tolerances are rounding.
inline constexpr double kFarthestFrame = 1e-6;
/// Input limit: each hull's diameter must be at least this many times the
/// world frame's rounding. A 5e-4 hull at 1e56 from the origin beside an
/// 8e70 one has every vertex at the same double: no hull left to check
/// (manifuzz fuzz on the built-in: a false on-surface of 0.58 L).
inline constexpr double kSmallestHullOverRounding = 1e3;

/// Input limit: each hull's diameter must be at least this. The squared
/// length of a cross product of two edges is a fourth power of them, and it
/// underflows below about 1e-77: two hulls 1e-107 across lost the exact
/// oracle its edge axes, its depth came out 9% more than the overlap along
/// EPA's direction, and the built-in failed depth-within-epa-bounds (h25,
/// manifuzz fuzz on the float variant). At 1e-30 an eighth power stays a
/// normal double, as at the coordinate limit below.
inline constexpr double kSmallestHullDiameter = 1e-30;

/// Input limit: no coordinate of a hull's point or a pose's position may
/// exceed this in magnitude. A generator squares lengths of products of
/// coordinates: the squared length of a cross product of two edges is a
/// fourth power of them, and it overflows past about 1e77. At 1e30 an
/// eighth power of a case the relations moved 1e4 L out and doubled stays
/// finite. (h17, open as O20: a tetrahedron 3e78 long was answered with the
/// normal (0, 0, 0), its edge axis divided by an infinite norm.)
inline constexpr double kLargestCoordinate = 1e30;

/// Under a profile's precision (float), a case whose rounding in that
/// precision (64 of its ulps of M) exceeds this (x L) is outside what the
/// generator promises: 130 L from the origin in float. It is discarded as
/// invalid, and the far-from-origin relation is not run past it.
inline constexpr double kProfileFarthestFrame = 1e-3;

/// |depth| or gap below this (x L) is "touching": either colliding answer passes.
inline constexpr double kTouching = 1e-9;
/// Two SAT axes whose overlaps differ by less than this (x L) tie.
inline constexpr double kTie = 1e-9;
/// on-surface, pair-consistency, within-both-hulls (x L).
inline constexpr double kPoint = 1e-9;
/// Refinement of the contract, and why: a face corner of angle t is the
/// crossing of two side planes t apart, which the world frame resolves only to
/// world_rounding(M) / sin t along the corner's bisector; a point clipped near
/// it is no better placed, in any generator computing in double. on-surface
/// and within-both-hulls add that much for the sharpest face corner of either
/// hull, never more than this (x L). Ordinary hulls (sin t above 1e-3) gain
/// less than 1e-10 L; needles 1e-3 wide and 1.4e4 long gain 1e-7 L. (The
/// second campaign: a point clipped at the tip of such a needle's face,
/// 1.08e-9 L off, at sin t = 1.5e-8; an edge-face contact 9.9e-8 L past the
/// apex of a face at sin t = 9e-9.)
inline constexpr double kSharpCornerCap = 1e-6;
/// Under a profile's precision (float) the cap is this many times that
/// precision's rounding, when larger (7.6e-3 L near the origin in float): a
/// float variant's point at a corner of sine 0.035 lay 7e-5 L off, within
/// its rounding over that sine (docs/profiles.md).
inline constexpr double kSharpCornerProfileCap = 1e3;
/// depth-exact, normal-realises-depth, negative-penetration, has-contacts (x L).
inline constexpr double kDepth = 1e-9;
/// unit-normal: | |n| - 1 | (dimensionless).
inline constexpr double kUnitNormal = 1e-9;

/// libccd is run on the case rescaled to L = 1 with these absolute settings.
inline constexpr double kCcdEpaTolerance = 1e-8;
inline constexpr double kCcdMprTolerance = 1e-8;
inline constexpr double kCcdDistTolerance = 1e-10;
/// Bound on libccd's iterations: its default is unbounded and GJK has been seen
/// to spin forever on fuzz input (docs/contract.md).
inline constexpr unsigned long kCcdMaxIterations = 500;
/// Bound on the vertices libccd's EPA and MPR portal may add (one support
/// point each): A - B has at most |A| |B| vertices, and past this many an
/// answer is dropped rather than waited for (libccd_oracle.cpp, h14).
inline constexpr size_t kCcdMaxPolytopeVertices = 2048;
/// EPA's answers are only as good as its tolerance; comparisons against EPA
/// use this (x L), two orders above kCcdEpaTolerance for its polytope error.
inline constexpr double kEpa = 1e-6;
/// normal-agrees-with-epa: angle between n and EPA's direction (radians).
inline constexpr double kEpaAngle = 1e-3;
/// separates: how far past (or short of) depth B is moved (x L). The test is
/// made on the exact Minkowski difference, so this only has to exceed kDepth.
inline constexpr double kSeparates = 1e-7;

/// Ties (docs/contract.md): a vertex within this (x L) of a hull's extreme
/// along the normal is part of its support, for the incident-face and
/// supporting-edge ties.
inline constexpr double kSupportWindow = 1e-8;
/// Ties: incident faces whose alignments with the normal (cosines) differ by
/// less than this are equally aligned.
inline constexpr double kIncidentAlignment = 1e-8;

/// spans-contact-region: the contact region is the part of the hulls'
/// intersection that touched first, deeper than this fraction of the depth
/// (B backed off along n by it): "as though the two objects were only
/// touching", as the clipping method infers its manifold. The full
/// intersection mixes in later, shallower parts: an edge lying 2e-3 rad off
/// a face beyond the ridge it crosses (f21), the far end of an edge tilted
/// 1e-4 rad that reaches 98% of the depth while the incident face holds only
/// the near end (seed 20261121, case 384).
inline constexpr double kRegionFirstTouch = 0.99;
/// spans-contact-region: the region's corners are crossings of edges with
/// planes; where they graze at an angle t, rounding moves them by eps M /
/// sin t (a needle's end tilted 1e-3, 1e-7 deep, 1e6 L out: seed 1), so the
/// centroid is compared to within this (x L), as the relations compare points.
inline constexpr double kRegionPoint = 1e-6;
/// spans-contact-region: the region's centroid may lie outside the contacts
/// by this many times the distance it moves between kRegionFirstTouch and
/// half-way to touching, plus kPoint L. A region that grows about a point (a
/// vertex, an edge) with depth drifts by about half its offset and passes; a
/// flat contact's region does not drift, so its contacts must span it. Added
/// to kRegionPoint L.
inline constexpr double kRegionDrift = 4.0;
/// spans-contact-region: two faces of one hull, each within this angle
/// (radians) of facing the other hull, that the region lies against are a
/// face folded under the contact: the clipping method takes one of them as
/// its reference (a cube 1000 times smaller across a fold of 1e-6, seed 4).
inline constexpr double kFoldAngle = 0.05;
/// spans-contact-region: the region's corners count as inside a hull within
/// this (x L) plus the frame's rounding.
inline constexpr double kRegionSlack = 1e-12;
/// spans-contact-region is checked only for a shallow contact, where the
/// intersection is thin along n: the depth at most this fraction of the
/// region's width (a body sunk deep into another has no contact plane).
inline constexpr double kThinRegion = 0.25;

/// Relations: normals of two runs agree within this (dimensionless), plus
/// the world frame's resolution over the shortest edge: an edge-edge normal
/// is a cross product of edges taken from world coordinates.
inline constexpr double kRelationNormal = 1e-6;
/// Relations: contact points of two runs agree within this (x L). Looser than
/// the invariants' 1e-9: where an incident edge grazes a clipping plane at an
/// angle t, rounding moves the crossing point along the edge by about eps M /
/// sin t, and both places are right. Depths stay at kDepth.
inline constexpr double kRelationPoint = 1e-6;

/// Hull building: a point within this (x L) of a plane through three others
/// makes the cloud flat (no positive volume).
inline constexpr double kFlatHull = 1e-9;
/// Hull validation: every vertex below every face plane within this (x L).
inline constexpr double kHullConvexity = 1e-9;

/// Generator: two edges whose cross product is shorter than this fraction of
/// the product of their lengths are parallel; their axis is a face normal's
/// and is skipped (guarded normalisation).
inline constexpr double kParallelEdges = 1e-9;

/// Generator: a hull with a cube's loops is a parallelepiped, and SAT tries
/// one axis per pair of edge directions, when the edges of each zone are
/// parallel to this sine in the hull's own frame (a box's are, exactly) and
/// the three directions are far from coplanar (kZoneSpan). Its axes then
/// differ from the edge pair's own by as little, which moves an overlap by
/// 1e-12 of the hull's size, below every tolerance that compares them.
inline constexpr double kZoneParallelSine = 1e-12;
/// The three directions' triple product, over the product of their lengths.
inline constexpr double kZoneSpan = 1e-3;
/// Generator: two boxes take the box path (generator/box_axis.h) when
/// their edge directions are square to this cosine in their own frames (a
/// box's corners given exactly are square to the bit): then the nine
/// cosines between two boxes' directions are their rotation, and an axis's
/// overlap comes out of them to 1e-12 of the size.
inline constexpr double kBoxSquareness = 1e-12;
/// Generator: the box path's overlaps differ from the bounded SAT's by the
/// zones' parallelism (kZoneParallelSine of the size, summed over six
/// edges) and rounding; a decision closer than this (x the size) is left to
/// the bounded SAT.
inline constexpr double kBoxAxisRounding = 1e-10;
/// Generator: the box path's incident face must be more aligned with the
/// normal than any other face of its box by this (a cosine, 1000 times
/// kTie), or the significant-face rules and their ties decide.
inline constexpr double kBoxIncidentLead = 1e-6;

/// Generator: two faces lie in one plane when the sine of the angle between
/// their normals is at most this (and the normals point the same way). A
/// patch joins faces each this near the face it is reached from (F60), so
/// it bends by at most 1e-11 of its size per face crossed: below
/// on-surface's 1e-9 L unless a hundred faces in a row each turn by the
/// whole sine the same way (1e-8 at the most faces a patch gathers, 1,024,
/// since F61), which no case has shown; a triangulated face's triangles
/// share their normal exactly. A cosine test cannot say this: 1 - cos underflows.
inline constexpr double kCoplanarSine = 1e-11;
/// Generator: another face of the incident hull faces the reference face
/// (F27) when the cosine of their normals is below minus this. A face
/// perpendicular to it to rounding adds only points its neighbours give,
/// and would come and go with the frame (rigid-motion, --strict --seed 102).
inline constexpr double kFacingCosine = 1e-9;
/// Generator: an edge-edge axis replaces the best face axis only when its
/// overlap is smaller by more than this fraction of the hulls' size (their
/// extent along it, or their span where larger: F41), so that a tie (to
/// rounding) keeps the face contact and its polygon.
inline constexpr double kEdgeAxisBias = 1e-9;
/// Generator: the Gauss-map test that prunes edge pairs (edge_arcs.h) drops
/// a pair only when its sign products miss by more than this. They are
/// products of dot products of unit normals, exact to about 1e-15, but a
/// hull's stored normals may sit 1e-12 off its vertices' planes; near such a
/// crossing the edge axis is within that angle of a face axis, which F3
/// prefers anyway.
inline constexpr double kGaussArcSlack = 1e-9;
/// Generator: an edge pair whose axis is within this sine of a face normal
/// at an end of either edge's Gauss arc is that face's axis again, and SAT
/// does not project the hulls onto it (sat.cpp). Tilted this far, an
/// axis's overlap moves by 1e-11 of the hulls' span, a hundredth of
/// kEdgeAxisBias, so the pair could not have beaten the face; it is ten
/// times the 1e-12 a hull's stored normals may sit off its vertices' planes.
inline constexpr double kAxisAlongFaceSine = 1e-11;
/// Generator: the supporting edges of an edge-edge axis make a contact only if
/// their closest points lie along n to within this fraction of the longer
/// edge's length: half of on-surface's 1e-9 L, since the point on B stands
/// off B's edge by that miss (F62).
inline constexpr double kEdgesCross = 5e-10;

}  // namespace mfz::tol

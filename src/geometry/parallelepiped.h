#pragma once
/// \file
/// Whether a posed hull is a parallelepiped (a box, sheared or not): its
/// loops are a cube's and each of its three edge zones runs one way. Then
/// its twelve edges give three directions, and SAT's edge phase against
/// another parallelepiped needs nine axes, one per pair of directions,
/// instead of every pair of edges whose Gauss arcs cross: on a
/// parallelepiped each zone's arcs make a whole great circle, so every pair
/// of directions spans faces of the Minkowski difference, and every edge
/// pair of one pair of directions has the same axis.
///
/// Where the verdicts live: both depend on the hull's own vertices and
/// loops alone, so each thread remembers them for the last few thousand
/// hulls of a cube's loops, in a table allocated on the thread's first
/// such hull and kept with it (no allocation per call), found by the
/// address of the hull's vertices and kept only while the vertices are the
/// same bytes and the loops the same topology (HullTopology::serial). A
/// plugin's user does nothing: the same hull passed again hits, as an
/// engine keeps each shape's data. Worked out, the two tests read the
/// twelve edges of each hull, a tenth of a box pair's call.
#include "geometry/posed_hull.h"

namespace mfz {

/// True when the hull's loops are a cube's (hull_topology.h), each zone's
/// edges are parallel in the hull's own frame to tol::kZoneParallelSine,
/// and the three directions span space (tol::kZoneSpan), so that no edge
/// lies between coplanar faces. Remembered per hull (below).
bool is_parallelepiped(const PosedHull& hull);

/// True when the hull is a parallelepiped whose three edge directions are
/// square to tol::kBoxSquareness in its own frame: a box, whose corners
/// are exact there. Remembered per hull (below).
bool is_box(const PosedHull& hull);

/// The world vector of zone `zone`'s first edge (from its v0 to its v1):
/// the direction SAT's parallelepiped phase crosses with the other hull's,
/// and the box path too, so that both take the same bits. Inline: a call
/// into this file per zone cost a box pair 2% more instructions.
inline Vec3 zone_direction(const PosedHull& hull, int zone) {
  const HullTopology& topology = *hull.topology();
  const TopologyEdge& e = topology.edge(topology.zone_edge(zone, 0));
  return hull.world_vertex(e.v1) - hull.world_vertex(e.v0);
}

/// The edge of a parallelepiped's zone `zone` that supports it along
/// `direction`: of the zone's four parallel edges, the one furthest along
/// it (the first of equals). SAT names an edge axis of two parallelepipeds
/// by these, and so does the box path.
int supporting_zone_edge(const PosedHull& hull, int zone, const Vec3& direction);

}  // namespace mfz

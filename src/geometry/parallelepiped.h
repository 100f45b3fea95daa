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
#include "geometry/posed_hull.h"

namespace mfz {

/// True when the hull's loops are a cube's (hull_topology.h), each zone's
/// edges are parallel in the hull's own frame to tol::kZoneParallelSine,
/// and the three directions span space (tol::kZoneSpan), so that no edge
/// lies between coplanar faces. Reads the twelve edges: a few dozen
/// flops, asked once per call.
bool is_parallelepiped(const PosedHull& hull);

/// The edge of a parallelepiped's zone `zone` that supports it along
/// `direction`: of the zone's four parallel edges, the one furthest along
/// it (the first of equals). SAT names an edge axis of two parallelepipeds
/// by these, and so does the box path.
int supporting_zone_edge(const PosedHull& hull, int zone, const Vec3& direction);

}  // namespace mfz

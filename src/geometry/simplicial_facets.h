#pragma once
/// \file
/// The facets of a cloud's hull in general position, without Qhull: the
/// hull grown a point at a time (the beneath-beyond step), every facet a
/// triangle with every other point clearly below its plane. Qhull spends
/// about 14 us of set-up on every call, whatever the cloud (it draws a
/// thousand random numbers to test its generator, reads the process's CPU
/// clock by a system call, prints its options into a string): three
/// quarters of an 8-point hull, and no way around it through its API (a
/// reused qhT saves nothing). Past the set-up, its merging and its sets
/// cost more than the hull itself where nothing is to be merged: half a
/// 32-point property case's scene was Qhull.
///
/// It only ever answers where Qhull would give the same facets: a point
/// within kNearPlane of a triangle's plane (a face Qhull would merge, or a
/// point it would call coplanar) makes it decline, and so does a cloud of
/// more than kSimplicialMaxPoints; the caller then asks Qhull. Where it
/// answers, the facets are those of the brute force over every triple of
/// points that it replaced, to the bit, in the same order.
#include <limits>
#include <optional>
#include <vector>

#include "geometry/qhull_facets.h"

namespace mfz {

/// The growing hull tries each point against every triangle, and each
/// final triangle against every point: n^2 steps, and the steps' index is
/// n^2 words.
inline constexpr int kSimplicialMaxPoints = 128;

/// A point within this distance (x the cloud's diameter) of a candidate
/// facet's plane is on it, as far as this builder may tell: the cloud is
/// not in general position and Qhull decides. Far above the rounding of a
/// plane through three points (1e-15), far below any face a case means to
/// have.
inline constexpr double kNearPlane = 1e-9;

/// Far from the origin the band is wider: Qhull merges facets, or calls a
/// point coplanar, within a multiple of its coordinates' rounding, and a
/// unit cloud 1e10 from the origin gave 30 in 200 hulls of 100 points other
/// facets than Qhull's with the band at kNearPlane alone. The band is at
/// least this times the largest coordinate's magnitude: 1e4 ulps, well
/// below kNearPlane x diameter for a cloud about the origin (where the
/// brute force's answers stay the same to the bit), far above the
/// thresholds Qhull derives from its rounding.
inline constexpr double kCoordinateRounding = 1e4 * std::numeric_limits<double>::epsilon();

/// The hull's facets: triangles, vertices counter-clockwise seen from
/// outside, outward unit normals, offsets through their first vertex. Facets
/// come in the order of their vertices' indices. nullopt where the cloud has
/// fewer than four or more than kSimplicialMaxPoints points, or a point within
/// kNearPlane of a candidate facet's plane. Whether the triangles close is
/// the caller's to check (validate_hull).
std::optional<std::vector<QhullFacet>> simplicial_facets(const std::vector<Vec3>& points);

}  // namespace mfz

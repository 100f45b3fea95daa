#pragma once
/// \file
/// The one place that talks to Qhull (reentrant API, libqhull_r). Callers get
/// plain facets; Qhull's state never escapes, so two threads may build hulls.
#include <string>
#include <vector>

#include "geometry/vec.h"

namespace mfz {

/// A facet of a 3-d convex hull: the plane `normal . x = offset` with the
/// outward unit normal, and the indices of its vertices into the input points
/// (unordered).
struct QhullFacet {
  Vec3 normal;
  double offset = 0;
  std::vector<int> point_ids;
};

/// Facets of the convex hull of `points`, or an empty vector and a one-line
/// reason in `error` when Qhull refuses (flat or too few points).
/// `triangulate` asks for simplicial output ("Qt"); otherwise coplanar facets
/// are merged (Qhull's default pre-merging, "C-0").
std::vector<QhullFacet> qhull_facets(const std::vector<Vec3>& points, bool triangulate,
                                     std::string& error);

}  // namespace mfz

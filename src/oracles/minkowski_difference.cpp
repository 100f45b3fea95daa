#include "oracles/minkowski_difference.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/qhull_facets.h"

namespace mfz {

std::optional<MinkowskiDifference> MinkowskiDifference::build(const std::vector<Vec3>& world_a,
                                                              const std::vector<Vec3>& world_b, std::string& error) {
  std::vector<Vec3> differences;
  differences.reserve(world_a.size() * world_b.size());
  for (const Vec3& a : world_a)
    for (const Vec3& b : world_b) differences.push_back(a - b);
  const std::vector<QhullFacet> facets = qhull_facets(differences, /*triangulate=*/false, error);
  if (facets.empty()) return std::nullopt;
  MinkowskiDifference md;
  for (const QhullFacet& f : facets) {
    // The offset through a vertex of the facet, not Qhull's own: a merged
    // facet's plane is an average, and a vertex is a true point of A - B.
    MinkowskiFacet out{f.normal.normalized(), -std::numeric_limits<double>::infinity()};
    for (const int id : f.point_ids) out.offset = std::max(out.offset, out.normal.dot(differences[id]));
    md.facets_.push_back(out);
  }
  return md;
}

double MinkowskiDifference::depth_of(const Vec3& t) const {
  double depth = std::numeric_limits<double>::infinity();
  for (const MinkowskiFacet& f : facets_) depth = std::min(depth, f.offset - f.normal.dot(t));
  return depth;
}

ExactDepth MinkowskiDifference::at_origin() const {
  ExactDepth answer;
  double nearest = std::numeric_limits<double>::infinity();
  for (const MinkowskiFacet& f : facets_)
    if (f.offset < nearest) nearest = f.offset, answer.normal = f.normal;
  answer.colliding = nearest >= 0;
  if (answer.colliding) {
    answer.signed_depth = nearest;
    return answer;
  }
  // Outside: the plane the origin lies furthest outside of, a lower bound on
  // the gap; hull_gap measures the gap itself.
  double furthest = -std::numeric_limits<double>::infinity();
  for (const MinkowskiFacet& f : facets_)
    if (-f.offset > furthest) furthest = -f.offset, answer.normal = -f.normal;
  answer.signed_depth = -furthest;
  return answer;
}

}  // namespace mfz

#include "oracles/minkowski_difference.h"

#include <cmath>
#include <limits>

#include "closest_point.h"
#include "qhull_facets.h"

namespace mfz {

std::optional<MinkowskiDifference> MinkowskiDifference::build(const std::vector<Vec3>& world_a,
                                                              const std::vector<Vec3>& world_b, std::string& error) {
  std::vector<Vec3> differences;
  differences.reserve(world_a.size() * world_b.size());
  for (const Vec3& a : world_a)
    for (const Vec3& b : world_b) differences.push_back(a - b);
  const std::vector<QhullFacet> facets = qhull_facets(differences, /*triangulate=*/true, error);
  if (facets.empty()) return std::nullopt;
  MinkowskiDifference md;
  for (const QhullFacet& f : facets) {
    if (f.point_ids.size() != 3) continue;  // "Qt" gives triangles only
    MinkowskiFacet out{f.normal.normalized(), 0, {}};
    for (int k = 0; k < 3; ++k) out.corner[k] = differences[f.point_ids[k]];
    out.offset = out.normal.dot(out.corner[0]);
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
  if (nearest >= 0) {
    answer.colliding = true;
    answer.signed_depth = nearest;
    return answer;
  }
  // Outside: the gap is the distance to the nearest boundary triangle, over
  // all of them: at a touching case rounding puts the origin a hair outside a
  // facet whose triangle is far away, while the facet it touches says inside.
  double gap_sq = std::numeric_limits<double>::infinity();
  for (const MinkowskiFacet& f : facets_) {
    const Vec3 c = closest_on_triangle(Vec3::Zero(), f.corner[0], f.corner[1], f.corner[2]);
    if (c.squaredNorm() < gap_sq) gap_sq = c.squaredNorm(), answer.normal = -c.normalized();
  }
  answer.signed_depth = -std::sqrt(gap_sq);
  return answer;
}

}  // namespace mfz

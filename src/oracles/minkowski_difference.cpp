#include "oracles/minkowski_difference.h"

#include <cmath>
#include <limits>

#include "qhull_facets.h"

namespace mfz {
namespace {

// Closest point to p on triangle (a, b, c): Ericson, Real-Time Collision
// Detection, 5.1.5, by Voronoi regions.
Vec3 closest_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + (d1 / (d1 - d3)) * ab;
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + (d2 / (d2 - d6)) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  const double denom = va + vb + vc;
  if (denom == 0) return a;  // a sliver: any corner is as close as rounding allows
  return a + ab * (vb / denom) + ac * (vc / denom);
}

}  // namespace

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
  // Outside: the gap is the distance to the nearest facet the origin sees.
  double gap_sq = std::numeric_limits<double>::infinity();
  for (const MinkowskiFacet& f : facets_) {
    if (f.offset >= 0) continue;
    const Vec3 c = closest_on_triangle(Vec3::Zero(), f.corner[0], f.corner[1], f.corner[2]);
    if (c.squaredNorm() < gap_sq) gap_sq = c.squaredNorm(), answer.normal = -c.normalized();
  }
  answer.signed_depth = -std::sqrt(gap_sq);
  return answer;
}

}  // namespace mfz

#include "geometry/closest_point.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/loop_corners.h"

namespace mfz {

Vec3 closest_on_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double length_sq = ab.squaredNorm();
  if (length_sq == 0) return a;
  double t = (p - a).dot(ab) / length_sq;
  t = t < 0 ? 0 : (t > 1 ? 1 : t);
  return a + t * ab;
}

namespace {

Vec3 closest_on_edges(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  Vec3 best = closest_on_segment(p, a, b);
  for (const Vec3& q : {closest_on_segment(p, b, c), closest_on_segment(p, c, a)})
    if ((q - p).squaredNorm() < (best - p).squaredNorm()) best = q;
  return best;
}

}  // namespace

Vec3 closest_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  if (ab.cross(ac).squaredNorm() == 0) return closest_on_edges(p, a, b, c);
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
  if (denom == 0) return closest_on_edges(p, a, b, c);
  return a + ab * (vb / denom) + ac * (vc / denom);
}

void closest_between_segments(const Vec3& p1, const Vec3& q1, const Vec3& p2, const Vec3& q2, Vec3& on_1, Vec3& on_2) {
  const Vec3 d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
  const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
  const auto clamp01 = [](double t) { return t < 0 ? 0.0 : (t > 1 ? 1.0 : t); };
  double s = 0, t = 0;
  if (a == 0 && e == 0) {
    on_1 = p1, on_2 = p2;
    return;
  }
  if (a == 0) {
    t = clamp01(f / e);
  } else {
    const double c = d1.dot(r);
    if (e == 0) {
      s = clamp01(-c / a);
    } else {
      // The lines' closest point on the first, s = (b f - c e) / (a e - b^2),
      // taken through the identity a e - b^2 = |d1 x d2|^2 (and its like for
      // the numerator): the products cancel to a relative eps / sin^2 of the
      // edges' angle, the cross products to eps / sin. Two edges 1e-6 rad
      // apart, 4000 long, crossed 0.15 apart in two frames, though the
      // geometry placed the crossing to 1e-6 (swap-symmetry, manifuzz fuzz,
      // F40). Within rounding of parallel, any s will do: start from p1.
      const double b = d1.dot(d2);
      const Vec3 across = d1.cross(d2);
      const double denominator = across.squaredNorm();
      constexpr double kParallelSine = 64 * std::numeric_limits<double>::epsilon();
      s = denominator > kParallelSine * kParallelSine * a * e ? clamp01(across.dot(d2.cross(r)) / denominator) : 0.0;
      t = (b * s + f) / e;
      if (t < 0) t = 0, s = clamp01(-c / a);
      else if (t > 1) t = 1, s = clamp01((b - c) / a);
    }
  }
  on_1 = p1 + s * d1;
  on_2 = p2 + t * d2;
}

namespace {

// Inlined into both callers: a call between them cost a box pair 0.2%.
[[gnu::always_inline]] inline Vec3 closest_of_projection(const Vec3& p, const Vec3& projected, const Vec3* loop,
                                                         int count, const Vec3& normal) {
  // Counter-clockwise about the normal: inside is to the left of every edge.
  const auto left_of = [&](const Vec3& a, const Vec3& b) { return (b - a).cross(projected - a).dot(normal) >= 0; };
  bool inside = true;
  int failed = -1;  // the edge a point outside fails first
  for (int k = 0; k < count && inside; ++k) inside = left_of(loop[k], loop[next_corner(k, count)]), failed = k;
  // An edge too short for its corners' rounding points anywhere, and a
  // point inside may fall to the right of it: where the edge it fails is
  // that short beside the point's distance, it is tested against the fan
  // of triangles from the first corner, whose other edges are long. A loop
  // of B with corners 1e-9 apart in a face 89,000 across put the foot of
  // A's corner, 2.3e-8 above the face, outside that edge, and the hulls'
  // gap came out 23.5, the foot's distance to the nearest long edge (h33,
  // far-from-origin: the moved run's contact "23.5 apart", manifuzz fuzz
  // --max-points 8, open as O38). Tried for every point outside, the fan
  // cost 64-gon cylinders 1.8%.
  constexpr double kShortEdge = 1e-6;
  const bool short_edge = !inside && count > 3 &&
                          (loop[next_corner(failed, count)] - loop[failed]).squaredNorm() <=
                              kShortEdge * kShortEdge * (projected - loop[failed]).squaredNorm();
  for (int k = 1; short_edge && !inside && k + 1 < count; ++k)
    inside = left_of(loop[0], loop[k]) && left_of(loop[k], loop[k + 1]) && left_of(loop[k + 1], loop[0]);
  if (inside) return projected;
  Vec3 best = loop[0];
  double best_sq = std::numeric_limits<double>::infinity();
  for (int k = 0; k < count; ++k) {
    const Vec3 c = closest_on_segment(p, loop[k], loop[next_corner(k, count)]);
    const double d = (c - p).squaredNorm();
    if (d < best_sq) best_sq = d, best = c;
  }
  return best;
}

}  // namespace

Vec3 closest_point_on_polygon(const Vec3& p, const Vec3* loop, int count, const Vec3& normal) {
  return closest_of_projection(p, p - normal.dot(p - loop[0]) * normal, loop, count, normal);
}

// Edge k's inside value at a projection q, (b - a) x (q - a) . n, is its
// value at the centre c plus (b - a) x (q - c) . n, which is at least
// -|b - a| |q - c| |n|: so a q nearer c than every edge's value at c over
// |b - a| has every value positive. Each value rounds by a few ulps of
// |b - a| times the loop's reach about c, the loop's floats being what they
// are (each difference rounds relative to itself); 1e-9 of the reach is a
// millionfold room for that and for |n| differing from 1.
PolygonCore polygon_core(const Vec3* loop, int count, const Vec3& normal) {
  PolygonCore core;
  if (count < 3) return core;
  Vec3 sum = Vec3::Zero();
  for (int k = 0; k < count; ++k) sum += loop[k];
  const Vec3 centre = sum / static_cast<double>(count);
  double nearest = std::numeric_limits<double>::infinity(), reach = 0;
  for (int k = 0; k < count; ++k) {
    const Vec3& a = loop[k];
    const Vec3 edge = loop[next_corner(k, count)] - a;
    reach = std::max(reach, (a - centre).norm());
    const double length = edge.norm();
    if (!(length > 0)) continue;  // a repeated corner: its value is 0, which passes
    nearest = std::min(nearest, edge.cross(centre - a).dot(normal) / length);
  }
  if (!std::isfinite(nearest)) return core;
  core.centre = centre;
  core.radius = nearest - 1e-9 * reach;
  return core;
}

Vec3 closest_point_on_polygon(const Vec3& p, const Vec3* loop, int count, const Vec3& normal, const PolygonCore& core) {
  const Vec3 projected = p - normal.dot(p - loop[0]) * normal;
  if (core.radius > 0 && (projected - core.centre).norm() < core.radius) return projected;
  return closest_of_projection(p, projected, loop, count, normal);
}

}  // namespace mfz

#include "oracles/contact_region.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "geometry/hull_distance.h"
#include "geometry/tolerances.h"

namespace mfz {
namespace {

using Vec2 = Eigen::Vector2d;

struct Planes {
  std::vector<Vec3> normals;
  std::vector<double> offsets;
};

Planes world_planes(const Hull& hull, const Pose& pose, const Vec3& shift) {
  Planes planes;
  planes.normals.reserve(static_cast<size_t>(hull.face_count()));
  planes.offsets.reserve(static_cast<size_t>(hull.face_count()));
  for (int f = 0; f < hull.face_count(); ++f) {
    const Vec3 normal = pose.rotate(hull.face_normal(f));
    planes.normals.push_back(normal);
    planes.offsets.push_back(normal.dot(pose.to_world(hull.vertex(hull.face_vertex(f, 0))) + shift));
  }
  return planes;
}

// The other hull of add_corners, posed and shifted as its planes are.
struct Solid {
  const Hull& hull;
  const Pose& pose;
  Vec3 shift;
  const Planes& planes;
  // Within `slack` of every plane (but `on_plane`, which p lies on) and of
  // the hull itself. The planes alone let a knife edge reach on: two faces
  // t apart at the edge admit points slack / t beyond it (a sheet whose
  // sides meet at 1.3e-8 rad took a point 4.9 past its edge into the
  // region, and the built-in's contacts were held to it: h10, manifuzz
  // fuzz). Inside every plane by more than the slack, p is inside the hull:
  // the distance is asked only of a point within the slack of a plane,
  // where the planes' heights may be rounding (3.1e5 L out, taking "inside
  // every plane" as inside let the sheet's point in again).
  bool holds(const Vec3& p, double slack, size_t on_plane = SIZE_MAX) const {
    double outside = -INFINITY;
    for (size_t f = 0; f < planes.normals.size(); ++f) {
      if (f == on_plane) continue;
      outside = std::max(outside, planes.normals[f].dot(p) - planes.offsets[f]);
      if (outside > slack) return false;
    }
    return admits(p, outside, slack);
  }
  // The same, for a point `outside` its farthest plane.
  bool admits(const Vec3& p, double outside, double slack) const {
    return outside <= -slack || (outside <= slack && signed_distance(hull, pose, p - shift) <= slack);
  }
};

// The corners of the intersection of two convex hulls lie among: each hull's
// vertices inside the other, and each edge of one crossing a face plane of
// the other at a point inside the other. Such a point is in its own hull,
// being on its edge: held to its own hull's planes as well, it was refused
// by a face 15,000 long and 0.03 wide at one end, whose plane, through its
// first corner, stood 2.3e-8 off one of its edges 90 from that end (past
// the slack, 2e-8); the first-touching region near a corner of a sliver
// tetrahedron lost that corner, its centroid moved 52 towards the deepest
// point, and the contact there missed it by 0.00309 L (h30,
// spans-contact-region, manifuzz fuzz --max-points 5 on the built-in, open
// as O34).
//
// Each vertex's height over each plane is taken once and read by its edges
// (taken per edge, twice for every vertex of three edges, this was 7% of a
// fuzz execution).
//
// An edge whose two ends stand beyond one plane of the other hull by more
// than the slack, and more than the rounding of a point between them, is
// beyond that plane all along: every point where it crosses another plane
// fails `holds` there, so it is passed by whole (the same corners to the
// bit on 23,000 regions; the function's instructions fell by a third on
// the fuzz target's 8-point cases).
void add_corners(const Hull& hull, const std::vector<Vec3>& world, const Vec3& shift, const Solid& other, double slack,
                 std::vector<Vec3>& out) {
  const size_t faces = other.planes.normals.size();
  std::vector<double> heights(world.size() * faces);
  double reach = 0;  // the largest coordinate of a point here
  for (size_t v = 0; v < world.size(); ++v) {
    const Vec3 p = world[v] + shift;
    reach = std::max(reach, p.cwiseAbs().maxCoeff());
    double* height = &heights[v * faces];
    double outside = -INFINITY;
    for (size_t f = 0; f < faces; ++f) {
      height[f] = other.planes.normals[f].dot(p) - other.planes.offsets[f];
      outside = std::max(outside, height[f]);
    }
    if (other.admits(p, outside, slack)) out.push_back(p);
  }
  // A point on an edge, and its height over a unit normal's plane, round by
  // a few ulps of its coordinates and of the offset: 1e-12 of them is a
  // thousandfold margin.
  const auto beyond_all_along = [&](const double* height_p, const double* height_q) {
    for (size_t f = 0; f < faces; ++f)
      if (std::min(height_p[f], height_q[f]) > slack + 1e-12 * (reach + std::abs(other.planes.offsets[f])))
        return true;
    return false;
  };
  for (const HullEdge& e : hull.edges()) {
    const Vec3 p = world[e.v0] + shift, q = world[e.v1] + shift;
    const double *height_p = &heights[e.v0 * faces], *height_q = &heights[e.v1 * faces];
    if (beyond_all_along(height_p, height_q)) continue;
    for (size_t f = 0; f < faces; ++f) {
      const double dp = height_p[f], dq = height_q[f];
      if ((dp > 0) == (dq > 0) || dp == dq) continue;
      const Vec3 x = p + (dp / (dp - dq)) * (q - p);
      if (other.holds(x, slack, f)) out.push_back(x);
    }
  }
}

double cross(const Vec2& o, const Vec2& a, const Vec2& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

// Andrew's monotone chain; collinear points dropped.
std::vector<Vec2> monotone_chain(std::vector<Vec2> p) {
  std::sort(p.begin(), p.end(), [](const Vec2& a, const Vec2& b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); });
  p.erase(std::unique(p.begin(), p.end()), p.end());
  if (p.size() < 3) return p;
  std::vector<Vec2> hull(2 * p.size());
  size_t k = 0;
  for (size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p[i]) <= 0) --k;
    hull[k++] = p[i];
  }
  for (size_t i = p.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && cross(hull[k - 2], hull[k - 1], p[i]) <= 0) --k;
    hull[k++] = p[i];
  }
  hull.resize(k - 1);
  return hull;
}

Vec2 area_centroid(const std::vector<Vec2>& poly) {
  if (poly.size() == 1) return poly[0];
  if (poly.size() == 2) return 0.5 * (poly[0] + poly[1]);
  double area = 0;
  Vec2 sum = Vec2::Zero();
  const Vec2& o = poly[0];
  for (size_t i = 1; i + 1 < poly.size(); ++i) {
    const double a = cross(o, poly[i], poly[i + 1]);
    area += a;
    sum += a * ((poly[i] - o) + (poly[i + 1] - o)) / 3;  // about o: far out, the sum keeps its digits
  }
  if (!(area > 0)) {  // collinear to rounding: the middle of the extremes
    Vec2 lo = poly[0], hi = poly[0];
    for (const Vec2& q : poly) lo = lo.cwiseMin(q), hi = hi.cwiseMax(q);
    return 0.5 * (lo + hi);
  }
  return o + sum / area;
}

// Convex polygons p and q (at least three corners each) overlap by more
// than `margin` across every edge of either: they share an area, not only
// an edge where two faces meet.
bool overlap_2d(const std::vector<Vec2>& p, const std::vector<Vec2>& q, double margin) {
  const auto separated_by_an_edge_of = [&](const std::vector<Vec2>& edges) {
    for (size_t i = 0; i < edges.size(); ++i) {
      const Vec2 along = edges[(i + 1) % edges.size()] - edges[i];
      const Vec2 across(-along.y(), along.x());
      const double length = across.norm();
      if (!(length > 0)) continue;
      double p_low = INFINITY, p_high = -INFINITY, q_low = INFINITY, q_high = -INFINITY;
      for (const Vec2& c : p) p_low = std::min(p_low, across.dot(c)), p_high = std::max(p_high, across.dot(c));
      for (const Vec2& c : q) q_low = std::min(q_low, across.dot(c)), q_high = std::max(q_high, across.dot(c));
      if (std::min(p_high - q_low, q_high - p_low) <= margin * length) return true;
    }
    return false;
  };
  return p.size() >= 3 && q.size() >= 3 && !separated_by_an_edge_of(p) && !separated_by_an_edge_of(q);
}

// The faces facing along `d`, within kFoldAngle, that the region lies
// against: some corner lies on the face's plane (a corner inside a convex
// hull and on a face's plane is on that face), or the region's projection
// shares an area with the face's. The second is for a region bounded by
// the other hull alone: a sheet 5e-4 thick lying wholly within the
// first-touching slab, 0.3 deep under a top folded by 1.4e-3 rad, has no
// corner on either half of the fold, and the built-in's contacts under one
// half were held to the whole sheet (h12, manifuzz check --seed 2026112502).
int facing_faces(const Hull& hull, const std::vector<Vec3>& world, const Vec3& shift, const Planes& planes,
                 const std::vector<Vec3>& corners, const std::vector<Vec2>& region, const Vec3& d, const Vec3& u,
                 const Vec3& v, double slack) {
  int count = 0;
  std::vector<Vec2> face;
  for (size_t f = 0; f < planes.normals.size(); ++f) {
    if (planes.normals[f].dot(d) < std::cos(tol::kFoldAngle)) continue;
    bool against = false;
    for (const Vec3& c : corners)
      if (std::abs(planes.normals[f].dot(c) - planes.offsets[f]) <= slack) {
        against = true;
        break;
      }
    if (!against) {
      face.clear();
      const int loop = static_cast<int>(f);
      for (int k = 0; k < hull.face_size(loop); ++k) {
        const Vec3 p = world[static_cast<size_t>(hull.face_vertex(loop, k))] + shift;
        face.emplace_back(u.dot(p), v.dot(p));
      }
      against = overlap_2d(region, face, slack);
    }
    count += against ? 1 : 0;
  }
  return count;
}

double segment_distance(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double len = ab.squaredNorm();
  const double t = len > 0 ? std::clamp((p - a).dot(ab) / len, 0.0, 1.0) : 0.0;
  return (p - (a + t * ab)).norm();
}

}  // namespace

void plane_basis(const Vec3& n, Vec3& u, Vec3& v) {
  const Vec3 helper = std::abs(n.x()) < 0.6 ? Vec3::UnitX() : (std::abs(n.y()) < 0.6 ? Vec3::UnitY() : Vec3::UnitZ());
  u = n.cross(helper).normalized();
  v = n.cross(u);
}

double distance_to_convex_hull_2d(const Vec2& p, std::vector<Vec2> points) {
  if (points.empty()) return INFINITY;
  const std::vector<Vec2> hull = monotone_chain(std::move(points));
  if (hull.size() == 1) return (p - hull[0]).norm();
  bool inside = hull.size() >= 3;
  double nearest = INFINITY;
  for (size_t i = 0; i < hull.size(); ++i) {
    const Vec2& a = hull[i];
    const Vec2& b = hull[(i + 1) % hull.size()];
    if (cross(a, b, p) < 0) inside = false;
    nearest = std::min(nearest, segment_distance(p, a, b));
    if (hull.size() == 2) break;
  }
  return inside ? 0.0 : nearest;
}

ContactRegion contact_region(const Scene& s, const Vec3& n, const Vec3& shift_b, double slack) {
  const Planes planes_a = world_planes(s.hull_a, s.pose_a, Vec3::Zero());
  const Planes planes_b = world_planes(s.hull_b, s.pose_b, shift_b);
  std::vector<Vec3> corners;
  const Solid solid_a{s.hull_a, s.pose_a, Vec3::Zero(), planes_a}, solid_b{s.hull_b, s.pose_b, shift_b, planes_b};
  add_corners(s.hull_a, s.world_a, Vec3::Zero(), solid_b, slack, corners);
  add_corners(s.hull_b, s.world_b, shift_b, solid_a, slack, corners);
  ContactRegion region;
  if (corners.empty()) return region;
  Vec3 u, v;
  plane_basis(n, u, v);
  std::vector<Vec2> projected;
  for (const Vec3& c : corners) projected.emplace_back(u.dot(c), v.dot(c));
  region.corners = monotone_chain(projected);
  region.facing_faces_a = facing_faces(s.hull_a, s.world_a, Vec3::Zero(), planes_a, corners, region.corners, n, u, v,
                                       slack);
  region.facing_faces_b = facing_faces(s.hull_b, s.world_b, shift_b, planes_b, corners, region.corners, -n, u, v,
                                       slack);
  region.empty = false;
  region.centroid = area_centroid(region.corners);
  for (size_t i = 0; i < region.corners.size(); ++i)
    for (size_t j = i + 1; j < region.corners.size(); ++j)
      region.width = std::max(region.width, (region.corners[i] - region.corners[j]).norm());
  return region;
}

double region_width_bound(const Scene& s, const Vec3& n, const Vec3& shift_b, double slack) {
  Vec3 u, v;
  plane_basis(n, u, v);
  const auto extent = [&](const std::vector<Vec3>& world, double& low, double& high) {
    low = INFINITY, high = -INFINITY;
    for (const Vec3& p : world) low = std::min(low, n.dot(p)), high = std::max(high, n.dot(p));
  };
  double low_a, high_a, low_b, high_b;
  extent(s.world_a, low_a, high_a);
  extent(s.world_b, low_b, high_b);
  // Every corner lies within the slack of both hulls, so within the slab
  // where their extents along n overlap, widened by twice the slack for the
  // point of each hull it stands beside.
  const double along_b = n.dot(shift_b);
  const double low = std::max(low_a, low_b + along_b) - 2 * slack;
  const double high = std::min(high_a, high_b + along_b) + 2 * slack;
  if (!(low <= high)) return 4 * slack;
  // A hull's section by the slab has for corners its vertices in the slab
  // and its edges' crossings of the slab's two planes; the bounding
  // rectangle of their shadows in (u, v).
  const auto section_rectangle = [&](const Hull& hull, const std::vector<Vec3>& world, const Vec3& shift,
                                     Vec2& rect_low, Vec2& rect_high) {
    rect_low = Vec2::Constant(INFINITY), rect_high = Vec2::Constant(-INFINITY);
    const auto add = [&](const Vec3& p) {
      const Vec2 q(u.dot(p), v.dot(p));
      rect_low = rect_low.cwiseMin(q), rect_high = rect_high.cwiseMax(q);
    };
    for (const Vec3& p : world)
      if (const Vec3 q = p + shift; n.dot(q) >= low && n.dot(q) <= high) add(q);
    for (const HullEdge& e : hull.edges()) {
      const Vec3 p = world[e.v0] + shift, q = world[e.v1] + shift;
      const double hp = n.dot(p), hq = n.dot(q);
      for (const double plane : {low, high})
        if ((hp < plane) != (hq < plane)) add(p + ((plane - hp) / (hq - hp)) * (q - p));
    }
  };
  Vec2 low_in_a, high_in_a, low_in_b, high_in_b;
  section_rectangle(s.hull_a, s.world_a, Vec3::Zero(), low_in_a, high_in_a);
  section_rectangle(s.hull_b, s.world_b, shift_b, low_in_b, high_in_b);
  const Vec2 across = (high_in_a.cwiseMin(high_in_b) - low_in_a.cwiseMax(low_in_b)).cwiseMax(0.0);
  return across.norm() * (1 + 1e-12) + 4 * slack;
}

std::vector<Vec2> convex_hull_2d(std::vector<Vec2> points) { return monotone_chain(std::move(points)); }

double convex_hull_area_2d(const std::vector<Vec2>& points) {
  const std::vector<Vec2> hull = monotone_chain(points);
  double twice = 0;
  for (size_t i = 0; hull.size() >= 3 && i < hull.size(); ++i) {
    const Vec2& a = hull[i];
    const Vec2& b = hull[(i + 1) % hull.size()];
    twice += a.x() * b.y() - b.x() * a.y();
  }
  return 0.5 * std::abs(twice);
}

}  // namespace mfz

#include "geometry/hull_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/closest_point.h"
#include "geometry/vector_lanes.h"

namespace mfz {

// Outside, the nearest point lies on a face whose plane the point is
// outside of, in exact arithmetic. Rounding breaks that: a point on a face
// can sit 1e-13 outside a neighbour folded by 1e-14 and exactly on its own
// face's plane, and the neighbour's polygon is far. So the faces the point
// is outside of come first, then every other face whose plane is nearer
// than the best so far: a face's polygon is never nearer than its plane,
// and a face of the hull can never undercut the distance to the hull
// (manifuzz fuzz: a false on-surface of 0.3 on the built-in).
//
// A caller that asks only whether the distance exceeds `enough` has its
// answer from any one face polygon within `enough`: the hull's surface is
// never further than one of its faces. The face the point stands highest
// over is asked first; where it is further, every face is measured as
// above, and the minimum is the same whichever face was asked first.
namespace {

// The distance from `p` to the convex hull of the hull's vertices, from the
// vertices alone (GJK on the point and the vertices: each step adds the
// vertex furthest along the way back to p and keeps the nearest point of
// the simplex, a triangle at most; a tetrahedron around p puts p inside).
// An upper bound, tight to rounding: the nearest point found is a point of
// the hull. Asked where the faces put a point outside by much more than its
// height over any face plane: merged faces may leave a crack that the
// vertices do not (h16: a vertex 6.9e-11 below a face plane and 3e-10 from
// its neighbour, and the faces either side of the short edge between them
// left a wedge 2.5 wide uncovered, 73 along; a contact 4.8e-11 inside the
// hull of the vertices measured 2.55 outside it, 1.25e-4 L).
double distance_to_vertex_hull(const Hull& hull, const Vec3& p) {
  const auto relative = [&](int i) { return Vec3(hull.vertex(i) - p); };
  // The vertex nearest along -x: the support of the vertices less p.
  const auto support_against = [&](const Vec3& x) {
    int best = 0;
    double least = x.dot(relative(0));
    for (int i = 1; i < hull.vertex_count(); ++i)
      if (const double d = x.dot(relative(i)); d < least) least = d, best = i;
    return relative(best);
  };
  Vec3 simplex[3] = {relative(0)};
  int size = 1;
  Vec3 x = simplex[0];
  const Vec3 origin = Vec3::Zero();
  constexpr int kMostSteps = 64;
  for (int step = 0; step < kMostSteps && x.squaredNorm() > 0; ++step) {
    const Vec3 s = support_against(x);
    // x . x - x . s bounds how much nearer the hull comes than x: stop when
    // that is rounding of x's length.
    if (x.squaredNorm() - x.dot(s) <= 1e-15 * x.squaredNorm()) break;
    Vec3 nearer = x;
    if (size == 1) {
      nearer = closest_on_segment(origin, simplex[0], s);
      simplex[size++] = s;
    } else if (size == 2) {
      nearer = closest_on_triangle(origin, simplex[0], simplex[1], s);
      simplex[size++] = s;
    } else {
      // A tetrahedron: p is inside when no face's plane separates it from the
      // fourth corner (a flat one holds nothing); else the nearest of its
      // faces is kept. Flat is flat to rounding: the volume within 1e-12 of
      // its edges' lengths' product (a point inside a tetrahedron that thin
      // is within 1e-12 of its size of a face, which is kept). A support
      // point already in the simplex made one of no volume whose triple
      // product rounded to -0.006, and a point 3.6 outside a needle 6.5e8
      // long, beside its tip, measured 0: the contact region took it in and
      // was 4,648 wide where the first-touching slab held 43, and the
      // built-in's one point at the tip missed its centroid (h27,
      // spans-contact-region, manifuzz fuzz --strict, open as O27).
      const Vec3 corners[4] = {simplex[0], simplex[1], simplex[2], s};
      const int faces[4][3] = {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}};
      const Vec3 e1 = corners[1] - corners[0], e2 = corners[2] - corners[0], e3 = corners[3] - corners[0];
      const double volume = e1.cross(e2).dot(e3);
      constexpr double kFlatVolume = 1e-12;
      bool inside = std::abs(volume) > kFlatVolume * e1.norm() * e2.norm() * e3.norm() && std::isfinite(volume);
      int kept = 0;
      double least = std::numeric_limits<double>::infinity();
      for (int f = 0; f < 4; ++f) {
        const Vec3 &a = corners[faces[f][0]], &b = corners[faces[f][1]], &c = corners[faces[f][2]];
        const Vec3& other = corners[6 - faces[f][0] - faces[f][1] - faces[f][2]];
        const Vec3 normal = (b - a).cross(c - a);
        if (normal.dot(-a) * normal.dot(other - a) < 0) inside = false;
        const Vec3 on = closest_on_triangle(origin, a, b, c);
        if (on.squaredNorm() < least) least = on.squaredNorm(), nearer = on, kept = f;
      }
      if (inside) return 0;
      for (int k = 0; k < 3; ++k) simplex[k] = corners[faces[kept][k]];
    }
    if (!(nearer.squaredNorm() < x.squaredNorm())) break;  // no progress: x is as near as rounding allows
    x = nearer;
  }
  return x.norm();
}

// Each face's height over its plane, n . p less the plane's offset, for
// the first `count` faces at once in vector lanes: the dot products summed
// (x + y) + z, as Vec3's are, so the bits of the face's normal dotted with
// p less Hull::face_offset. One face at a time, through the hull's
// accessors, the heights were a third of the function (on-surface and
// within-both-hulls spent 13% of a 32-point fuzz execution in it).
MFZ_VECTOR_LANES void plane_heights(const mfz_vec3* face_normals, const double* offsets, int count, double px,
                                    double py, double pz, double* heights) {
  static_assert(sizeof(mfz_vec3) == 3 * sizeof(double), "the normals lie x y z, x y z, ...");
  const double* normals = &face_normals[0].x;
#pragma omp simd
  for (int f = 0; f < count; ++f) {
    const int n = 3 * f;
    const double nx = normals[n], ny = normals[n + 1], nz = normals[n + 2];
    heights[f] = ((nx * px + ny * py) + nz * pz) - offsets[f];
  }
}

double distance_to_surface(const Hull& hull, const Pose& pose, const Vec3& world_point, double enough) {
  const Vec3 p = pose.to_local_direction(world_point - pose.position);
  // Each face's height over its plane is taken once, for all three passes
  // (taken in each, it was three fifths of the function, which the on-surface
  // and within-both-hulls checks made 7% of a fuzz execution); faces past
  // the buffer take theirs again, to the same bits.
  constexpr int kHeightsOnStack = 256;
  double heights[kHeightsOnStack];
  const auto plane_height = [&](int f) { return hull.face_normal(f).dot(p) - hull.face_offset(f); };
  const auto height = [&](int f) { return f < kHeightsOnStack ? heights[f] : plane_height(f); };
  double outside_most = -std::numeric_limits<double>::infinity();
  int highest_over = 0;
  const mfz_hull view = hull.view();
  const int in_buffer = std::min(hull.face_count(), kHeightsOnStack);
  plane_heights(view.face_normals, hull.face_offsets(), in_buffer, p.x(), p.y(), p.z(), heights);
  for (int f = 0; f < in_buffer; ++f)
    if (heights[f] > outside_most) outside_most = heights[f], highest_over = f;
  for (int f = in_buffer; f < hull.face_count(); ++f)
    if (const double h = plane_height(f); h > outside_most) outside_most = h, highest_over = f;
  if (outside_most <= 0) return outside_most;
  Vec3 loop[kMaxLoopOnStack];
  const auto polygon_distance = [&](int f) {
    const int n = std::min(hull.face_size(f), kMaxLoopOnStack);
    for (int k = 0; k < n; ++k) loop[k] = hull.vertex(hull.face_vertex(f, k));
    return (closest_point_on_polygon(p, loop, n, hull.face_normal(f)) - p).norm();
  };
  // The face asked first is not asked again: the minimum is the same.
  double nearest = std::numeric_limits<double>::infinity();
  const int asked_first = enough >= 0 ? highest_over : -1;
  if (asked_first >= 0) {
    nearest = polygon_distance(asked_first);
    if (nearest <= enough) return nearest;
  }
  for (const bool outside_pass : {true, false}) {
    for (int f = 0; f < hull.face_count(); ++f) {
      const double plane = height(f);
      if (f == asked_first || (outside_pass ? plane <= 0 : (plane > 0 || -plane >= nearest))) continue;
      nearest = std::min(nearest, polygon_distance(f));
    }
    if (outside_pass && nearest <= enough) return nearest;
  }
  // Further from the faces than twice its height over their planes: a point
  // beyond a sharp edge or corner, or one over a crack between merged faces.
  // The vertices decide.
  if (nearest > 2 * outside_most) nearest = std::min(nearest, distance_to_vertex_hull(hull, p));
  return nearest;
}

}  // namespace

double signed_distance(const Hull& hull, const Pose& pose, const Vec3& world_point) {
  return distance_to_surface(hull, pose, world_point, -std::numeric_limits<double>::infinity());
}

double signed_distance_past(const Hull& hull, const Pose& pose, const Vec3& world_point, double allowed) {
  return distance_to_surface(hull, pose, world_point, allowed);
}

}  // namespace mfz

#include "generator/last_resort_contact.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "generator/contact_output.h"
#include "geometry/tolerances.h"

namespace mfz {
namespace {

// How far a ray from `point` along `out_of` runs inside the reference hull;
// negative when the point is outside it. A point within the frame's
// rounding of a face's plane is on it: where an edge of the other hull
// enters, its point lies on the plane it enters by, and rounding puts it on
// either side. Taken as outside there, the entering points of one argument
// order were all refused and the last resort took the other hull's point,
// 3,428 away (F29: the correct face-bias variant, swap-symmetry, --seed 61).
double exit_along(const PosedHull& reference, const Vec3& point, const Vec3& out_of) {
  double exit = std::numeric_limits<double>::infinity();
  const double point_extent = point.cwiseAbs().maxCoeff();
  for (int f = 0; f < reference.face_count(); ++f) {
    const Vec3 normal = reference.world_face_normal(f);
    const Vec3 on_face = reference.world_face_point(f, 0);
    const double below = normal.dot(on_face - point);
    if (below < -tol::world_rounding(point_extent + on_face.cwiseAbs().maxCoeff())) return -1;  // outside
    const double rate = normal.dot(out_of);
    if (!(rate > 0)) continue;  // the ray does not leave through a face it runs along or away from
    exit = std::min(exit, std::max(below, 0.0) / rate);
  }
  return exit;
}

// The part of segment [p, q] inside every face plane of `hull` (Cyrus-Beck),
// as parameters [t0, t1]; false when none is.
bool segment_inside(const PosedHull& hull, const Vec3& p, const Vec3& q, double& t0, double& t1) {
  t0 = 0, t1 = 1;
  for (int f = 0; f < hull.face_count() && t0 <= t1; ++f) {
    const Vec3 normal = hull.world_face_normal(f);
    const double offset = normal.dot(hull.world_face_point(f, 0));
    const double dp = normal.dot(p) - offset, dq = normal.dot(q) - offset;
    if (dp > 0 && dq > 0) return false;
    if (dp > 0) t0 = std::max(t0, dp / (dp - dq));
    if (dq > 0) t1 = std::min(t1, dp / (dp - dq));
  }
  return t0 <= t1;
}

// The point of `inner` deepest inside `outer`, measured by how far a ray
// from it along `out_of` runs inside `outer` before it leaves: the deepest
// vertex along -out_of when it is inside (F17, F18), or a point where an
// edge running inside enters or leaves (two corners crossing by their edges,
// F26). The deepest along -out_of alone is not enough: the end of an edge
// cut by a face the ray leaves through at once gives a contact of no depth
// (a 0.17 tetrahedron 0.055 deep in a 1.5e6 hull: has-contacts in the
// swap-symmetry run, the second campaign). Returns the ray's length, or a
// negative number when no point of `inner` is inside `outer`.
double deepest_point_inside(const PosedHull& outer, const PosedHull& inner, const Vec3& out_of, Vec3& point) {
  double longest = -1;
  const auto consider = [&](const Vec3& x) {
    if (const double exit = exit_along(outer, x, out_of); std::isfinite(exit) && exit > longest) longest = exit, point = x;
  };
  consider(inner.world_vertex(inner.support_vertex(-out_of)));
  inner.for_each_edge([&](int, int v0, int v1, int) {
    const Vec3 p = inner.world_vertex(v0), q = inner.world_vertex(v1);
    double t0, t1;
    if (segment_inside(outer, p, q, t0, t1))
      for (const double t : {t0, t1}) consider(p + t * (q - p));
    return true;
  });
  return longest;
}

}  // namespace

// F17: the last resort when neither clipping nor the edges give a contact (the
// reference face is one half of a fold, and the other hull pokes into the
// other half; two corners crossing by their edges under a face axis that F3
// preferred, F26): a point of one hull deepest inside the other, paired with
// where a ray from it along n leaves the other. A point of B inside A leaves
// A along +n, one of A inside B leaves B along -n; both points are on their
// surfaces by construction. The incident hull's point is tried first.
//
// The ray is no longer than the depth, since moving B by depth n separates
// the hulls; its length is capped there, as rounding can make it longer: a
// point within the world's rounding of a face's plane is on it only to that
// rounding, and a ray from it that runs nearly along the face leaves it
// that rounding over the face's slope to n further on. A tetrahedron 3.8e8
// across touching one 6.6e17 across had a point 32 below a face of the large
// one (the rounding there 7.1e3) that runs 1.06e-8 off n; its ray left after
// 3.0e9, a contact that deep under a manifold 1.5e-8 deep, 3.6e-9 L deeper
// than the manifold (F63, negative-penetration in the swap-symmetry run,
// manifuzz fuzz --max-points 5, open as O35).
void deepest_point_contact(const PosedHull& a, const PosedHull& b, const Vec3& n, double depth, bool flipped,
                           mfz_manifold& out) {
  for (const bool b_inside_a : {!flipped, flipped}) {
    Vec3 point;
    const Vec3 out_of = b_inside_a ? n : Vec3(-n);
    const double exit = b_inside_a ? deepest_point_inside(a, b, out_of, point) : deepest_point_inside(b, a, out_of, point);
    if (!(exit > 0)) continue;
    const double p = -std::min(exit, depth);
    if (b_inside_a)
      add_contact(out, point - p * n, point, p);
    else
      add_contact(out, point, point + p * n, p);
    return;
  }
}

}  // namespace mfz

#include "generator/baseline/tutorial_method.h"

#include "generator/clip_polygon.h"

namespace mfz {
namespace {

// One axis, the tutorial's way: false when it separates.
bool try_axis(const PosedHull& a, const PosedHull& b, const Vec3& axis, AxisKind kind, int fa, int fb,
              SatResult& best) {
  const Interval ia = a.project(axis), ib = b.project(axis);
  const double b_above = ia.max - ib.min, b_below = ib.max - ia.min;
  const bool along = b_above <= b_below;
  const double overlap = along ? b_above : b_below;
  if (b_above < 0 || b_below < 0) {
    best = {true, along ? axis : Vec3(-axis), overlap, kind, fa, fb};
    return false;
  }
  if (overlap < best.depth) best = {false, along ? axis : Vec3(-axis), overlap, kind, fa, fb};
  return true;
}

}  // namespace

SatResult tutorial_sat(const PosedHull& a, const PosedHull& b) {
  SatResult best;
  best.depth = std::numeric_limits<double>::infinity();
  for (int f = 0; f < a.face_count(); ++f)
    if (!try_axis(a, b, a.world_face_normal(f), AxisKind::face_a, f, -1, best)) return best;
  for (int f = 0; f < b.face_count(); ++f)
    if (!try_axis(a, b, b.world_face_normal(f), AxisKind::face_b, -1, f, best)) return best;
  bool separated = false;
  a.for_each_edge([&](int ea, int a0, int a1, int) {
    b.for_each_edge([&](int eb, int b0, int b1, int) {
      const Vec3 edge_a = a.world_vertex(a1) - a.world_vertex(a0);
      const Vec3 edge_b = b.world_vertex(b1) - b.world_vertex(b0);
      const Vec3 axis = edge_a.cross(edge_b);
      const double length = axis.norm();
      if (length <= tol::kParallelEdges * edge_a.norm() * edge_b.norm()) return true;  // a face normal's
      separated = !try_axis(a, b, axis / length, AxisKind::edge_edge, ea, eb, best);
      return !separated;
    });
    return !separated;
  });
  return best;
}

// The plane of the face across each edge of the reference face, kept side inward.
bool clip_to_adjacent_face_planes(const ClipFace& reference, ClipPolygon& incident) {
  const PosedHull& hull = *reference.hull;
  const int n = hull.face_size(reference.index);
  ClipPolygon scratch;
  for (int k = 0; k < n; ++k) {
    const int v0 = hull.face_vertex(reference.index, k), v1 = hull.face_vertex(reference.index, (k + 1) % n);
    const int adjacent = hull.face_across(v0, v1);
    if (adjacent < 0) continue;  // an open hull: no plane to clip against
    const Vec3 normal = hull.world_face_normal(adjacent);
    const Plane side{normal, normal.dot(hull.world_vertex(v0))};
    if (!clip_to_plane(incident, side, scratch)) return false;
    incident.take(scratch);
  }
  return true;
}

// The tutorial's GenContactPoints, step by step:
//  1. SAT gives n (A to B) and the depth; no contacts unless p < 0.
//  2. Significant faces: of the faces holding the vertex furthest along n
//     (for B, along -n), the one most parallel to it.
//  3. The one more parallel to n is the reference face, the other incident.
//  4. Clip the incident face against the planes of the faces adjacent to the
//     reference face (Sutherland-Hodgman).
//  5. Remove the points above the reference plane.
//  6. Each remaining point is a contact, its depth measured from the
//     reference face along n.
int32_t generate_tutorial_manifold(const mfz_hull& hull_a, const mfz_pose& abi_pose_a, const mfz_hull& hull_b,
                                   const mfz_pose& abi_pose_b, mfz_manifold& out) {
  const Pose pose_a = Pose::from_abi(abi_pose_a), pose_b = Pose::from_abi(abi_pose_b);
  const PosedHull a(hull_a, pose_a), b(hull_b, pose_b);
  const SatResult sat = tutorial_sat(a, b);
  out.contact_count = 0;
  out.colliding = sat.separated ? 0 : 1;
  out.normal = to_abi(sat.normal);
  out.penetration = sat.separated ? 0.0 : -sat.depth;
  if (sat.separated || !(out.penetration < 0)) return 0;
  const Vec3 n = sat.normal;
  int support_a = -1, support_b = -1;
  ClipFace face_a{&a, significant_face(a, n, support_a), {}};
  ClipFace face_b{&b, significant_face(b, -n, support_b), {}};
  if (face_a.index < 0 || face_b.index < 0) return 1;  // a vertex in no face: not a hull
  face_a.normal = a.world_face_normal(face_a.index);
  face_b.normal = b.world_face_normal(face_b.index);
  if (single_point_contact(face_a, support_a, face_b, support_b, n, out)) return 0;
  const bool flipped = more_parallel_is_reference_b(sat, face_a, face_b);
  ClipFace& reference = flipped ? face_b : face_a;
  const ClipFace& incident = flipped ? face_a : face_b;
  ClipPolygon reference_polygon, polygon;
  face_loop(*reference.hull, reference.index, reference_polygon);
  reference.polygon = &reference_polygon;
  face_loop(*incident.hull, incident.index, polygon);
  if (polygon.size() + reference_polygon.size() >= kMaxPolygonVertices) return 1;
  if (!clip_to_adjacent_face_planes(reference, polygon)) return 1;
  const Vec3 on_reference = reference.hull->world_face_point(reference.index, 0);
  remove_points_outside(polygon, Plane{reference.normal, reference.normal.dot(on_reference)});
  reduce_polygon(polygon, MFZ_MAX_CONTACTS);
  emit_clipped_contacts(reference, polygon, n, flipped, out);
  return 0;
}

}  // namespace mfz

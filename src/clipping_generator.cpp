#include "clipping_generator.h"

#include <cmath>
#include <limits>

#include "clip_polygon.h"

namespace mfz {

int significant_face(const PosedHull& hull, const Vec3& direction, int& support) {
  support = hull.support_vertex(direction);
  int best = -1;
  double most_parallel = -std::numeric_limits<double>::infinity();
  for (int f = 0; f < hull.face_count(); ++f) {
    bool contains = false;
    for (int k = 0; k < hull.face_size(f) && !contains; ++k) contains = hull.face_vertex(f, k) == support;
    if (!contains) continue;
    const double alignment = hull.world_face_normal(f).dot(direction);
    if (alignment > most_parallel) most_parallel = alignment, best = f;
  }
  return best;
}

namespace {

struct Face {
  const PosedHull* hull = nullptr;
  int index = -1;
  Vec3 normal;
};

void load_face(const Face& face, ClipPolygon& polygon) {
  polygon.clear();
  for (int k = 0; k < face.hull->face_size(face.index); ++k) polygon.push(face.hull->world_face_point(face.index, k));
}

void record(ClipTrace* trace, std::string what, const ClipPolygon& polygon) {
  if (!trace) return;
  ClipTrace::Step step{std::move(what), {}};
  for (int k = 0; k < polygon.size(); ++k) step.polygon.push_back(polygon[k]);
  trace->steps.push_back(std::move(step));
}

// The seed clips against "the adjacent faces" of the reference face: the plane
// of the face across each of its edges, kept side inward.
bool clip_to_side_planes(const Face& reference, ClipPolygon& incident, ClipTrace* trace) {
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
    std::swap(incident, scratch);
    if (trace)
      record(trace, "clipped against the plane of face " + std::to_string(adjacent) + " (across edge " +
                        std::to_string(v0) + "-" + std::to_string(v1) + ")", incident);
  }
  return true;
}

void add_contact(mfz_manifold& out, const Vec3& on_a, const Vec3& on_b, double penetration) {
  mfz_contact& c = out.contacts[out.contact_count++];
  c.point_on_a = to_abi(on_a);
  c.point_on_b = to_abi(on_b);
  c.penetration = penetration;
}

// The seed's last loop: each clipped point is on the incident face; its depth
// is measured from the closest point of the reference polygon, along n.
void emit_contacts(const Face& reference, const ClipPolygon& clipped, const Vec3& n, bool flipped,
                   mfz_manifold& out) {
  Vec3 reference_loop[kMaxPolygonVertices];
  const int count = reference.hull->face_size(reference.index);
  for (int k = 0; k < count; ++k) reference_loop[k] = reference.hull->world_face_point(reference.index, k);
  for (int k = 0; k < clipped.size(); ++k) {
    const Vec3& point = clipped[k];
    const Vec3 on_reference = closest_point_on_polygon(point, reference_loop, count, reference.normal);
    double penetration = (point - on_reference).dot(n);
    if (flipped) penetration = -penetration;
    if (!(penetration < 0)) continue;  // the seed's sanity check: above the reference face, not a contact
    if (flipped)
      add_contact(out, point, point + penetration * n, penetration);  // incident face is A's
    else
      add_contact(out, point - penetration * n, point, penetration);  // incident face is B's
  }
}

}  // namespace

// Outline, after the seed's CollisionDetectionSAT::GenContactPoints:
//  1. SAT gives the normal n (A to B) and the depth; no contacts unless p < 0.
//  2. Significant faces: A's along n, B's along -n.
//  3. The one more parallel to n is the reference face, the other incident
//     ("flipped" when the reference face is B's).
//  4. Clip the incident face against the planes of the faces adjacent to the
//     reference face (Sutherland-Hodgman).
//  5. Remove the points above the reference plane.
//  6. Each remaining point is a contact with its own penetration.
int32_t generate_clipping_manifold(const mfz_hull& hull_a, const mfz_pose& abi_pose_a, const mfz_hull& hull_b,
                                   const mfz_pose& abi_pose_b, mfz_manifold& out, ClipTrace* trace) {
  const Pose pose_a = Pose::from_abi(abi_pose_a), pose_b = Pose::from_abi(abi_pose_b);
  const PosedHull a(hull_a, pose_a), b(hull_b, pose_b);
  const SatResult sat = run_sat(a, b);
  if (trace) trace->sat = sat;
  out.contact_count = 0;
  out.colliding = sat.separated ? 0 : 1;
  out.normal = to_abi(sat.normal);
  out.penetration = sat.separated ? 0.0 : -sat.depth;
  if (sat.separated || !(out.penetration < 0)) return 0;
  const Vec3 n = sat.normal;

  int support_a = -1, support_b = -1;
  Face face_a{&a, significant_face(a, n, support_a), {}};
  Face face_b{&b, significant_face(b, -n, support_b), {}};
  if (trace) trace->face_a = face_a.index, trace->face_b = face_b.index, trace->support_a = support_a,
             trace->support_b = support_b;
  if (face_a.index < 0 || face_b.index < 0) return 1;  // a vertex in no face: not a hull
  face_a.normal = a.world_face_normal(face_a.index);
  face_b.normal = b.world_face_normal(face_b.index);

  // The seed's single-point branch is for curved shapes, whose "face" is one
  // point; a hull's faces have three or more vertices, so here it only catches
  // a degenerate face handed in through the ABI: the support point is the contact.
  if (a.face_size(face_a.index) < 3) {
    const Vec3 point = a.world_vertex(support_a);
    add_contact(out, point, point + out.penetration * n, out.penetration);
    return 0;
  }
  if (b.face_size(face_b.index) < 3) {
    const Vec3 point = b.world_vertex(support_b);
    add_contact(out, point - out.penetration * n, point, out.penetration);
    return 0;
  }

  const bool flipped = std::abs(n.dot(face_a.normal)) < std::abs(n.dot(face_b.normal));
  if (trace) trace->flipped = flipped;
  const Face& reference = flipped ? face_b : face_a;
  const Face& incident = flipped ? face_a : face_b;
  const int reference_size = reference.hull->face_size(reference.index);
  if (incident.hull->face_size(incident.index) + reference_size >= kMaxPolygonVertices) return 1;

  ClipPolygon polygon;
  load_face(incident, polygon);
  record(trace, "incident face", polygon);
  if (!clip_to_side_planes(reference, polygon, trace)) return 1;
  const Vec3 on_reference = reference.hull->world_face_point(reference.index, 0);
  remove_points_outside(polygon, Plane{reference.normal, reference.normal.dot(on_reference)});
  record(trace, "points above the reference plane removed", polygon);
  reduce_polygon(polygon, MFZ_MAX_CONTACTS);
  emit_contacts(reference, polygon, n, flipped, out);
  return 0;
}

}  // namespace mfz

// ODE 0.16 as a manifuzz generator, in two of its colliders:
//
//   ode      dCollideConvexConvex (collision_convex.cpp): SAT over both
//            hulls' face planes and edge pairs, then for a face axis the
//            incident polygon clipped against the reference convex, for an
//            edge axis the closest points of the two edges. ODE's dCollide
//            does not reach it for two convexes (Debian builds ODE with
//            libccd, which sends the pair to an MPR path with one point), so
//            the collider is called directly: libode exports it with C++
//            linkage but declares it in no installed header.
//   ode-box  dBoxBox for two boxes (return code 1-3 a face of A, 4-6 one of
//            B, 7-15 two edges); it prefers a face axis unless an edge
//            axis is 5% shallower (its fudge_factor 1.05), hence the profile's
//            face-bias=0.05. Any other hull is refused (status 1): run it
//            with `--family boxes`.
//
// Built against Debian's libode (dDOUBLE): no precision key.
//
// Conventions mapped to the contract's (docs/peers.md):
//   - ODE's normal points into body 1 (from B to A): n = -normal. dBoxBox's
//     own normal argument already points from A to B.
//   - ODE's depth is positive when overlapping: p_i = -depth.
//   - Where ODE puts `pos` depends on the case: on the incident face (B's
//     when A's face is the reference, A's when B's is: dBoxBox's return
//     code tells), on A's edge for an edge contact of dCollideConvexConvex,
//     halfway between the two edges for one of dBoxBox. Each is mapped to
//     the two points.
//   - ODE needs a convex's local origin inside it: each hull is handed over
//     about the mean of its vertices, and its pose moved to match.
#include <ode/ode.h>

#include <cmath>
#include <vector>

#include "../peer_plugin.h"

#ifndef ODE_PEER_BOX
#error "define ODE_PEER_BOX to 1 (ode-box) or 0 (ode)"
#endif

// libode.so's convex-convex collider (collision_std.h, not installed).
int dCollideConvexConvex(dxGeom* o1, dxGeom* o2, int flags, dContactGeom* contact, int skip);

namespace {

/// Contacts asked of ODE: the ABI's capacity.
constexpr int kMaxContacts = MFZ_MAX_CONTACTS;
/// A box's faces are paired and perpendicular to this (relative) tolerance.
constexpr double kBoxTolerance = 1e-9;

struct Vec {
  double x, y, z;
};
Vec operator+(Vec a, Vec b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
Vec operator-(Vec a, Vec b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Vec operator*(double s, Vec a) { return {s * a.x, s * a.y, s * a.z}; }
double dot(Vec a, Vec b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec cross(Vec a, Vec b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
Vec vec(const mfz_vec3& v) { return {v.x, v.y, v.z}; }
Vec vec(const dReal* v) { return {double(v[0]), double(v[1]), double(v[2])}; }
mfz_vec3 abi(Vec v) { return {v.x, v.y, v.z}; }

/// The pose's rotation, row-major as ODE's dMatrix3 (rows padded to four).
void rotation(const mfz_quat& q, dMatrix3 r) {
  const dQuaternion odeq = {dReal(q.w), dReal(q.x), dReal(q.y), dReal(q.z)};
  dRfromQ(r, odeq);
}
Vec rotate(const dMatrix3 r, Vec v) {
  return {r[0] * v.x + r[1] * v.y + r[2] * v.z, r[4] * v.x + r[5] * v.y + r[6] * v.z,
          r[8] * v.x + r[9] * v.y + r[10] * v.z};
}

void init_once() {
  static const bool done = [] {
    dInitODE2(0);
    return true;
  }();
  (void)done;
}

// ---- ode: dCollideConvexConvex ----

/// A hull in ODE's convex form, about the mean of its vertices; ODE keeps
/// pointers into these arrays, so they live as long as the geom. Built once
/// per hull (peer::PreparedHulls), placed on each call.
struct OdeConvex {
  std::vector<dReal> planes, points;
  std::vector<unsigned int> polygons;
  Vec centre{0, 0, 0};
  dGeomID geom = nullptr;
  ~OdeConvex() {
    if (geom) dGeomDestroy(geom);
  }
};

void make_convex(const mfz_hull& h, OdeConvex& c) {
  for (int i = 0; i < h.vertex_count; ++i) c.centre = c.centre + (1.0 / h.vertex_count) * vec(h.vertices[i]);
  for (int i = 0; i < h.vertex_count; ++i) {
    const Vec p = vec(h.vertices[i]) - c.centre;
    c.points.insert(c.points.end(), {dReal(p.x), dReal(p.y), dReal(p.z)});
  }
  for (int f = 0; f < h.face_count; ++f) {
    const Vec n = vec(h.face_normals[f]);
    const int first = h.face_offsets[f], end = h.face_offsets[f + 1];
    const Vec on_face = vec(h.vertices[h.face_vertices[first]]) - c.centre;
    c.planes.insert(c.planes.end(), {dReal(n.x), dReal(n.y), dReal(n.z), dReal(dot(n, on_face))});
    c.polygons.push_back(static_cast<unsigned int>(end - first));
    for (int k = first; k < end; ++k) c.polygons.push_back(static_cast<unsigned int>(h.face_vertices[k]));
  }
  c.geom = dCreateConvex(nullptr, c.planes.data(), static_cast<unsigned int>(h.face_count), c.points.data(),
                         static_cast<unsigned int>(h.vertex_count), c.polygons.data());
}

/// Places a kept geom at the pose of its hull.
void place(OdeConvex& c, const mfz_pose& pose) {
  dMatrix3 r;
  rotation(pose.orientation, r);
  const Vec at = vec(pose.position) + rotate(r, c.centre);
  dGeomSetPosition(c.geom, dReal(at.x), dReal(at.y), dReal(at.z));
  dGeomSetRotation(c.geom, r);
}

/// Whether `normal` (world) is one of A's face normals: ODE's face contacts
/// carry the reference face's normal and lie on B; its edge contact carries
/// the edges' closest-point direction and lies on A.
bool is_face_normal_of(const mfz_hull& a, const mfz_pose& pose, Vec normal) {
  dMatrix3 r;
  rotation(pose.orientation, r);
  for (int f = 0; f < a.face_count; ++f)
    if (std::abs(dot(rotate(r, vec(a.face_normals[f])), normal)) > 1 - 1e-12) return true;
  return false;
}

int32_t generate_convex(const mfz_hull& a, const mfz_pose& pa, const mfz_hull& b, const mfz_pose& pb,
                        mfz_manifold& out) {
  // A geom has one pose: A's and B's are kept apart, so that a pair of equal
  // hulls gets two.
  static thread_local peer::PreparedHulls<OdeConvex> kept_a, kept_b;
  kept_a.begin_call();
  kept_b.begin_call();
  OdeConvex& ca = kept_a.get(a, make_convex);
  OdeConvex& cb = kept_b.get(b, make_convex);
  place(ca, pa);
  place(cb, pb);
  dContactGeom contacts[kMaxContacts];
  const int count = dCollideConvexConvex(ca.geom, cb.geom, kMaxContacts, contacts, sizeof(dContactGeom));
  peer::clear(out);
  if (count <= 0) return 0;
  out.colliding = 1;
  const Vec n = -1.0 * vec(contacts[0].normal);
  out.normal = abi(n);
  const bool on_b = is_face_normal_of(a, pa, n);
  for (int i = 0; i < count; ++i) {
    const double depth = double(contacts[i].depth);
    const Vec pos = vec(contacts[i].pos);
    mfz_contact& c = out.contacts[out.contact_count++];
    c.point_on_a = abi(on_b ? pos + depth * n : pos);
    c.point_on_b = abi(on_b ? pos : pos - depth * n);
    c.penetration = -depth;
    out.penetration = std::min(out.penetration, -depth);
  }
  return 0;
}

// ---- ode-box: dBoxBox ----

struct Box {
  dVector3 centre, sides;
  dMatrix3 rotation;
};

/// The box a hull is, in world space; false when the hull is no box.
bool as_box(const mfz_hull& h, const mfz_pose& pose, Box& box) {
  if (h.vertex_count != 8 || h.face_count != 6) return false;
  Vec axes[3];
  int found = 0;
  for (int f = 0; f < 6 && found < 3; ++f) {
    const Vec n = vec(h.face_normals[f]);
    bool known = false;
    for (int k = 0; k < found; ++k) {
      const double c = std::abs(dot(n, axes[k]));
      if (c > 1 - kBoxTolerance) known = true;
      else if (c > kBoxTolerance) return false;
    }
    if (!known) axes[found++] = n;
  }
  if (found != 3) return false;
  if (dot(cross(axes[0], axes[1]), axes[2]) < 0) axes[2] = -1.0 * axes[2];
  const double size = peer::diameter(h);
  Vec local_centre{0, 0, 0};
  for (int k = 0; k < 3; ++k) {
    double low = INFINITY, high = -INFINITY;
    for (int i = 0; i < 8; ++i) {
      const double s = dot(vec(h.vertices[i]), axes[k]);
      low = std::min(low, s);
      high = std::max(high, s);
    }
    for (int i = 0; i < 8; ++i) {
      const double s = dot(vec(h.vertices[i]), axes[k]);
      if (std::min(s - low, high - s) > kBoxTolerance * size) return false;
    }
    box.sides[k] = dReal(high - low);
    local_centre = local_centre + (0.5 * (low + high)) * axes[k];
  }
  dMatrix3 r;
  rotation(pose.orientation, r);
  const Vec centre = vec(pose.position) + rotate(r, local_centre);
  box.centre[0] = dReal(centre.x), box.centre[1] = dReal(centre.y), box.centre[2] = dReal(centre.z);
  // Column k of the box's rotation: its k-th axis in world space.
  for (int k = 0; k < 3; ++k) {
    const Vec w = rotate(r, axes[k]);
    box.rotation[0 * 4 + k] = dReal(w.x), box.rotation[1 * 4 + k] = dReal(w.y), box.rotation[2 * 4 + k] = dReal(w.z);
  }
  box.rotation[3] = box.rotation[7] = box.rotation[11] = 0;
  return true;
}

int32_t generate_box(const mfz_hull& a, const mfz_pose& pa, const mfz_hull& b, const mfz_pose& pb,
                     mfz_manifold& out) {
  Box ba, bb;
  if (!as_box(a, pa, ba) || !as_box(b, pb, bb)) return 1;
  dContactGeom contacts[kMaxContacts];
  dVector3 normal;
  dReal depth = 0;
  int code = 0;
  const int count = dBoxBox(ba.centre, ba.rotation, ba.sides, bb.centre, bb.rotation, bb.sides, normal, &depth, &code,
                            kMaxContacts, contacts, sizeof(dContactGeom));
  peer::clear(out);
  if (count <= 0) return 0;
  const Vec n = vec(normal);
  out.colliding = 1;
  out.normal = abi(n);
  out.penetration = -double(depth);
  // Where `pos` lies, as a fraction of the depth from A's point towards
  // B's: on B's incident face (A's face is the reference), on A's incident
  // face (B's is), halfway between the edges.
  const double from_a = code <= 3 ? 1.0 : code <= 6 ? 0.0 : 0.5;
  for (int i = 0; i < count; ++i) {
    const double d = double(contacts[i].depth);
    const Vec pos = vec(contacts[i].pos);
    mfz_contact& c = out.contacts[out.contact_count++];
    c.point_on_a = abi(pos + (from_a * d) * n);
    c.point_on_b = abi(pos - ((1 - from_a) * d) * n);
    c.penetration = -d;
  }
  return 0;
}

}  // namespace

MFZ_PEER_EXPORT int32_t mfz_abi_version(void) { return MFZ_ABI_VERSION; }
MFZ_PEER_EXPORT const char* mfz_generator_name(void) { return ODE_PEER_BOX ? "ode-box" : "ode"; }
MFZ_PEER_EXPORT const char* mfz_generator_profile(void) { return ODE_PEER_BOX ? "face-bias=0.05" : ""; }

MFZ_PEER_EXPORT int32_t mfz_generate(const mfz_hull* a, const mfz_pose* pose_a, const mfz_hull* b,
                                     const mfz_pose* pose_b, mfz_manifold* out) {
  init_once();
  return ODE_PEER_BOX ? generate_box(*a, *pose_a, *b, *pose_b, *out) : generate_convex(*a, *pose_a, *b, *pose_b, *out);
}

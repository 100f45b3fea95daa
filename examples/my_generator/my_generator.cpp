// A contact-manifold generator written against manifuzz's plugin ABI: the
// starting point for testing your own. Copy this folder, replace the body of
// mfz_generate with a call into your engine, and run `manifuzz check` on the
// library this builds (README.md, "Testing your own generator").
//
// What it does, in the clipping method's steps:
//   1. SAT over A's and B's face normals and the cross products of their
//      edges: the axis of least overlap is the normal n (from A to B), its
//      overlap the depth.
//   2. The reference face: the face of A most aligned with n; the incident
//      face: the face of B most opposed to n.
//   3. The incident face is clipped against the side planes of the
//      reference face (Sutherland-Hodgman); the points below the reference
//      plane are the contacts, each with its own depth.
// It has one known gap, which `manifuzz check` finds in seconds: on an edge
// axis the clipped face points are not where the edges touch.
#include <manifuzz/abi.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace {

struct V {
  double x, y, z;
};
V operator+(V a, V b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
V operator-(V a, V b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
V operator*(double s, V a) { return {s * a.x, s * a.y, s * a.z}; }
double dot(V a, V b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V cross(V a, V b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
V unit(V a) { return (1 / std::sqrt(dot(a, a))) * a; }

// World-space view of a hull: its posed vertices and face normals. Fixed
// capacity: a generator should not allocate per call.
constexpr int kMaxVertices = 1024, kMaxFaces = 2048, kMaxPolygon = 256;

struct Posed {
  const mfz_hull* hull;
  std::array<V, kMaxVertices> vertex;
  std::array<V, kMaxFaces> normal;
};

V rotate(const mfz_quat& q, V v) {
  const V u{q.x, q.y, q.z};
  const V t = 2 * cross(u, v);
  return v + q.w * t + cross(u, t);
}

bool pose(const mfz_hull& h, const mfz_pose& p, Posed& out) {
  if (h.vertex_count > kMaxVertices || h.face_count > kMaxFaces) return false;
  out.hull = &h;
  const V at{p.position.x, p.position.y, p.position.z};
  for (int i = 0; i < h.vertex_count; ++i)
    out.vertex[i] = rotate(p.orientation, {h.vertices[i].x, h.vertices[i].y, h.vertices[i].z}) + at;
  for (int f = 0; f < h.face_count; ++f)
    out.normal[f] = rotate(p.orientation, {h.face_normals[f].x, h.face_normals[f].y, h.face_normals[f].z});
  return true;
}

/// max over A of n.x minus min over B of n.x: how far the hulls overlap along n.
double overlap(const Posed& a, const Posed& b, V n) {
  double max_a = -INFINITY, min_b = INFINITY;
  for (int i = 0; i < a.hull->vertex_count; ++i) max_a = std::max(max_a, dot(n, a.vertex[i]));
  for (int i = 0; i < b.hull->vertex_count; ++i) min_b = std::min(min_b, dot(n, b.vertex[i]));
  return max_a - min_b;
}

/// Step 1: the axis of least overlap (face normals of A, reversed face
/// normals of B, edge cross products either way).
bool least_overlap(const Posed& a, const Posed& b, V& n, double& depth) {
  depth = INFINITY;
  const auto consider = [&](V axis) {
    const double d = overlap(a, b, axis);
    if (d < depth) depth = d, n = axis;
  };
  for (int f = 0; f < a.hull->face_count; ++f) consider(a.normal[f]);
  for (int f = 0; f < b.hull->face_count; ++f) consider(-1 * b.normal[f]);
  const auto edges = [](const Posed& p, auto each) {
    for (int f = 0; f < p.hull->face_count; ++f)
      for (int k = p.hull->face_offsets[f]; k < p.hull->face_offsets[f + 1]; ++k) {
        const int next = k + 1 < p.hull->face_offsets[f + 1] ? k + 1 : p.hull->face_offsets[f];
        each(p.vertex[p.hull->face_vertices[next]] - p.vertex[p.hull->face_vertices[k]]);
      }
  };
  edges(a, [&](V ea) {
    edges(b, [&](V eb) {
      const V c = cross(ea, eb);
      if (dot(c, c) < 1e-24 * dot(ea, ea) * dot(eb, eb)) return;  // parallel edges
      consider(unit(c));
      consider(-1 * unit(c));
    });
  });
  return depth >= 0;
}

/// Step 2: the face of `p` whose normal has the largest dot with `d`.
int most_aligned_face(const Posed& p, V d) {
  int best = 0;
  for (int f = 1; f < p.hull->face_count; ++f)
    if (dot(p.normal[f], d) > dot(p.normal[best], d)) best = f;
  return best;
}

/// Step 3: keeps the part of `poly` on the inner side of the plane
/// (normal `side`, through `on`): Sutherland-Hodgman, one plane.
int clip(const V* poly, int count, V side, V on, V* out) {
  int kept = 0;
  for (int i = 0; i < count && kept < kMaxPolygon - 1; ++i) {
    const V p = poly[i], q = poly[(i + 1) % count];
    const double dp = dot(side, p - on), dq = dot(side, q - on);
    if (dp <= 0) out[kept++] = p;
    if ((dp < 0 && dq > 0) || (dp > 0 && dq < 0)) out[kept++] = p + (dp / (dp - dq)) * (q - p);
  }
  return kept;
}

}  // namespace

extern "C" {

__attribute__((visibility("default"))) int32_t mfz_abi_version(void) { return MFZ_ABI_VERSION; }
__attribute__((visibility("default"))) const char* mfz_generator_name(void) { return "my-generator"; }

__attribute__((visibility("default"))) int32_t mfz_generate(const mfz_hull* hull_a, const mfz_pose* pose_a,
                                                            const mfz_hull* hull_b, const mfz_pose* pose_b,
                                                            mfz_manifold* out) {
  static thread_local Posed a, b;
  if (!pose(*hull_a, *pose_a, a) || !pose(*hull_b, *pose_b, b)) return 1;  // past our capacity: refuse
  out->contact_count = 0;
  out->normal = {0, 0, 1};
  out->penetration = 0;
  V n{0, 0, 1};
  double depth = 0;
  out->colliding = least_overlap(a, b, n, depth) ? 1 : 0;
  if (!out->colliding) return 0;
  out->normal = {n.x, n.y, n.z};
  out->penetration = -depth;

  const int ref = most_aligned_face(a, n), inc = most_aligned_face(b, -1 * n);
  const mfz_hull& ha = *hull_a;
  const mfz_hull& hb = *hull_b;
  V poly[kMaxPolygon], next[kMaxPolygon];
  int count = 0;
  for (int k = hb.face_offsets[inc]; k < hb.face_offsets[inc + 1] && count < kMaxPolygon; ++k)
    poly[count++] = b.vertex[hb.face_vertices[k]];
  const V ref_normal = a.normal[ref];
  const int first = ha.face_offsets[ref], end = ha.face_offsets[ref + 1];
  for (int k = first; k < end && count > 0; ++k) {
    const V p = a.vertex[ha.face_vertices[k]], q = a.vertex[ha.face_vertices[k + 1 < end ? k + 1 : first]];
    count = clip(poly, count, unit(cross(q - p, ref_normal)), p, next);
    std::copy(next, next + count, poly);
  }
  const V on_reference = a.vertex[ha.face_vertices[first]];
  for (int i = 0; i < count && out->contact_count < MFZ_MAX_CONTACTS; ++i) {
    const double below = dot(ref_normal, poly[i] - on_reference);  // < 0: inside A
    if (below >= 0) continue;
    // The point on B, and its projection along n onto A's reference plane.
    const double along = below / dot(ref_normal, n);
    const V on_a = poly[i] - along * n;
    mfz_contact& c = out->contacts[out->contact_count++];
    c.point_on_b = {poly[i].x, poly[i].y, poly[i].z};
    c.point_on_a = {on_a.x, on_a.y, on_a.z};
    c.penetration = along;
  }
  return 0;
}

}  // extern "C"

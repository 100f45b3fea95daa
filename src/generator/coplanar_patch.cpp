// F2: a hull whose faces arrive triangulated still clips against, and is
// clipped as, the whole planar face.
#include "generator/coplanar_patch.h"

#include "generator/clipping_generator.h"

namespace mfz {

namespace {

/// Fixed capacity of a coplanar patch: faces, and boundary edges.
constexpr int kMaxPatchFaces = 256;
constexpr int kMaxPatchEdges = 512;

bool contains(const int* items, int count, int item) {
  for (int i = 0; i < count; ++i)
    if (items[i] == item) return true;
  return false;
}

// Grows the patch breadth first across edges to faces of the same plane.
int gather_patch(const PosedHull& hull, int face, int* members) {
  const Vec3 normal = hull.world_face_normal(face);
  int count = 1;
  members[0] = face;
  for (int i = 0; i < count; ++i) {
    const int f = members[i], n = hull.face_size(f);
    for (int k = 0; k < n; ++k) {
      const int g = hull.face_across_step(f, k);
      if (g < 0 || count == kMaxPatchFaces || contains(members, count, g)) continue;
      if (coplanar_normals(hull.world_face_normal(g), normal)) members[count++] = g;
    }
  }
  return count;
}

}  // namespace

void coplanar_patch(const PosedHull& hull, int face, ClipPolygon& out) {
  int members[kMaxPatchFaces];
  const int count = gather_patch(hull, face, members);
  if (count == 1) return face_loop(hull, face, out);
  // The patch's boundary: the loop steps whose other side is outside it.
  int from[kMaxPatchEdges], to[kMaxPatchEdges], edges = 0;
  for (int i = 0; i < count; ++i) {
    const int f = members[i], n = hull.face_size(f);
    for (int k = 0; k < n && edges < kMaxPatchEdges; ++k) {
      const int a = hull.face_vertex(f, k), b = hull.face_vertex(f, (k + 1) % n);
      if (!contains(members, count, hull.face_across_step(f, k))) from[edges] = a, to[edges++] = b;
    }
  }
  // Chain the steps into one loop; it keeps the faces' counter-clockwise turn.
  out.clear();
  int current = 0;
  for (int step = 0; step < edges; ++step) {
    out.push(hull.world_vertex(from[current]));
    int next = -1;
    for (int j = 0; j < edges && next < 0; ++j)
      if (from[j] == to[current]) next = j;
    if (next <= 0) break;  // closed (or, on a malformed hull, broken)
    current = next;
  }
}

double patch_area(const PosedHull& hull, int face) {
  ClipPolygon loop;
  coplanar_patch(hull, face, loop);
  Vec3 twice = Vec3::Zero();
  for (int k = 0; k < loop.size(); ++k) twice += loop[k].cross(loop[(k + 1) % loop.size()]);
  return 0.5 * std::abs(twice.dot(hull.world_face_normal(face)));
}

}  // namespace mfz

// F2: a hull whose faces arrive triangulated still clips against, and is
// clipped as, the whole planar face.
#include "generator/coplanar_patch.h"

#include <algorithm>
#include <cstdint>

#include "generator/clipping_generator.h"

namespace mfz {

namespace {

/// Fixed capacity of a coplanar patch's boundary edges.
constexpr int kMaxPatchEdges = kMaxPatchLoop;

// The faces of a patch, in the order gathered, with a mark per face for
// the first kMarkedFaces faces of a hull: a search of the list per step
// grew with the patch's square, and a triangulated 30-gon cap, gathered
// once per triangle, spent 70% of its gather there.
class PatchMembers {
 public:
  explicit PatchMembers(int first) { add(first); }
  int size() const { return count_; }
  int operator[](int i) const { return faces_[i]; }
  bool full() const { return count_ == kMaxPatchFaces; }
  bool has(int face) const {
    if (face < 0) return false;  // no face across: a malformed hull's open edge
    if (face < kMarkedFaces) return (marks_[face / 64] >> (face % 64)) & 1u;
    return std::find(faces_, faces_ + count_, face) != faces_ + count_;
  }
  void add(int face) {
    if (face < kMarkedFaces) marks_[face / 64] |= uint64_t{1} << (face % 64);
    faces_[count_++] = face;
  }

 private:
  static constexpr int kMarkedFaces = 2048;
  uint64_t marks_[kMarkedFaces / 64] = {};
  int faces_[kMaxPatchFaces];
  int count_ = 0;
};

// Grows the patch breadth first across flat steps: a face joins when its
// normal is within the coplanar sine of the face it is reached from, the
// same test that makes the step between them no edge of the polyhedron
// (is_flat_step, F4). The patch is then every face joined to the first by
// flat steps, the same from whichever of them it starts, and its boundary
// is edges of the polyhedron. Asked of the first face's normal instead,
// the patch depended on where it started: a disc of 43 triangles whose
// normals lie about 1e-11 apart gave 43 patches of 29 to 31 corners, some
// of them not convex, whose clipped points repeated a reference corner
// five times and, with the vertices renumbered, overflowed the clip
// (vertex-order, manifuzz fuzz --strict, F60, open as O28). A chain of
// faces each within the sine of the last bends by at most the sine per
// face crossed (tolerances.h, kCoplanarSine, says what that allows).
void gather_patch(const PosedHull& hull, PatchMembers& members) {
  for (int i = 0; i < members.size(); ++i) {
    const int f = members[i], n = hull.face_size(f);
    const Vec3 normal = hull.world_face_normal(f);
    for (int k = 0; k < n; ++k) {
      const int g = hull.face_across_step(f, k);
      if (g < 0 || members.full() || members.has(g)) continue;
      if (coplanar_normals(hull.world_face_normal(g), normal)) members.add(g);
    }
  }
}

// Whether a face has a neighbour in its plane: the patch grows from the
// face's own neighbours, so without one it is the face alone.
bool has_coplanar_neighbour(const PosedHull& hull, int face) {
  for (int k = 0; k < hull.face_size(face); ++k)
    if (hull.is_flat_step(face, k)) return true;
  return false;
}

}  // namespace

// A face standing alone (every face of a box, most of a random hull's) is
// its own loop, found without the patch's members: their marks, cleared
// for each patch, were most of a lone face's cost, and patches were 6% of
// a box pair's call.
int patch_loop(const PosedHull& hull, int face, int* loop, int& members, int* faces) {
  const auto own_loop = [&] {
    const int n = std::min(hull.face_size(face), kMaxPatchEdges);
    for (int k = 0; k < n; ++k) loop[k] = hull.face_vertex(face, k);
    return n;
  };
  members = 1;
  if (!has_coplanar_neighbour(hull, face)) return own_loop();
  PatchMembers member(face);
  gather_patch(hull, member);
  members = member.size();
  if (members == 1) return own_loop();
  if (faces)
    for (int i = 0; i < members; ++i) faces[i] = member[i];
  // The patch's boundary: the loop steps whose other side is outside it.
  int from[kMaxPatchEdges], to[kMaxPatchEdges], edges = 0;
  for (int i = 0; i < members; ++i) {
    const int f = member[i], n = hull.face_size(f);
    for (int k = 0; k < n && edges < kMaxPatchEdges; ++k) {
      const int a = hull.face_vertex(f, k), b = hull.face_vertex(f, (k + 1) % n);
      if (!member.has(hull.face_across_step(f, k))) from[edges] = a, to[edges++] = b;
    }
  }
  // Chain the steps into one loop; it keeps the faces' counter-clockwise turn.
  int size = 0, current = 0;
  for (int step = 0; step < edges; ++step) {
    loop[size++] = from[current];
    int next = -1;
    for (int j = 0; j < edges && next < 0; ++j)
      if (from[j] == to[current]) next = j;
    if (next <= 0) break;  // closed (or, on a malformed hull, broken)
    current = next;
  }
  return size;
}

void loop_points(const PosedHull& hull, const int* loop, int size, ClipPolygon& out) {
  out.clear();
  for (int k = 0; k < size; ++k) out.push(hull.world_vertex(loop[k]));
}

void coplanar_patch(const PosedHull& hull, int face, ClipPolygon& out) {
  int loop[kMaxPatchLoop], members = 0;
  loop_points(hull, loop, patch_loop(hull, face, loop, members), out);
}

// From the loop's vertex numbers, not a polygon of its points: SAT asks
// for it, and a polygon of kMaxPolygonVertices points on the stack is 50 KB.
double patch_area(const PosedHull& hull, int face) {
  int loop[kMaxPatchLoop], members = 0;
  const int size = patch_loop(hull, face, loop, members);
  Vec3 twice = Vec3::Zero();
  for (int k = 0; k < size; ++k)
    twice += hull.world_vertex(loop[k]).cross(hull.world_vertex(loop[(k + 1) % size]));
  return 0.5 * std::abs(twice.dot(hull.world_face_normal(face)));
}

}  // namespace mfz

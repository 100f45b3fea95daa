#include "generator/clipping_generator.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "generator/box_axis.h"
#include "generator/clip_polygon.h"
#include "generator/contact_output.h"
#include "generator/coplanar_patch.h"
#include "generator/last_resort_contact.h"
#include "geometry/loop_corners.h"
#include "geometry/tolerances.h"

namespace mfz {

namespace {

// Enough for the apex of a 64-sided pyramid, whose side faces all tie (F15).
constexpr int kMaxTiedFaces = 64;

// Equal to rounding: two tied faces clip their shared edge from both ends.
// Rounding is a few ulps of the coordinates the clip worked with (the
// reference face's, `resolution`) whatever the hull's size: a relative
// 1e-12 was 4500 ulps, and 1e6 L from the origin it merged the corners of a
// slab 1e-6 thick (FINDINGS F19). With a unit `along`, the distance is
// measured across it only, in the column of each point.
//
// F30: a point of a face nearly perpendicular to the reference face has its
// height only to the world's rounding over the cosine, so where it stands in
// the column of a point already kept (to the world's rounding, measured in
// the reference plane) it adds nothing to the region's span, only a depth
// that the moved frame puts elsewhere (rigid-motion, --strict --seed 12: a
// face 1e-6 off perpendicular, 2.3e-10 beside the incident face's corner
// 2e5 L from the origin, 8e-6 L higher). `at_least` is a floor under that
// rounding.
bool holds_point(const ClipPolygon& points, const Vec3& p, double resolution, const Vec3& along = Vec3::Zero(),
                 double at_least = 0) {
  const double same = std::max(at_least, tol::world_rounding(std::max(resolution, p.cwiseAbs().maxCoeff())));
  for (int k = 0; k < points.size(); ++k) {
    const Vec3 apart = points[k] - p;
    if ((apart - apart.dot(along) * along).norm() <= same) return true;
  }
  return false;
}

double largest_coordinate(const ClipPolygon& polygon) {
  double largest = 0;
  for (int k = 0; k < polygon.size(); ++k) largest = std::max(largest, polygon[k].cwiseAbs().maxCoeff());
  return largest;
}

}  // namespace

namespace {

// Callers test `trace` first: building the message would allocate.
void record(ClipTrace* trace, std::string what, const ClipPolygon& polygon) {
  ClipTrace::Step step{std::move(what), {}};
  for (int k = 0; k < polygon.size(); ++k) step.polygon.push_back(polygon[k]);
  trace->steps.push_back(std::move(step));
}

// Whether face f of the incident hull clips to nothing against the kept
// sides of the reference prism, decided before its patch is gathered: its
// own loop lies wholly outside one side, beyond the clip's band for those
// points (side_bands), and no neighbour is coplanar, so that its loop is
// the polygon coplanar_patch would give. The same points against the same
// planes, with a band no narrower: clip_to_plane would keep none. F27's
// faces are most of a large hull's near half, and nearly all lie beside a
// small reference face (a 128-point pair clipped 100 faces a call for a
// handful of points, 15% of the call). A face of a larger patch is clipped
// as before even so: the patch's points inside the prism lie in its other
// faces, which would give them too, but starting from another corner, in
// another order.
bool lone_face_clips_to_nothing(const PosedHull& incident, int f, const ClipFace& reference) {
  const PrismSides* sides = reference.sides;
  if (!sides || sides->count == 0) return false;
  const int n = incident.face_size(f);
  // The hull's reach bounds its loop's largest coordinate: a band at least
  // the clip's, so that a face outside it is outside the clip's. Twice the
  // reach bounds every edge a clip of the face can make, so that no edge of
  // its points, all further out than this, lies in the plane (F53).
  const double reach = incident.reach_from_origin();
  const double on_plane =
      std::max(tol::world_rounding(std::max(sides->largest, reach)), tol::kCoplanarSine * 2 * reach);
  bool outside = false;
  for (int s = 0; s < sides->count && !outside; ++s) {
    if (!sides->spans[s]) continue;
    outside = true;
    for (int k = 0; k < n && outside; ++k)
      outside = sides->plane[s].signed_distance(incident.world_face_point(f, k)) > on_plane;
  }
  if (!outside) return false;
  const Vec3 normal = incident.world_face_normal(f);
  for (int k = 0; k < n; ++k) {
    const int g = incident.face_across_step(f, k);
    if (g >= 0 && coplanar_normals(incident.world_face_normal(g), normal)) return false;
  }
  return true;
}

// Whether face f of the incident hull, met by F27, would add nothing: its
// own loop (no neighbour is coplanar) lies inside every side and cap of
// the reference prism, so the clip gives it back as it is, and each corner
// that the points above the reference plane leave behind is one of the
// points already held, to the bit, which holds_point finds at no distance.
// The faces beside a box's incident face are such faces: they lean toward
// the reference face and reach below its plane by the incident face's
// edge alone (two a call on the box families, 17% of the call, for 758
// points over 201 calls and none kept), and so are most of the side faces
// of a cylinder standing on another's cap.
bool lone_face_adds_nothing(const PosedHull& incident, int f, const ClipFace& reference,
                            const Plane& reference_plane, const ClipPolygon& held) {
  const PrismSides* sides = reference.sides;
  if (!sides || sides->count == 0) return false;
  const int n = incident.face_size(f);
  // The corners below the plane first: most faces of a hull in deep
  // contact have one that is not held, and fail at once.
  for (int k = 0; k < n; ++k) {
    const Vec3 p = incident.world_face_point(f, k);
    if (reference_plane.signed_distance(p) > 0) continue;  // removed above the reference plane
    bool is_held = false;
    for (int h = 0; h < held.size() && !is_held; ++h) is_held = held[h] == p;
    if (!is_held) return false;
  }
  for (int k = 0; k < n; ++k) {
    const Vec3 p = incident.world_face_point(f, k);
    for (int s = 0; s < sides->count; ++s)
      if (sides->spans[s] && !(sides->plane[s].signed_distance(p) <= 0)) return false;
    for (int c = 0; c < sides->cap_count; ++c)
      if (!(sides->cap[c].signed_distance(p) <= 0)) return false;
  }
  const Vec3 normal = incident.world_face_normal(f);
  for (int k = 0; k < n; ++k) {
    const int g = incident.face_across_step(f, k);
    if (g >= 0 && coplanar_normals(incident.world_face_normal(g), normal)) return false;
  }
  return true;
}

// The loops of the multi-face patches F27 has clipped in one call. A
// triangulated face is met once per triangle, and each gathers the same
// patch: its loop from another corner, which clips to the same points in
// turned order (clip_to_plane walks the loop round from any corner), all
// of them held already. A triangulated 30-gon cap below a large reference
// face clipped its whole patch 30 times, three-quarters of the call (fuzz
// inputs of triangulated 60-point hulls took 12 ms each).
class ClippedPatches {
 public:
  // Whether `loop` is a kept loop turned to start at another corner.
  bool holds(const int* loop, int size) const {
    for (int p = 0; p < count_; ++p) {
      const int* kept = ints_ + start_[p];
      if (start_[p + 1] - start_[p] != size) continue;
      const int* first = std::find(kept, kept + size, loop[0]);
      if (first == kept + size) continue;
      const int turn = static_cast<int>(first - kept);
      bool same = true;
      for (int k = 1; k < size && same; ++k) same = kept[(turn + k) % size] == loop[k];
      if (same) return true;
    }
    return false;
  }
  void clear() { count_ = 0; }
  // Kept while there is room; a loop not kept is clipped again when met.
  bool keep(const int* loop, int size) {
    if (count_ == kLoops || start_[count_] + size > kInts) return false;
    std::copy(loop, loop + size, ints_ + start_[count_]);
    start_[count_ + 1] = start_[count_] + size;
    ++count_;
    return true;
  }

 private:
  static constexpr int kLoops = 64, kInts = 1024;
  int ints_[kInts];
  int start_[kLoops + 1] = {0};
  int count_ = 0;
};

// The faces of the patches ClippedPatches holds: met again, such a face is
// passed by before its patch is gathered. Gathered from any of its faces,
// the patch is the same faces (coplanar_patch.h), so its loop is the kept
// one turned, and ClippedPatches would pass it by after the gather. A
// triangulated 64-gon cap met F27 61 times a call, and each gathered the
// whole cap again: 64-gon cylinders with triangulated faces spent three
// quarters of a call there. Until F60 a patch was gathered against the
// normal of the face it started from, and only a patch whose faces shared
// one normal to the bit could be passed by.
class ClippedPatchFaces {
 public:
  bool has(int face) const { return face < kFaces && ((marks_[face / 64] >> (face % 64)) & 1u); }
  void clear() {
    if (any_) std::fill(marks_, marks_ + kFaces / 64, uint64_t{0});
    any_ = false;
  }
  // The patch's faces, when not past the gather's room (a patch that fills
  // it may gather otherwise from another face).
  void mark(const int* faces, int count) {
    if (count >= kMaxPatchFaces) return;
    for (int i = 0; i < count; ++i)
      if (faces[i] < kFaces) marks_[faces[i] / 64] |= uint64_t{1} << (faces[i] % 64), any_ = true;
  }

 private:
  static constexpr int kFaces = 2048;
  uint64_t marks_[kFaces / 64] = {};
  bool any_ = false;
};

// A call's polygons and F27's records, kept per thread and reached once per
// call, not on the call's stack: five polygons of 512 points are 64 KB, and
// with them on the stack a call took 95.5 KB of it where the speed issue
// asked for tens of kilobytes (an engine's job threads and fibres run
// collision on small stacks). Reached once: a plugin reaches its
// thread-local storage through a call each time, and a static per
// function, reached on every clip, cost boxes 3% more instructions. A call
// runs to its end before the thread makes another.
struct ClipWorkspace {
  ClipPolygon reference, incident, clipped;
  ClipPolygon below;  // F27's faces below the reference plane, in turn
  // F50: a face of each tied with equal areas, the other way round: the
  // incident face as the reference face, its prism's sides, and the points
  // of the reference hull's faces below its plane.
  ClipPolygon other_reference, other_way;
  PrismSides other_sides;
  ClipPolygon scratch;  // the clip's other buffer (ClipFace::scratch)
  ClippedPatches patches;
  ClippedPatchFaces patch_faces_clipped;
  int corners[kMaxPatchLoop];
  int patch_faces[kMaxPatchFaces];
  // Their clipped points, each with its height over the reference plane,
  // waiting to be added deepest first.
  std::array<std::pair<double, Vec3>, 2 * kMaxPolygonVertices> below_points;
  int below_order[2 * kMaxPolygonVertices];
  bool below_kept[2 * kMaxPolygonVertices];
  // 5.3 KB: on the stack, the sanitized build's call took 64,632 bytes of
  // the 64 KiB a fibre may have.
  PrismSides sides;
};

// Past the ABI's capacity the incident faces' and F27's points, a cloud in
// no loop order, give way to the corners of their outline seen along the
// reference normal, reduced as a loop, and the deepest point: the contacts
// still span the region F27's faces reach, and still hold the depth. Only
// points below the reference plane count: one on it is no contact, and a
// 59-point hull's faces met the plane in an outline wider than its incident
// face, whose 14 points at the full depth were then all dropped. The
// incident faces' points alone, kept past the capacity before, lost the
// region (F55: a needle cone's ridge 1.5e-4 rad off the reference face, its
// incident face a rim face 5.7 degrees off, contacts within 0.003 of the
// base where the first-touching region reached 0.5 up the ridge;
// spans-contact-region, manifuzz fuzz --strict, open as O21).
void keep_outline_and_deepest(ClipPolygon& points, const Plane& reference_plane, ClipPolygon& scratch) {
  for (int k = points.size() - 1; k >= 0; --k)
    if (!(reference_plane.signed_distance(points[k]) < 0)) points.erase(k);
  if (points.size() <= MFZ_MAX_CONTACTS) return;
  int deepest = 0;
  double least = reference_plane.signed_distance(points[0]);
  for (int k = 1; k < points.size(); ++k)
    if (const double d = reference_plane.signed_distance(points[k]); d < least) least = d, deepest = k;
  const Vec3 deepest_point = points[deepest];
  const bool deepest_crossing = points.is_crossing(deepest);
  keep_outline(points, reference_plane.normal, scratch);
  reduce_polygon(points, MFZ_MAX_CONTACTS - 1);
  for (int k = 0; k < points.size(); ++k)
    if (points[k] == deepest_point) return;
  points.push(deepest_point, deepest_crossing);
}

// This thread's workspace, looked up once by each call that holds it.
[[gnu::noinline]] ClipWorkspace& thread_workspace() {
  static thread_local ClipWorkspace work;
  return work;
}

double loop_perimeter(const ClipPolygon& loop) {
  double perimeter = 0;
  for (int k = 0; k < loop.size(); ++k) perimeter += (loop[next_corner(k, loop.size())] - loop[k]).norm();
  return perimeter;
}

// The loop's area, its corners taken from the first so that a loop far
// from the frame's centre keeps its digits.
double loop_area(const ClipPolygon& loop, const Vec3& normal) {
  Vec3 twice = Vec3::Zero();
  for (int k = 1; k + 1 < loop.size(); ++k) twice += (loop[k] - loop[0]).cross(loop[k + 1] - loop[0]);
  return 0.5 * std::abs(twice.dot(normal));
}

// F27: the other faces of the incident hull that face the reference face and
// reach below its plane, each clipped as the incident face is; their points
// are added to `clipped` (each once). True when one was added. The faces
// held for the support alone (F58, `support_faces`) are among them whether
// they face the reference face or not, as F24 clipped them.
bool add_faces_below_reference(const PosedHull& incident, const int* done, int done_count,
                               const ClipFace& reference, const Plane& reference_plane, const ClippingSteps& steps,
                               double world_resolution, ClipWorkspace& work, ClipPolygon& clipped,
                               const int* support_faces = nullptr, int support_count = 0) {
  bool added = false;
  // F33: the world's rounding alone made the column a frame's choice. A face
  // 1.1e-6 rad off perpendicular stood 2.3e-10 beside a kept point, 2.1e-4
  // higher: within the rounding 1e4 L out, beyond it at the origin, and
  // far-from-origin dropped the point the original kept (--strict --seed
  // 2026112503). Within a small part of the reference face's perimeter it
  // adds nothing to the region's span, and the perimeter is the same in every
  // frame (a bounding box's diagonal is not: turned, it moved the column
  // past a point 1.4e-9 beside a cylinder's, rigid-motion, the same seed).
  // F46: the column must also stand well clear of the world's rounding,
  // which still widened it far out. 3e5 L from the origin, 1e-9 of the
  // perimeter (3.6e-9) was below the rounding (4.3e-9, and 4.6e-9 moved
  // 2.7e4 further), and a slab's edge 1e-3 long, 4.4e-6 rad off the normal,
  // stood 4.4e-9 beside the kept point at its deeper end: the moved frame
  // dropped its other end, the case's frame kept it, 1e-3 from every
  // contact (far-from-origin, --strict --seed 946867892, open as O13).
  // A face's perimeter is at most pi times its hull's diameter, so 1e-7 of
  // it is under a third of what a relation or the region's span can tell
  // (1e-6 L), and it is 80 times the rounding that far out.
  constexpr double kColumnOverPerimeter = 1e-7;
  // Measured once a point waits: a call whose faces all add nothing (a
  // box's) needs no column.
  double column = -1;
  // The shortcut stands for the built-in's own steps only: a mutant's
  // patch or clip is run as it is.
  const bool builtin_clip = steps.face_polygon == coplanar_patch && steps.clip_to_sides == clip_to_reference_prism;
  ClipPolygon& polygon = work.below;
  ClippedPatches& patches = work.patches;
  ClippedPatchFaces& clipped_faces = work.patch_faces_clipped;
  int* corners = work.corners;
  patches.clear();
  clipped_faces.clear();
  // A point in a column that a point already added stands in adds nothing
  // to the region's span, and is left out. Every face's points wait, and
  // the column test takes them deepest first (lower coordinates first
  // between equals, the same point once, where it first came), so that a
  // column keeps its deepest point in any numbering; those kept are then
  // added in the faces' order, as before, so a call whose points share no
  // column answers as it did. Taken in the faces' order, two faces beside a
  // corner poking 3.9e-4 through a face next to its corner clipped to
  // points 2.2e-7 apart, in one column of 2.6e-7 but 1.5e-5 apart in depth,
  // and the hulls renumbered kept the other one (F49, vertex-order,
  // manifuzz check --strict --family boxes --seed 2026112847).
  auto& below_points = work.below_points;
  int* by_depth = work.below_order;
  bool* kept = work.below_kept;
  int waiting = 0;
  const auto add_deepest_first = [&] {
    if (waiting == 0) return;
    if (column < 0) column = kColumnOverPerimeter * loop_perimeter(*reference.polygon);
    for (int k = 0; k < waiting; ++k) by_depth[k] = k, kept[k] = false;
    std::sort(by_depth, by_depth + waiting, [&](int i, int j) {
      const auto &x = below_points[i], &y = below_points[j];
      if (x.first != y.first) return x.first < y.first;
      if (x.second != y.second)
        return std::lexicographical_compare(x.second.data(), x.second.data() + 3, y.second.data(), y.second.data() + 3);
      return i < j;  // the same point twice: the first, as before
    });
    const int before = clipped.size();
    for (int k = 0; k < waiting; ++k) {
      const Vec3& p = below_points[by_depth[k]].second;
      // The same point again, which the sort puts beside the first (a
      // vertex inside the prism comes once from each face around it): the
      // first was held or added, so this one is held by the same point or
      // by the first (or, the polygon full, fails as the first did), and
      // the column test need not look. A 128-point pair's F27 waited with
      // 61 points a call and tested each against every point kept.
      if (k > 0 && p == below_points[by_depth[k - 1]].second) continue;
      if (holds_point(clipped, p, world_resolution, reference.normal, column)) continue;
      if (clipped.push(p)) kept[by_depth[k]] = true;
    }
    while (clipped.size() > before) clipped.erase(clipped.size() - 1);
    for (int k = 0; k < waiting; ++k)
      if (kept[k]) added = clipped.push(below_points[k].second) || added;
    waiting = 0;
  };
  incident.turn_face_normals();
  for (int f = 0; f < incident.face_count(); ++f) {
    if (std::find(done, done + done_count, f) != done + done_count) continue;
    const bool holds_support = std::find(support_faces, support_faces + support_count, f) != support_faces + support_count;
    if (!holds_support && !(incident.world_face_normal(f).dot(reference.normal) < -tol::kFacingCosine)) continue;
    bool reaches_below = false;
    for (int k = 0; k < incident.face_size(f) && !reaches_below; ++k)
      reaches_below = reference_plane.signed_distance(incident.world_face_point(f, k)) < 0;
    if (!reaches_below || clipped_faces.has(f)) continue;
    if (builtin_clip && lone_face_clips_to_nothing(incident, f, reference)) continue;
    if (builtin_clip && lone_face_adds_nothing(incident, f, reference, reference_plane, clipped)) continue;
    if (builtin_clip) {
      int members = 0;
      const int size = patch_loop(incident, f, corners, members, work.patch_faces);
      if (members > 1 && size > 0) {
        if (patches.holds(corners, size)) continue;
        if (patches.keep(corners, size)) clipped_faces.mark(work.patch_faces, members);
      }
      loop_points(incident, corners, size, polygon);
    } else {
      steps.face_polygon(incident, f, polygon);
    }
    if (polygon.size() + reference.polygon->size() >= kMaxPolygonVertices) continue;
    if (!steps.clip_to_sides(reference, polygon, nullptr)) continue;
    remove_points_outside(polygon, reference_plane);
    for (int k = 0; k < polygon.size(); ++k) {
      if (waiting == static_cast<int>(below_points.size())) add_deepest_first();
      below_points[waiting++] = {reference_plane.signed_distance(polygon[k]), polygon[k]};
    }
  }
  add_deepest_first();
  return added;
}

// F50: a face of each hull along the axis, antiparallel and so with the
// same overlap, whose patches have the same area to rounding: F14 leaves
// the reference face to the order of the hulls, and F27 reaches only into
// the incident hull, below the reference plane. A pyramid deep in a hull,
// its base tied with the hull's face of the same area, took five points of
// the hull's sloping faces one way round and none the other, the pyramid's
// sides facing away (swap-symmetry, 0.107 L, --strict --family
// near-coplanar,coplanar-grid,duplicates,slab,needle --seed 2026112868,
// F50, open as O16). Such a tie is clipped the other way round too: the
// incident face stands as a reference face, and the reference hull's faces
// that reach below its plane add their points, held against the incident
// faces' points alone, as F27's are, so that either order gives the same
// contacts. The area is of the faces' patches (a triangulated face weighs
// as the face), so the tie is decided alike where a triangle of it is the
// face. Returns how many points it gives, in work.other_way; `incident`
// is then a reference face, with its polygon and its prism's sides.
int add_faces_below_incident_face(const ClipFace& reference, ClipFace& incident, const ClipPolygon& incident_points,
                                  const ClippingSteps& steps, double world_resolution, ClipWorkspace& work) {
  if (!coplanar_normals(reference.normal, -incident.normal)) return 0;
  ClipPolygon& loop = work.other_reference;
  steps.face_polygon(*incident.hull, incident.index, loop);
  const ClipPolygon& reference_loop = *reference.polygon;
  const double area = loop_area(loop, incident.normal), reference_area = loop_area(reference_loop, reference.normal);
  const double largest = std::max({largest_coordinate(loop), largest_coordinate(reference_loop), world_resolution});
  // F59: the areas' room is their perimeters times the world's rounding,
  // and never less than their perimeters times 1e-8 of the hulls' span, so
  // that the frame does not decide the tie: the rounding alone, 1.4e8 from
  // the origin, joined two triangles 5e7 in area and 0.087 apart that it
  // held apart at the origin, and the far run had a contact 1,996 from the
  // case's (far-from-origin, manifuzz fuzz --strict, open as O26). 1e-8 of
  // the span is 70 times the rounding 1e4 L out.
  constexpr double kAreaTieOverSpan = 1e-8;
  const double span = std::max(reference.hull->span(), incident.hull->span());
  const double per_length = std::max(tol::world_rounding(largest), kAreaTieOverSpan * span);
  const double room = per_length * (loop_perimeter(loop) + loop_perimeter(reference_loop));
  if (!(std::abs(area - reference_area) <= tol::kTie * std::max(area, reference_area) + room)) return 0;
  incident.polygon = &loop;
  incident.world_resolution = world_resolution;
  incident.scratch = &work.scratch;
  keep_prism_sides(incident, work.other_sides);
  incident.sides = &work.other_sides;
  const Plane incident_plane{incident.normal, incident.normal.dot(incident.hull->world_face_point(incident.index, 0))};
  ClipPolygon& points = work.other_way;
  points.take(incident_points);
  const int held = points.size();
  add_faces_below_reference(*reference.hull, &reference.index, 1, incident, incident_plane, steps,
                            std::max(work.other_sides.largest, world_resolution), work, points);
  for (int k = 0; k < held; ++k) points.erase(0);
  return points.size();
}

}  // namespace

void face_loop(const PosedHull& hull, int face, ClipPolygon& out) {
  out.clear();
  for (int k = 0; k < hull.face_size(face); ++k) out.push(hull.world_face_point(face, k));
}

SideBands side_bands(const ClipFace& reference, const ClipPolygon& incident) {
  // F23: an incident edge that lies in a side plane is on it, not across it
  // by a rounding error at each end.
  // The reference loop's largest coordinate is kept with its sides.
  const double reference_largest = reference.sides ? reference.sides->largest : largest_coordinate(*reference.polygon);
  const double incident_largest = largest_coordinate(incident);
  const double on_plane = tol::world_rounding(std::max(reference_largest, incident_largest));
  // F32: B's corners carry the rounding of the world's positions into the
  // frame, so a corner that far outside a side plane may be inside it in
  // another frame: its edge crosses at the corner's foot on the plane, not
  // where the edge, 6e-7 rad off the plane, met it 2.4e-6 along (a corner
  // 1.5e-12 out, 1.8e4 L from the origin; rigid-motion, manifuzz check
  // --seed 2026112502). Widening F23's band instead kept such corners
  // unclipped, up to 2e-6 outside a needle's tip 1e4 L out (h7's case).
  // F53: an incident edge within the generator's coplanarity of a side
  // plane lies in it in every frame (clip_to_plane). Clipping keeps the
  // polygon within its corners' hull, so no edge it makes is longer than
  // twice their reach, sqrt(3) times their largest coordinate.
  const double longest_edge = 2 * std::sqrt(3.0) * incident_largest;
  return {on_plane, std::max(on_plane, tol::world_rounding(reference.world_resolution)), tol::kCoplanarSine,
          tol::kCoplanarSine * longest_edge};
}

bool reference_side(const ClipFace& reference, int k, Plane& side, SideEdge& edge) {
  const ClipPolygon& loop = *reference.polygon;
  const Vec3& from = loop[k];
  const Vec3& to = loop[next_corner(k, loop.size())];
  edge = {from, to};
  // The loop runs counter-clockwise about the outward normal, so edge x
  // normal points out of the face, in its plane. Its length is the edge's
  // (never zero on a validated hull); normalising keeps distances in lengths.
  const Vec3 outward = (to - from).cross(reference.normal);
  const double length = outward.norm();
  if (!(length > 0)) return false;
  side = Plane{outward / length, outward.dot(from) / length};
  return true;
}

// F44, F45: the two sides at a corner of angle t cross where the clip puts
// the corner only to their rounding over sin t, along its bisector. The cap
// through the corner across its bisector is known to the rounding of the
// corner itself, since its direction comes from the two long edges, not
// from their crossing. A sliver face 1.3e-3 long with a corner of sine
// 9e-11 let a face below the reference plane keep a point 1.26e-6 L past
// that corner (open as O11); a needle face 28 long, its base 3.4e-13 wide
// (t = 1.2e-14), 5e5 from the origin, let a contact stand 4.97e-4 past its
// tip, outside the hull, the sides' rounding over t being longer than the
// needle (far-from-origin, open as O12).
//
// `band` is how far outside a side a point may be kept: the rounding, or
// F66's wider band (acute_corner_cap).
bool corner_cap(const ClipPolygon& loop, int k, double rounding, double band, Plane& cap) {
  // Directions known to 1e-3 rad at worst: an acute corner's caps may lean
  // by nearly 45 degrees and still leave the polygon behind them.
  constexpr double kEdgeOverRounding = 1e3;
  const int n = loop.size();
  const Vec3& corner = loop[k];
  const Vec3 in = corner - loop[previous_corner(k, n)], out = loop[next_corner(k, n)] - corner;
  // Every corner is tested, on every call: in squares, with no root or
  // quotient until a corner proves sharp.
  if (!(in.dot(out) < 0)) return false;  // a right or obtuse corner
  const double in_squared = in.squaredNorm(), out_squared = out.squaredNorm();
  const double shortest = kEdgeOverRounding * rounding;
  if (!(std::min(in_squared, out_squared) > shortest * shortest)) return false;
  // sin t = |in x out| / (|in| |out|); sharp where sin t 1e-9 |longer| < band.
  const double sine_squared = in.cross(out).squaredNorm() / in_squared / out_squared;
  const double bound = band / tol::kTie;
  if (!(sine_squared * std::max(in_squared, out_squared) < bound * bound)) return false;
  const Vec3 along_in = in / std::sqrt(in_squared), along_out = out / std::sqrt(out_squared);
  // |along_in - along_out| is at least sqrt(2) at an acute corner.
  const Vec3 bisector = (along_in - along_out).normalized();
  cap = Plane{bisector, bisector.dot(corner)};
  return true;
}

bool sharp_corner_cap(const ClipPolygon& loop, int k, double rounding, Plane& cap) {
  return corner_cap(loop, k, rounding, rounding, cap);
}

// F66: F53 keeps an incident edge whole where it lies in a side plane to
// the coplanar sine, its ends up to that sine times its length outside
// (SideBands::in_plane_band); at a corner of sine t such an end may stand
// that band over t beyond the corner, along the other side, inside both.
// A reference sliver 1.6e9 long, its tip's sine 6.1e-4, and an edge of the
// incident hull 1e-9 rad off the side through one of its long edges: the
// edge's end 10 past the tip, 6.1e-3 outside that side, within the band
// (5.7), and on the other side's plane, was a contact 10 off the sliver's
// hull, where the cap a sharp corner gets asks the rounding (2.3e-5) over
// t to reach past 1e-9 of the edge (vertex-order, manifuzz fuzz
// --max-points 8). Where a side kept such an end, every corner where that
// band over t reaches so far is capped, as a sharp corner is.
bool acute_corner_cap(const ClipPolygon& loop, int k, double rounding, double in_plane_band, Plane& cap) {
  return corner_cap(loop, k, rounding, std::max(rounding, in_plane_band), cap);
}

// F57: an edge of the reference loop too short for the world's rounding to
// give it a direction gives no side, or one that points anywhere: a sliver
// face of B, two of its corners 1e-14 apart, 1.6e5 from the origin, lost
// the side through that edge, and its prism, between two long sides 1e-14
// rad apart, lay open past it: a point of A's face 9,000 beyond the sliver
// was a contact, off B's surface (rigid-motion, manifuzz fuzz --strict).
// The prism is closed there by a cap through the short edge, its normal
// the bisector of the long edges either side, which the rounding does not
// turn: at a convex corner the loop lies behind it, as behind a sharp
// corner's cap. Where those edges run on in one line, their sides bound
// the prism already. The side through the short edge stays, held between
// its neighbours' (F64, hold_side_between_neighbours).
bool short_edge_cap(const ClipPolygon& loop, int k, double rounding, Plane& cap) {
  constexpr double kEdgeOverRounding = 1e3;
  const int n = loop.size();
  const Vec3& from = loop[k];
  const Vec3& to = loop[next_corner(k, n)];
  const double shortest = kEdgeOverRounding * rounding;
  if (!((to - from).squaredNorm() <= shortest * shortest)) return false;
  const Vec3 in = from - loop[previous_corner(k, n)], out = loop[next_corner(next_corner(k, n), n)] - to;
  if (!(std::min(in.squaredNorm(), out.squaredNorm()) > shortest * shortest)) return false;
  const Vec3 across = in.normalized() - out.normalized();
  if (!(across.squaredNorm() > tol::kTie * tol::kTie)) return false;
  const Vec3 normal = across.normalized();
  cap = Plane{normal, std::max(normal.dot(from), normal.dot(to))};
  return true;
}

// F64: the side through a short edge (short_edge_cap's) has its direction
// from rounding, and where the loop, reflex there to rounding, lets it turn
// past a neighbouring side, it cuts into the loop along that side. On a
// convex loop each side's outward normal lies between its neighbours', so
// such a side is held there: turned past one, it takes that one's normal,
// through the short edge. A hull's two corners 3e-13 apart made a
// reference edge 4e-13 long whose side, turned one way in one argument
// order and another way swapped, cut the incident face 63 from its deepest
// corner in one run and 0.89 in the other, where the swapped run kept a
// second contact (swap-symmetry, manifuzz fuzz --max-points 8). Leaving
// such sides out instead let a cap across a needle's oblique base stand up
// to the base's width beyond it: three contacts 0.3 to 0.7 off needles 3e5
// long within 108 s of fuzzing (stop 69).
void hold_side_between_neighbours(const ClipFace& reference, int k, Plane& side) {
  const ClipPolygon& loop = *reference.polygon;
  const int n = loop.size();
  Plane before, after;
  SideEdge unused;
  if (!reference_side(reference, previous_corner(k, n), before, unused) ||
      !reference_side(reference, next_corner(k, n), after, unused))
    return;
  const Vec3& from = loop[k];
  const Vec3& to = loop[next_corner(k, n)];
  const auto through_edge = [&](const Vec3& normal) {
    side = Plane{normal, std::max(normal.dot(from), normal.dot(to))};
  };
  if (before.normal.cross(side.normal).dot(reference.normal) < 0)
    through_edge(before.normal);
  else if (side.normal.cross(after.normal).dot(reference.normal) < 0)
    through_edge(after.normal);
}

// F65: an acute corner whose edges are too short for a cap's direction
// (sharp_corner_cap asks 1000 times the rounding) gets none, and two sides
// t apart may then cross anywhere along its bisector. The loop's extent
// along its longest edge and across it, each widened by the rounding,
// bounds the prism there instead: four caps the loop lies behind, which
// take nothing away in exact arithmetic. A sliver face 14,142 long and
// 1.2e-8 wide, 1.1e15 from the origin (the rounding there 15.6, its edges
// under the 15,600 a cap asks), let an incident edge cross its side 3e8
// beyond it, and that crossing was a contact (on-surface 0.0038 L,
// far-from-origin, manifuzz fuzz --max-points 8, open as O36).
int extent_caps(const ClipPolygon& loop, const Vec3& normal, double rounding, Plane* caps) {
  constexpr double kEdgeOverRounding = 1e3;
  const int n = loop.size();
  const double shortest = kEdgeOverRounding * rounding;
  bool uncapped = false;
  int longest = 0;
  double longest_squared = -1;
  for (int k = 0; k < n; ++k) {
    const Vec3 in = loop[k] - loop[previous_corner(k, n)], out = loop[next_corner(k, n)] - loop[k];
    uncapped = uncapped || (in.dot(out) < 0 && !(std::min(in.squaredNorm(), out.squaredNorm()) > shortest * shortest));
    if (out.squaredNorm() > longest_squared) longest_squared = out.squaredNorm(), longest = k;
  }
  if (!uncapped || !(longest_squared > 0)) return 0;
  const Vec3 along = (loop[next_corner(longest, n)] - loop[longest]).normalized();
  const Vec3 across = normal.cross(along).normalized();
  int count = 0;
  for (const Vec3& axis : {along, Vec3(-along), across, Vec3(-across)}) {
    double reach = -INFINITY;
    for (int k = 0; k < n; ++k) reach = std::max(reach, axis.dot(loop[k]));
    caps[count++] = Plane{axis, reach + rounding};
  }
  return count;
}

double corner_rounding(const ClipFace& reference) {
  const double largest = reference.sides ? reference.sides->largest : largest_coordinate(*reference.polygon);
  return tol::world_rounding(std::max(largest, reference.world_resolution));
}

void keep_prism_sides(const ClipFace& reference, PrismSides& sides) {
  const int n = reference.polygon->size();
  sides.count = n <= kKeptPrismSides ? n : 0;
  for (int k = 0; k < sides.count; ++k) sides.spans[k] = reference_side(reference, k, sides.plane[k], sides.edge[k]);
  sides.largest = largest_coordinate(*reference.polygon);
  sides.cap_count = 0;
  if (sides.count == 0) return;
  const double rounding = tol::world_rounding(std::max(sides.largest, reference.world_resolution));
  for (int k = 0; k < sides.count && sides.cap_count < PrismSides::kMaxCaps; ++k)
    if (sharp_corner_cap(*reference.polygon, k, rounding, sides.cap[sides.cap_count])) ++sides.cap_count;
  for (int k = 0; k < sides.count && sides.cap_count < PrismSides::kMaxCaps; ++k)
    if (short_edge_cap(*reference.polygon, k, rounding, sides.cap[sides.cap_count])) {
      ++sides.cap_count;
      if (sides.spans[k]) hold_side_between_neighbours(reference, k, sides.plane[k]);
    }
  if (sides.cap_count + kExtentCaps <= PrismSides::kMaxCaps)
    sides.cap_count += extent_caps(*reference.polygon, reference.normal, rounding, sides.cap + sides.cap_count);
}


// F1: the clipping method's contact region is the prism over the reference
// face. The adjacent faces' planes only bound it where those faces stand
// perpendicular; where they slope inwards the region reaches past the face and
// point_on_a leaves the hull.
namespace {

// Whether clip_to_plane would give `polygon` back as it is: every point
// inside the side by its own test, so that no edge crosses it.
bool inside_side(const ClipPolygon& polygon, const Plane& side, double on_plane) {
  for (int k = 0; k < polygon.size(); ++k)
    if (!(side.signed_distance(polygon[k]) <= on_plane)) return false;
  return true;
}

// A side that every point lies inside is passed over: Sutherland-Hodgman
// would copy the polygon, points and crossing marks, unchanged. Most sides
// of a many-sided reference face clip nothing (a 64-gon cylinder's cap
// clipped 28 side faces of the other cylinder a call through its 64 sides,
// a third of the call, to add a point twice in 7,242 faces).
bool clip_to_side(ClipPolygon& incident, const Plane& side, const SideEdge* edge, const SideBands& bands,
                  ClipPolygon& scratch, bool* held_in_plane = nullptr) {
  if (inside_side(incident, side, bands.on_plane)) return true;
  if (!clip_to_plane(incident, side, scratch, bands.on_plane, bands.near_plane, edge, bands.in_plane_sine,
                     bands.in_plane_band, held_in_plane))
    return false;
  incident.take(scratch);
  return true;
}

// After the sides: a cap's crossings lie on the sides' crossings already
// made, and a cap's own foot crossing needs no edge to lie along, every
// point being inside the sides by then.
bool clip_to_sharp_corner_caps(const ClipFace& reference, ClipPolygon& incident, const SideBands& bands,
                               bool held_in_plane, ClipPolygon& scratch, ClipTrace* trace) {
  const PrismSides* kept = reference.sides;
  const auto clip_cap = [&](const Plane& cap) {
    if (!clip_to_side(incident, cap, nullptr, bands, scratch)) return false;
    if (trace) record(trace, "clipped against the cap of a sharp corner of the reference face", incident);
    return true;
  };
  const double rounding = corner_rounding(reference);
  if (held_in_plane) {  // F66
    Plane cap;
    for (int k = 0; k < reference.polygon->size(); ++k)
      if (acute_corner_cap(*reference.polygon, k, rounding, bands.in_plane_band, cap) && !clip_cap(cap)) return false;
  }
  if (kept && kept->count > 0) {
    for (int c = 0; c < kept->cap_count; ++c)
      if (!clip_cap(kept->cap[c])) return false;
    return true;
  }
  Plane cap;
  for (int k = 0; k < reference.polygon->size(); ++k)
    if (sharp_corner_cap(*reference.polygon, k, rounding, cap) && !clip_cap(cap)) return false;
  for (int k = 0; k < reference.polygon->size(); ++k)
    if (short_edge_cap(*reference.polygon, k, rounding, cap) && !clip_cap(cap)) return false;
  Plane extent[kExtentCaps];
  const int extents = extent_caps(*reference.polygon, reference.normal, rounding, extent);
  for (int c = 0; c < extents; ++c)
    if (!clip_cap(extent[c])) return false;
  return true;
}

bool clip_with_scratch(const ClipFace& reference, ClipPolygon& incident, ClipPolygon& scratch, ClipTrace* trace) {
  const SideBands bands = side_bands(reference, incident);
  const bool kept = reference.sides && reference.sides->count > 0;
  const double rounding = kept ? 0 : corner_rounding(reference);
  Plane computed, cap;
  SideEdge computed_edge;
  bool held_in_plane = false;  // an end kept outside a side as its edge lies in it (F53, F66)
  for (int k = 0; k < reference.polygon->size(); ++k) {
    const PrismSide side = prism_side(reference, k, computed, computed_edge);
    if (!side.plane) continue;
    if (!kept && short_edge_cap(*reference.polygon, k, rounding, cap))
      hold_side_between_neighbours(reference, k, computed);  // F64, as keep_prism_sides holds it
    if (!clip_to_side(incident, *side.plane, side.edge, bands, scratch, &held_in_plane)) return false;
    if (trace)
      record(trace, "clipped against the side of the reference prism through edge " + std::to_string(k), incident);
  }
  return clip_to_sharp_corner_caps(reference, incident, bands, held_in_plane, scratch, trace);
}

// Apart, so that its polygon is on the stack only when the caller gave no
// scratch (a test calling the clip on its own).
[[gnu::noinline]] bool clip_with_own_scratch(const ClipFace& reference, ClipPolygon& incident, ClipTrace* trace) {
  ClipPolygon scratch;
  return clip_with_scratch(reference, incident, scratch, trace);
}

}  // namespace

bool clip_to_reference_prism(const ClipFace& reference, ClipPolygon& incident, ClipTrace* trace) {
  return reference.scratch ? clip_with_scratch(reference, incident, *reference.scratch, trace)
                           : clip_with_own_scratch(reference, incident, trace);
}

constexpr int kCoreFromCorners = 8;

// The tutorial's last loop: each clipped point is on the incident face; its depth
// is measured from the closest point of the reference polygon, along n.
void emit_clipped_contacts(const ClipFace& reference, const ClipPolygon& clipped, const Vec3& n, bool flipped,
                   mfz_manifold& out) {
  const ClipPolygon& loop = *reference.polygon;
  // Only a many-sided loop is worth its core: on a box's four sides the
  // pass cost more than the tests it spared (boxes tilted 0.8% more).
  const PolygonCore core = loop.size() >= kCoreFromCorners ? polygon_core(&loop[0], loop.size(), reference.normal)
                                                           : PolygonCore{};
  for (int k = 0; k < clipped.size(); ++k) {
    const Vec3& point = clipped[k];
    const Vec3 on_reference = closest_point_on_polygon(point, &loop[0], loop.size(), reference.normal, core);
    double penetration = (point - on_reference).dot(n);
    if (flipped) penetration = -penetration;
    if (!(penetration < 0)) continue;  // the tutorial's sanity check: above the reference face, not a contact
    if (flipped)
      add_contact(out, point, point + penetration * n, penetration);  // incident face is A's
    else
      add_contact(out, point - penetration * n, point, penetration);  // incident face is B's
  }
}

// The tutorial's single-point branch is for curved shapes, whose "face" is one
// point; a hull's faces have three or more vertices, so it only catches a
// degenerate face handed in through the ABI: the support point is the contact.
bool single_point_contact(const ClipFace& face_a, int support_a, const ClipFace& face_b, int support_b,
                          const Vec3& n, mfz_manifold& out) {
  if (face_a.hull->face_size(face_a.index) < 3) {
    const Vec3 point = face_a.hull->world_vertex(support_a);
    add_contact(out, point, point + out.penetration * n, out.penetration);
    return true;
  }
  if (face_b.hull->face_size(face_b.index) < 3) {
    const Vec3 point = face_b.hull->world_vertex(support_b);
    add_contact(out, point - out.penetration * n, point, out.penetration);
    return true;
  }
  return false;
}

bool more_parallel_is_reference_b(const SatResult& sat, const ClipFace& face_a, const ClipFace& face_b) {
  return std::abs(sat.normal.dot(face_a.normal)) < std::abs(sat.normal.dot(face_b.normal));
}

// F13: the tutorial's "more parallel" rule ties when the other face is parallel
// to rounding, and then the order of the arguments chooses, which swapping A
// and B changes. The face SAT found is the reference face.
bool sat_face_is_reference(const SatResult& sat, const ClipFace& face_a, const ClipFace& face_b) {
  if (sat.kind == AxisKind::face_a) return false;
  if (sat.kind == AxisKind::face_b) return true;
  return more_parallel_is_reference_b(sat, face_a, face_b);
}

ClippingSteps::ClippingSteps()
    : incident_faces(tied_significant_faces),
      face_polygon(coplanar_patch),
      reference_is_b(sat_face_is_reference),
      clip_to_sides(clip_to_reference_prism),
      edge_contact(closest_points_of_edges),
      emit_contacts(emit_clipped_contacts) {}

// Outline of the built-in generator (the tutorial's GenContactPoints, with
// the fixes FINDINGS.md names), in a frame centred on A's position (F21):
//  1. SAT (face normals, then the edge pairs whose Gauss arcs cross) gives
//     the normal n, from A to B, and the depth. A face axis wins a near-tie
//     with an edge axis (F3, F9); a reversed face axis only proves separation
//     (F7). No contacts unless p < 0.
//  2. On an edge-edge axis, every crossing pair of supporting edges is one
//     contact (F3, F6, F12, F20, F22); done.
//  3. Significant faces, A's along n and B's along -n. On a face axis, that
//     face is its hull's (F8). Otherwise, of the faces holding the most of
//     the support vertices (F10, F24), the most parallel one.
//  4. The SAT face is the reference face (F13, F14), the other incident
//     ("flipped" when the reference face is B's). Each stands for the largest
//     patch of coplanar faces around it (F2).
//  5. Every incident face equally aligned (F11, F15) is clipped
//     (Sutherland-Hodgman) against the sides of the prism over the reference
//     face (F1), with a band for edges lying in a side (F23). Then the points
//     above the reference plane are removed, and tied faces' shared points
//     are kept once (F19). The incident hull's other faces that reach below
//     the reference plane are clipped the same way (F27), and so are the
//     faces held for the support alone (F24, F58); where the two
//     faces are a face of each with equal areas, the reference hull's faces
//     below the incident face's plane too (F50).
//  6. Each remaining point is a contact with its own penetration, measured
//     from the reference polygon along n (F50's from the incident face's).
//     Past the ABI's 64, the outline of the points below the reference
//     plane, reduced to 63, and the deepest point (F55).
//  7. Nothing left at a positive depth: the crossing supporting edges (F16),
//     then the deepest vertex inside the reference hull paired with where a
//     ray along n leaves it (F17, F18), then the edge axis the face axis
//     beat by F3's bias (F39).
namespace {

// F39: a face axis that beat an edge axis by less than F3's bias bounds
// the overlap, but no point of either hull need reach its depth: where the
// hulls touch by two edges crossing, clipping, the supporting edges along
// the face normal and the deepest point all come back empty. The edge axis
// it beat is then the answer, its normal and depth with its crossing
// edges' contact. Every pair is tried: the path is rare, and the bounded
// SAT kept no record of the pair it passed over (a tetrahedron 1.4e-9 L
// into a five-point hull, reported colliding with no contact in one
// argument order: swap-symmetry, manifuzz fuzz, O9).
void least_edge_axis_contact(const PosedHull& a, const PosedHull& b, const SatResult& sat, mfz_manifold& out,
                             ClipTrace* trace, const ClippingSteps& steps) {
  if (sat.kind == AxisKind::edge_edge) return;
  const SatResult edge = least_edge_axis(a, b);
  if (edge.separated || !(edge.depth < sat.depth) || !steps.edge_contact(a, b, edge, out)) return;
  out.normal = to_abi(edge.normal);
  out.penetration = -edge.depth;
  if (trace) trace->sat = edge, trace->edge_contact = true;
}

// The edge axes F42 tries lie within this sine of SAT's: rounding picks
// among axes 1e-8 rad apart; an axis further off is another direction,
// whose crossing lies elsewhere. Most pairs fail this at the cost of a
// cross product, before the hulls are projected (boxes tilted a few
// degrees took 10% longer when every pair was projected).
constexpr double kTiedEdgeAxisSine = 1e-6;

// F42: several edge pairs can tie for the axis, a few 1e-8 rad apart (the
// two edges of a sliver side, 2e-8 rad apart, against one long edge), and
// rounding picks one; along it the sliver's corner may stand above the
// edge the other hull's edge crosses, so no supporting pair crosses. Each
// edge pair along SAT's axis and within F3's bias of the depth is then
// tried, in the hulls' order, and the first whose supporting edges cross
// answers with its axis: clipping faces on an edge axis puts points off
// the surfaces (F3). The path runs only where the supporting edges failed
// (rigid-motion, on-surface 0.167 L, manifuzz fuzz; open as O10).
bool tied_edge_axis_contact(const PosedHull& a, const PosedHull& b, const SatResult& sat, mfz_manifold& out,
                            ClipTrace* trace, const ClippingSteps& steps) {
  const double slack = tol::kEdgeAxisBias * std::max(a.span(), b.span()) +
                       tol::world_rounding(std::max(a.reach_from_origin(), b.reach_from_origin()));
  bool found = false;
  a.for_each_edge([&](int ea, int a0, int a1, int face_a) {
    if (a.is_flat_edge(a0, a1, face_a)) return true;
    const Vec3 edge_a = a.world_vertex(a1) - a.world_vertex(a0);
    b.for_each_edge([&](int eb, int b0, int b1, int face_b) {
      if (b.is_flat_edge(b0, b1, face_b)) return true;
      const Vec3 edge_b = b.world_vertex(b1) - b.world_vertex(b0);
      const Vec3 axis = edge_a.cross(edge_b);
      const double length = axis.norm();
      if (length <= tol::kParallelEdges * edge_a.norm() * edge_b.norm()) return true;
      if (!(axis.cross(sat.normal).norm() <= kTiedEdgeAxisSine * length)) return true;
      bool b_along_axis = true;
      const double overlap = overlap_along(a, b, axis / length, b_along_axis);
      if (!(overlap > 0) || !(overlap <= sat.depth + slack)) return true;
      const SatResult tied{false, (b_along_axis ? axis : Vec3(-axis)) / length, overlap, AxisKind::edge_edge, ea, eb};
      found = steps.edge_contact(a, b, tied, out);
      if (found) out.normal = to_abi(tied.normal), out.penetration = -overlap;
      if (found && trace) trace->sat = tied;
      return !found;
    });
    return !found;
  });
  return found;
}

// Step 5's clip, shared by the box path: the reference face's polygon
// (`face_polygon`, the steps' own on the general path) and the sides of its
// prism in `work`, the reference plane, and each of the
// incident faces clipped against the sides, its points above the plane
// removed, and each point kept once in work.clipped (F19). False where a
// buffer would overflow.
bool clip_incident_faces(ClipFace& reference, const ClipFace& incident, const int* incident_faces, int tied,
                         double world_resolution, ClipWorkspace& work, ClipTrace* trace, const ClippingSteps& steps,
                         void (*face_polygon)(const PosedHull&, int, ClipPolygon&), Plane& reference_plane) {
  ClipPolygon &reference_polygon = work.reference, &polygon = work.incident, &clipped = work.clipped;
  reference_polygon.clear(), clipped.clear();
  reference.world_resolution = world_resolution;
  face_polygon(*reference.hull, reference.index, reference_polygon);
  reference.polygon = &reference_polygon;
  reference.scratch = &work.scratch;
  keep_prism_sides(reference, work.sides);
  reference.sides = &work.sides;
  const double resolution = work.sides.largest;
  const Vec3 on_reference = reference.hull->world_face_point(reference.index, 0);
  reference_plane = Plane{reference.normal, reference.normal.dot(on_reference)};
  for (int i = 0; i < tied; ++i) {
    face_polygon(*incident.hull, incident_faces[i], polygon);
    // Each side plane can add one point: refuse rather than overflow.
    if (polygon.size() + reference_polygon.size() >= kMaxPolygonVertices) return false;
    if (trace) record(trace, "incident face " + std::to_string(incident_faces[i]), polygon);
    if (!steps.clip_to_sides(reference, polygon, trace)) return false;
    remove_points_outside(polygon, reference_plane);
    if (trace) record(trace, "points above the reference plane removed", polygon);
    for (int k = 0; k < polygon.size(); ++k) {
      // F11's joined faces share points: each is kept once (F19).
      if (holds_point(clipped, polygon[k], resolution)) continue;
      if (!clipped.push(polygon[k])) return false;
    }
  }
  return true;
}

// The box path (generator/box_axis.h): two boxes whose edge axis clears
// every tie take the supporting edges' closest points, as the general path
// does first. Two boxes whose face axis and
// incident face clear every tie are clipped as below, one incident face
// (its own loop: a box's faces have no coplanar neighbour), F27's faces
// only where they may add a point, and without F50's other way round (the
// faces are not parallel). A box overhanging the reference face's rim is
// cut by a side plane across its leaning side faces too, below the plane,
// and F27 adds those points (a box tilted 3.4 degrees over A's rim gave 3
// contacts where the general path gave 4: BoxPath.AnswersAsTheGeneralPath
// ToTheBit...). Where it gives no contact the general path answers, with
// its fallbacks. True when it answered. Boxes face to face spent half a
// call in SAT and a sixth in F27's faces.
bool clear_box_pair_contacts(const PosedHull& a, const PosedHull& b, double world_resolution, mfz_manifold& out,
                             const ClippingSteps& steps) {
  BoxAxis axis;
  if (!clear_box_axis(a, b, axis)) return false;
  const SatResult& sat = axis.sat;
  out.contact_count = 0;
  out.colliding = 1;
  out.normal = to_abi(sat.normal);
  out.penetration = -sat.depth;
  // An edge pair: the closest points of the supporting edges (F3), as the
  // general path answers first; where they do not cross, its fallbacks.
  if (sat.kind == AxisKind::edge_edge) return steps.edge_contact(a, b, sat, out);
  const bool flipped = sat.kind == AxisKind::face_b;
  ClipFace reference{flipped ? &b : &a, flipped ? sat.feature_b : sat.feature_a, {}};
  const ClipFace incident{flipped ? &a : &b, axis.incident_face, flipped ? a.world_face_normal(axis.incident_face)
                                                                         : b.world_face_normal(axis.incident_face)};
  reference.normal = reference.hull->world_face_normal(reference.index);
  ClipWorkspace& work = thread_workspace();
  Plane reference_plane;
  if (!clip_incident_faces(reference, incident, &incident.index, 1, world_resolution, work, nullptr, steps,
                           face_loop, reference_plane))
    return false;
  if (!axis.side_faces_add_nothing)
    add_faces_below_reference(*incident.hull, &incident.index, 1, reference, reference_plane, steps,
                              std::max(work.sides.largest, world_resolution), work, work.clipped);
  reduce_polygon(work.clipped, MFZ_MAX_CONTACTS);
  steps.emit_contacts(reference, work.clipped, sat.normal, flipped, out);
  return out.contact_count > 0;
}

int32_t generate_in_frame(const mfz_hull& hull_a, const Pose& pose_a, const mfz_hull& hull_b, const Pose& pose_b,
                          double world_resolution, mfz_manifold& out, ClipTrace* trace, const ClippingSteps& steps) {
  const PosedHull a(hull_a, pose_a), b(hull_b, pose_b);
  if (steps.box_path && !trace && clear_box_pair_contacts(a, b, world_resolution, out, steps)) return 0;
  const SatResult sat = steps.sat(a, b);
  if (trace) trace->sat = sat;
  out.contact_count = 0;
  out.colliding = sat.separated ? 0 : 1;
  out.normal = to_abi(sat.normal);
  out.penetration = sat.separated ? 0.0 : -sat.depth;
  if (sat.separated || !(out.penetration < 0)) return 0;
  const Vec3 n = sat.normal;
  if (sat.kind == AxisKind::edge_edge &&
      (steps.edge_contact(a, b, sat, out) || tied_edge_axis_contact(a, b, sat, out, trace, steps))) {
    if (trace) trace->edge_contact = true;
    return 0;
  }

  // F8: on a face axis, that face is its hull's significant face, and the
  // hull's support vertex is asked for only where it is read: a trace, or a
  // face of fewer than three corners (single_point_contact).
  int support_a = -1, support_b = -1;
  ClipFace face_a{&a, sat.kind == AxisKind::face_a ? sat.feature_a : significant_face(a, n, support_a, true), {}};
  ClipFace face_b{&b, sat.kind == AxisKind::face_b ? sat.feature_b : significant_face(b, -n, support_b, true), {}};
  const auto needs_support = [&](const ClipFace& face, int support) {
    return support < 0 && face.index >= 0 && (trace || face.hull->face_size(face.index) < 3);
  };
  if (needs_support(face_a, support_a)) support_a = a.support_vertex(n);
  if (needs_support(face_b, support_b)) support_b = b.support_vertex(-n);
  if (trace) trace->face_a = face_a.index, trace->face_b = face_b.index, trace->support_a = support_a,
             trace->support_b = support_b;
  if (face_a.index < 0 || face_b.index < 0) return 1;  // a vertex in no face: not a hull
  face_a.normal = a.world_face_normal(face_a.index);
  face_b.normal = b.world_face_normal(face_b.index);

  if (single_point_contact(face_a, support_a, face_b, support_b, n, out)) return 0;

  const bool flipped = steps.reference_is_b(sat, face_a, face_b);
  if (trace) trace->flipped = flipped;
  ClipFace& reference = flipped ? face_b : face_a;
  const ClipFace& incident = flipped ? face_a : face_b;
  ClipWorkspace& work = thread_workspace();
  // F11: equally aligned incident faces (a symmetric corner) are all clipped
  // and their contacts joined: picking one would leave the choice to rounding.
  // F58: those held for the support alone are clipped with F27's faces.
  int incident_faces[kMaxTiedFaces] = {incident.index};
  const Vec3 along = flipped ? n : Vec3(-n);
  const int tied = steps.incident_faces(*incident.hull, along, incident_faces, kMaxTiedFaces);
  const int as_parallel = parallel_faces_first(*incident.hull, along, incident_faces, tied);
  Plane reference_plane;
  if (!clip_incident_faces(reference, incident, incident_faces, as_parallel, world_resolution, work, trace, steps,
                           steps.face_polygon, reference_plane))
    return 1;
  ClipPolygon& clipped = work.clipped;
  const double resolution = work.sides.largest;
  // F27: the incident face is one face around the support vertex; another
  // face that reaches below the reference plane (a wedge's other side, a
  // flat edge 5e-8 rad off beside a tilted face) holds part of the contact
  // region too. Each is clipped the same way and its points join, all of
  // them: keeping only the corners of their hull would leave a point on an
  // edge of it to rounding (swap-symmetry, --strict --seed 20261121).
  const int from_incident_faces = clipped.size();
  ClipFace other_way_round = incident;
  int other_way = add_faces_below_incident_face(reference, other_way_round, clipped, steps, world_resolution, work);
  if (other_way > 0 && trace)
    record(trace, "a face of each tied: the reference hull's faces reaching below the incident face's plane",
           work.other_way);
  if (add_faces_below_reference(*incident.hull, incident_faces, as_parallel, reference, reference_plane, steps,
                                std::max(resolution, world_resolution), work, clipped, incident_faces + as_parallel,
                                tied - as_parallel) &&
      trace)
    record(trace, "with the other faces reaching below the reference plane, clipped the same way", clipped);
  // More than the ABI holds: the outline of the contacts and the deepest of
  // them (keep_outline_and_deepest). A reduction of the points in no loop
  // order left a 59-point hull's 67 points without their shape
  // (has-contacts, the second campaign); the incident faces' own points
  // alone, kept for that, left the region F27's faces reach (F55).
  if (clipped.size() + other_way > MFZ_MAX_CONTACTS && clipped.size() + other_way > from_incident_faces) {
    keep_outline_and_deepest(clipped, reference_plane, work.below);
    other_way = 0;
  }
  reduce_polygon(clipped, MFZ_MAX_CONTACTS);
  steps.emit_contacts(reference, clipped, n, flipped, out);
  if (other_way > 0) steps.emit_contacts(other_way_round, work.other_way, n, !flipped, out);
  // F16: where a face axis ties with an edge axis, the edges can cross just
  // beyond the reference face (a fold of 1e-9 rad in the other hull), and the
  // prism clips everything away. The supporting edges then give the contact.
  if (out.contact_count == 0 && steps.edge_contact(a, b, sat, out) && trace) trace->edge_contact = true;
  if (out.contact_count == 0) deepest_point_contact(a, b, n, sat.depth, flipped, out);
  if (out.contact_count == 0) least_edge_axis_contact(a, b, sat, out, trace, steps);
  return 0;
}

void shift_contacts(mfz_manifold& out, const Vec3& by) {
  for (int i = 0; i < out.contact_count; ++i) {
    out.contacts[i].point_on_a = to_abi(Vec3(to_vec(out.contacts[i].point_on_a) + by));
    out.contacts[i].point_on_b = to_abi(Vec3(to_vec(out.contacts[i].point_on_b) + by));
  }
}

}  // namespace

int32_t generate_clipping_manifold(const mfz_hull& hull_a, const mfz_pose& abi_pose_a, const mfz_hull& hull_b,
                                   const mfz_pose& abi_pose_b, mfz_manifold& out, ClipTrace* trace,
                                   const ClippingSteps& steps) {
  const Pose pose_a = Pose::from_abi(abi_pose_a), pose_b = Pose::from_abi(abi_pose_b);
  // F21: the frame is centred on A's position, so that a far frame rounds
  // B's pose once instead of every decision (which edge is deepest, which
  // face ties) by eps M.
  const Vec3 origin = pose_a.position;
  const Pose local_a{Vec3::Zero(), pose_a.orientation}, local_b{pose_b.position - origin, pose_b.orientation};
  // The frame's coordinates are small; the world's rounding is what its
  // positions carry in (F30). It is taken of their lengths, which a turn of
  // the world keeps, not of their largest coordinates, which it changes: a
  // thin wedge's corner stood 63 beside a kept corner's column, 5e15 from
  // the origin, inside the column's rounding of 72 and outside the turned
  // world's, which kept it 2000 higher (F35, rigid-motion, open as O6).
  const double world_resolution = std::max(pose_a.position.norm(), pose_b.position.norm());
  const int32_t status = generate_in_frame(hull_a, local_a, hull_b, local_b, world_resolution, out, trace, steps);
  shift_contacts(out, origin);
  if (trace)
    for (ClipTrace::Step& step : trace->steps)
      for (Vec3& p : step.polygon) p += origin;
  return status;
}

}  // namespace mfz

#pragma once
/// \file
/// Sutherland-Hodgman clipping of a convex polygon in 3-d against planes, on
/// fixed-capacity storage (no heap in the generator's hot path).
#include <algorithm>
#include <array>

#include "geometry/closest_point.h"
#include "geometry/vec.h"

namespace mfz {

/// Room for an incident face and one extra vertex per side plane, for any
/// two faces of hulls the harness takes (case/case_file.h: at most 1,024
/// points, so a face has at most 1,023 corners and two faces clip to at
/// most 2,046 points). At 512, two 256-gon prisms cap to cap were refused
/// (status 1) as more than the clip could hold (F61, found by hand: no
/// family made a face of more than 64 corners).
inline constexpr int kMaxPolygonVertices = 2048;

/// The plane `normal . x = offset`; its inside is `normal . x <= offset`.
/// Left unset when declared (as Vec3 is): the reference prism's kept sides
/// and caps are arrays of 64, set only as far as the loop goes, and setting
/// each on every call cost more than computing a square's four sides.
struct Plane {
  Vec3 normal;
  double offset;
  double signed_distance(const Vec3& p) const { return normal.dot(p) - offset; }
};

/// A polygon of at most kMaxPolygonVertices points, in loop order. Each
/// point knows whether a clip pass made it where an edge crossed a plane (a
/// crossing), or is a corner of the polygon first given (or such a corner
/// moved onto a plane).
class ClipPolygon {
 public:
  int size() const { return size_; }
  bool empty() const { return size_ == 0; }
  const Vec3& operator[](int i) const { return points_[i]; }
  bool is_crossing(int i) const { return crossing_[i]; }
  void clear() { size_ = 0; }
  /// False, and nothing added, when full.
  bool push(const Vec3& p, bool crossing = false) {
    if (size_ == kMaxPolygonVertices) return false;
    crossing_[size_] = crossing;
    points_[size_++] = p;
    return true;
  }
  /// Takes `other`'s points: only the ones in use, not the whole capacity
  /// (50 KiB), which a clip pass per side plane would otherwise copy.
  void take(const ClipPolygon& other) {
    std::copy(other.points_.begin(), other.points_.begin() + other.size_, points_.begin());
    std::copy(other.crossing_.begin(), other.crossing_.begin() + other.size_, crossing_.begin());
    size_ = other.size_;
  }
  void erase(int i) {
    for (int k = i + 1; k < size_; ++k) points_[k - 1] = points_[k], crossing_[k - 1] = crossing_[k];
    --size_;
  }

 private:
  std::array<Vec3, kMaxPolygonVertices> points_;
  std::array<bool, kMaxPolygonVertices> crossing_;
  int size_ = 0;
};

/// The edge of the reference face that a side plane stands on.
struct SideEdge {
  Vec3 from, to;
};

/// One Sutherland-Hodgman pass: keeps the part of `in` inside `plane`, adding
/// the crossing point of every edge that crosses it. `out` must not alias
/// `in`. A point within `on_plane` of the plane is on it: inside, and its own
/// crossing point (0: only a point exactly on the plane). An outside corner
/// (no crossing) within `near_plane` of it (a larger band, at least
/// `on_plane`) crosses at its foot on the plane, where that foot lies on
/// `edge` (when given) to within `near_plane`; an inside corner within
/// `near_plane` of it is its edge's crossing. The ends of an edge that lies
/// in the plane to `in_plane_sine` (both ends within that sine times its
/// length) are inside too, and the edge is kept whole; `in_plane_band` bounds
/// that sine times the longest edge the polygon can have (0: no edge lies
/// in the plane); `held_in_plane`, when given, is set true where such an
/// end further out than `on_plane` was kept (and left as it was otherwise).
/// Returns false if `out` overflowed (cannot happen when in.size() <
/// capacity).
bool clip_to_plane(const ClipPolygon& in, const Plane& plane, ClipPolygon& out, double on_plane = 0,
                   double near_plane = 0, const SideEdge* edge = nullptr, double in_plane_sine = 0,
                   double in_plane_band = 0, bool* held_in_plane = nullptr);

/// The tutorial's last step: drops the points outside `plane` without adding
/// crossing points (it wants contact points, not the clipped polygon).
void remove_points_outside(ClipPolygon& polygon, const Plane& plane);

/// Replaces the points, a cloud in no loop order, by the corners of their
/// convex hull seen along `normal`, counter-clockwise about it; points on
/// the hull's edges are dropped. `scratch` is overwritten. The points the
/// incident faces and F27's faces give are such a cloud, and past the ABI's
/// capacity their outline is what reduce_polygon can shrink (F55).
void keep_outline(ClipPolygon& points, const Vec3& normal, ClipPolygon& scratch);

/// Removes, one at a time, the point whose triangle with its two neighbours
/// has the least area, until at most `capacity` are left: the polygon's shape,
/// and so the support it gives a solver, changes least.
void reduce_polygon(ClipPolygon& polygon, int capacity);

}  // namespace mfz

#pragma once
/// \file
/// A hull of the C ABI seen in world space through its pose, without copying:
/// the generator's hot path reads local vertices and rotates on demand, so a
/// call allocates nothing whatever the hull's size.
#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

#include "manifuzz/abi.h"
#include "geometry/hull_topology.h"
#include "geometry/tolerances.h"
#include "geometry/vec.h"

namespace mfz {

/// The projection of a hull onto a world axis: [min, max] of `axis . x`.
struct Interval {
  double min = std::numeric_limits<double>::infinity();
  double max = -std::numeric_limits<double>::infinity();
};

/// True when two unit face normals belong to one plane (tol::kCoplanarSine).
/// Normals more than 60 degrees apart are not, whatever the rounding of the
/// sine: the dot product alone turns most pairs away (a box's faces).
inline bool coplanar_normals(const Vec3& n1, const Vec3& n2) {
  return n1.dot(n2) > 0.5 && n1.cross(n2).norm() <= tol::kCoplanarSine;
}

/// World vertices are cached on the stack for hulls up to this size (larger
/// hulls are rotated on demand), so SAT's projections are plain dot
/// products; so are the world face normals of hulls of up to kCachedFaces
/// faces. The stack holds a call's two posed hulls, 12 KB each: a hull of
/// more vertices, up to kTopologyMaxVertices, still gets its topology
/// (hull_topology.h) and SAT's edge arcs, and rotates what it reads.
inline constexpr int kCachedVertices = 128;
inline constexpr int kCachedFaces = 2 * kCachedVertices - 4;

/// Hulls of more cached vertices than this are projected by
/// project_columns (AVX2 where the processor has it); smaller ones inline,
/// where a call through the processor's choice would cost more than the
/// wider lanes save.
inline constexpr int kWideProjectionVertices = 16;

/// [min, max] of (ax * x + ay * y) + az * z over the columns' n points: the
/// coordinates apart (x, y, z arrays), so that the loop runs in vector
/// lanes; each dot product is summed in Eigen's order, (x + y) + z, so the
/// interval is the same to the bit.
inline Interval columns_interval(const double* xs, const double* ys, const double* zs, int n, double ax, double ay,
                                 double az) {
  double low = std::numeric_limits<double>::infinity(), high = -low;
#pragma omp simd reduction(min : low) reduction(max : high)
  for (int i = 0; i < n; ++i) {
    const double d = (ax * xs[i] + ay * ys[i]) + az * zs[i];
    low = d < low ? d : low;
    high = d > high ? d : high;
  }
  return {low, high};
}

/// columns_interval built for AVX2 as well, four points at a time where the
/// processor has it (geometry/vector_lanes.h).
Interval project_columns(const double* xs, const double* ys, const double* zs, int n, double ax, double ay,
                         double az);

/// Every one of n points (columns xs, ys, zs) projected onto each of `count`
/// axes (columns ax, ay, az, need not be unit): the least projection of
/// each axis in `lowest`, the greatest in `highest`. Each is the same sum as
/// columns_interval's, (x + y) + z, and min and max are exact, so every
/// bound is the same bits as projecting onto its axis alone. Built for AVX2
/// as well (geometry/vector_lanes.h). The brute-force SAT projects every
/// edge pair's axis this way, a row of them at a time, and SAT on small
/// hulls the axes of the pairs the Gauss-map test keeps.
void project_onto_axes(const double* xs, const double* ys, const double* zs, int n, const double* ax,
                       const double* ay, const double* az, int count, double* lowest, double* highest);

class PosedHull {
 public:
  // It keeps references to the hull and the pose: a temporary of either
  // would dangle once the statement ends (a test's hull posed by a Pose{}
  // written in the call passed under g++ and shared no patch under clang).
  PosedHull(mfz_hull&&, const Pose&) = delete;
  PosedHull(const mfz_hull&, Pose&&) = delete;
  PosedHull(mfz_hull&&, Pose&&) = delete;
  PosedHull(const mfz_hull& hull, const Pose& pose)
      : hull_(hull), pose_(pose), rotation_(pose.orientation.toRotationMatrix()),
        cached_(hull.vertex_count <= kCachedVertices) {
    if (!cached_) return;
    for (int i = 0; i < hull.vertex_count; ++i) {
      world_[i] = rotation_ * local_vertex(i) + pose_.position;
      xs_[i] = world_[i].x(), ys_[i] = world_[i].y(), zs_[i] = world_[i].z();
    }
  }

  /// The loops' topology, or nullptr for a hull too large or not closed.
  /// Looked up on first use: a pair that a face axis separates never needs it.
  const HullTopology* topology() const {
    if (!topology_looked_up_) topology_ = topology_of(hull_), topology_looked_up_ = true;
    return topology_;
  }

  /// The hull as the caller passed it.
  const mfz_hull& abi_hull() const { return hull_; }
  int vertex_count() const { return hull_.vertex_count; }
  int face_count() const { return hull_.face_count; }
  int face_size(int f) const { return hull_.face_offsets[f + 1] - hull_.face_offsets[f]; }
  int face_vertex(int f, int k) const { return hull_.face_vertices[hull_.face_offsets[f] + k]; }
  Vec3 local_vertex(int i) const { return to_vec(hull_.vertices[i]); }
  Vec3 world_vertex(int i) const { return cached_ ? world_[i] : Vec3(rotation_ * local_vertex(i) + pose_.position); }
  Vec3 world_face_normal(int f) const { return normals_turned_ ? normals_[f] : turned_normal(f); }
  /// Turns every face's normal into the frame at once, for the passes that
  /// read them all: SAT's faces, the inner ball, the edge arcs and the faces
  /// reaching below the reference plane each turned them again, 1,800
  /// turns of a 128-point pair's call where 504 do. The same product as
  /// world_face_normal's, so the same bits. Hulls of more faces than
  /// kCachedFaces turn each normal where it is read.
  void turn_face_normals() const {
    if (normals_turned_ || hull_.face_count > kCachedFaces) return;
    for (int f = 0; f < hull_.face_count; ++f) normals_[f] = turned_normal(f);
    normals_turned_ = true;
  }
  /// The turned normals, x y z of each face in turn, once turn_face_normals
  /// has turned them; nullptr for a hull of more faces than kCachedFaces.
  const double* turned_face_normals() const {
    static_assert(sizeof(Vec3) == 3 * sizeof(double), "the normals lie x y z, x y z, ...");
    return normals_turned_ ? normals_[0].data() : nullptr;
  }
  /// Whether the world vertices are cached, as columns too (kCachedVertices).
  bool has_world_columns() const { return cached_; }
  /// The cached world vertices' x, y and z, each an array of vertex_count();
  /// only when has_world_columns().
  const double* world_xs() const { return xs_; }
  const double* world_ys() const { return ys_; }
  const double* world_zs() const { return zs_; }
  /// World position of the k-th vertex of face f's loop.
  Vec3 world_face_point(int f, int k) const { return world_vertex(face_vertex(f, k)); }

  /// The largest distance of a vertex from the frame's origin: what the
  /// rounding of a projection onto any unit axis is a fraction of, however
  /// small the projection (a turn of the frame keeps it). Measured on first
  /// use.
  double reach_from_origin() const {
    if (!(reach_from_origin_ >= 0)) {
      double largest = 0;
      for (int i = 0; i < hull_.vertex_count; ++i) largest = std::max(largest, world_vertex(i).squaredNorm());
      reach_from_origin_ = std::sqrt(largest);
    }
    return reach_from_origin_;
  }

  /// The largest distance of a vertex from vertex 0, in the hull's own
  /// frame: a size no pose changes, between half the diameter and the
  /// diameter, however thin the hull is along any one axis. Measured on
  /// first use.
  double span() const {
    if (!(span_ >= 0)) {
      double largest = 0;
      const Vec3 first = local_vertex(0);
      for (int i = 1; i < hull_.vertex_count; ++i) largest = std::max(largest, (local_vertex(i) - first).squaredNorm());
      span_ = std::sqrt(largest);
    }
    return span_;
  }

  /// Projection of the hull onto a world direction (need not be unit).
  Interval project(const Vec3& world_axis) const {
    if (cached_) {
      const double ax = world_axis.x(), ay = world_axis.y(), az = world_axis.z();
      const int n = hull_.vertex_count;
      return n > kWideProjectionVertices ? project_columns(xs_, ys_, zs_, n, ax, ay, az)
                                         : columns_interval(xs_, ys_, zs_, n, ax, ay, az);
    }
    const Vec3 local_axis = rotation_.transpose() * world_axis;
    Interval range;
    for (int i = 0; i < hull_.vertex_count; ++i) {
      const double d = local_axis.dot(local_vertex(i));
      range.min = d < range.min ? d : range.min;
      range.max = d > range.max ? d : range.max;
    }
    const double shift = world_axis.dot(pose_.position);
    return {range.min + shift, range.max + shift};
  }

  /// project() onto each of `count` world axes (columns ax, ay, az) at once,
  /// by project_onto_axes: the same bits as one axis at a time. Only for a
  /// hull whose world vertices are cached (kCachedVertices).
  void project_onto_axes(const double* ax, const double* ay, const double* az, int count, double* lowest,
                         double* highest) const {
    assert(cached_);
    mfz::project_onto_axes(xs_, ys_, zs_, hull_.vertex_count, ax, ay, az, count, lowest, highest);
  }

  /// Index of the vertex furthest along a world direction; the first of equals.
  int support_vertex(const Vec3& world_direction) const {
    const Vec3 local = rotation_.transpose() * world_direction;
    int best = 0;
    double best_d = -std::numeric_limits<double>::infinity();
    for (int i = 0; i < hull_.vertex_count; ++i) {
      const double d = local.dot(local_vertex(i));
      if (d > best_d) best_d = d, best = i;
    }
    return best;
  }

  /// A vertex furthest along a world direction, found by climbing from
  /// `start` to a neighbour further along until none is: on a convex
  /// polyhedron the first vertex with no neighbour further is a furthest
  /// one, to rounding (vertices within rounding of a face's plane can stop
  /// the climb one short, so callers use it as a bound, not as the answer).
  /// Scans every vertex for a hull without topology. A hull too large for
  /// its world vertices to be cached climbs too, rotating the vertices it
  /// passes: scanning made each of a 1,024-point hull's climbs read all.
  int climb_to_support(const Vec3& world_direction, int start) const {
    const HullTopology* t = topology();
    if (!t) return support_vertex(world_direction);
    if (cached_) return climb(*t, world_direction, start, [this](int i) -> const Vec3& { return world_[i]; });
    return climb(*t, world_direction, start, [this](int i) { return world_vertex(i); });
  }

  /// The face on the other side of the loop step v0 -> v1 of some face, or -1
  /// (an open hull, which the harness never builds).
  int face_across(int v0, int v1) const {
    if (const HullTopology* t = topology()) {
      for (int e = 0; e < t->edge_count(); ++e) {
        const TopologyEdge& edge = t->edge(e);
        if (edge.v0 == v0 && edge.v1 == v1) return edge.twin;
        if (edge.v0 == v1 && edge.v1 == v0) return edge.face;
      }
      return -1;
    }
    for (int f = 0; f < hull_.face_count; ++f) {
      const int n = face_size(f);
      for (int k = 0; k < n; ++k)
        if (face_vertex(f, k) == v1 && face_vertex(f, (k + 1) % n) == v0) return f;
    }
    return -1;
  }

  /// True when the loop step v0 -> v1 of `face` lies between two coplanar
  /// faces (a triangulated face's diagonal): no edge of the polyhedron, so it
  /// spans no SAT axis (F4) and supports no edge contact (F22). Scans loops:
  /// ask it only of an edge about to count.
  bool is_flat_edge(int v0, int v1, int face) const {
    const int other = face_across(v0, v1);
    return other >= 0 && coplanar_normals(world_face_normal(other), world_face_normal(face));
  }
  /// The face across step k -> k+1 of face f's loop, or -1.
  int face_across_step(int f, int k) const {
    if (const HullTopology* t = topology()) return t->face_across_step(f, k);
    return face_across(face_vertex(f, k), face_vertex(f, (k + 1) % face_size(f)));
  }
  /// is_flat_edge for step k of face f's loop.
  bool is_flat_step(int face, int k) const {
    const int other = face_across_step(face, k);
    return other >= 0 && coplanar_normals(world_face_normal(other), world_face_normal(face));
  }

  /// Calls visit(edge_index, v0, v1, face) once per undirected edge, in loop
  /// order: the step v0 -> v1 of `face` with v0 < v1 stands for the edge, its
  /// twin is skipped. Stops when visit returns false.
  template <class Visit>
  void for_each_edge(Visit&& visit) const {
    if (const HullTopology* t = topology()) {
      for (int e = 0; e < t->edge_count(); ++e) {
        const TopologyEdge& edge = t->edge(e);
        if (!visit(e, edge.v0, edge.v1, edge.face)) return;
      }
      return;
    }
    int index = 0;
    for (int f = 0; f < face_count(); ++f) {
      const int n = face_size(f);
      for (int k = 0; k < n; ++k) {
        const int v0 = face_vertex(f, k), v1 = face_vertex(f, (k + 1) % n);
        if (v0 < v1 && !visit(index++, v0, v1, f)) return;
      }
    }
  }

 private:
  Vec3 turned_normal(int f) const { return rotation_ * to_vec(hull_.face_normals[f]); }

  template <class Vertex>
  static int climb(const HullTopology& t, const Vec3& world_direction, int start, Vertex&& vertex) {
    int at = start;
    double at_d = world_direction.dot(vertex(at));
    for (int from = -1; from != at;) {
      from = at;
      for (const int* w = t.neighbours_begin(from); w != t.neighbours_end(from); ++w) {
        const double d = world_direction.dot(vertex(*w));
        if (d > at_d) at = *w, at_d = d;
      }
    }
    return at;
  }

  const mfz_hull& hull_;
  const Pose& pose_;
  Mat3 rotation_;
  bool cached_;
  mutable const HullTopology* topology_ = nullptr;
  mutable bool topology_looked_up_ = false;
  mutable double reach_from_origin_ = -1;
  mutable double span_ = -1;
  mutable bool normals_turned_ = false;
  mutable Vec3 normals_[kCachedFaces];
  Vec3 world_[kCachedVertices];
  double xs_[kCachedVertices], ys_[kCachedVertices], zs_[kCachedVertices];
};

}  // namespace mfz

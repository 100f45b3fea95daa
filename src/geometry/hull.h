#pragma once
/// \file
/// Convex hulls as the contract defines them: extreme vertices only, maximal
/// planar faces as counter-clockwise loops (seen from outside) with outward
/// unit normals, every edge shared by two faces.
#include <optional>
#include <string>
#include <vector>

#include "manifuzz/abi.h"
#include "geometry/vec.h"

namespace mfz {

/// An edge of a hull: `face_left` holds the loop step v0 -> v1, `face_right`
/// the step v1 -> v0.
struct HullEdge {
  int v0 = 0, v1 = 0;
  int face_left = 0, face_right = 0;
};

/// A validated convex polyhedron in local space. Owns the arrays that
/// `view()` hands to a generator through the C ABI.
class Hull {
 public:
  int vertex_count() const { return static_cast<int>(vertices_.size()); }
  int face_count() const { return static_cast<int>(face_normals_.size()); }
  int edge_count() const { return static_cast<int>(edges_.size()); }
  Vec3 vertex(int i) const { return to_vec(vertices_[i]); }
  Vec3 face_normal(int f) const { return to_vec(face_normals_[f]); }
  /// The face plane's offset: normal . x = offset for x on face f.
  double face_offset(int f) const { return face_normal(f).dot(vertex(face_vertex(f, 0))); }
  int face_size(int f) const { return face_offsets_[f + 1] - face_offsets_[f]; }
  int face_vertex(int f, int k) const { return face_vertices_[face_offsets_[f] + k]; }
  const std::vector<HullEdge>& edges() const { return edges_; }
  /// Greatest distance between two vertices.
  double diameter() const { return diameter_; }
  /// The ABI view; valid while this hull lives and is not moved.
  mfz_hull view() const;

  /// This hull scaled about its local origin by `s` > 0 (metamorphic relations).
  Hull scaled(double s) const;
  /// This hull numbered the other way: vertices and faces in reverse order,
  /// each loop starting one vertex later. The same polyhedron; every index
  /// moves (the vertex-order relation).
  Hull renumbered() const;

  /// Assembles a hull from loops and normals already computed (hull builder,
  /// tests); computes edges and diameter. No validation: see `validate_hull`.
  static Hull from_faces(std::vector<Vec3> vertices, std::vector<std::vector<int>> loops,
                         std::vector<Vec3> normals);

 private:
  std::vector<mfz_vec3> vertices_;
  std::vector<int32_t> face_offsets_;
  std::vector<int32_t> face_vertices_;
  std::vector<mfz_vec3> face_normals_;
  std::vector<HullEdge> edges_;
  double diameter_ = 0;
};

/// The outcome of building a hull: a hull, or a one-line reason.
struct HullBuild {
  std::optional<Hull> hull;
  std::string error;
};

/// The convex hull of `points` (local space). Duplicates and interior points are
/// dropped; coplanar triangles are merged into one face. Degenerate input
/// (fewer than four points, a NaN or Inf, all points within
/// tol::kFlatHull * diameter of a plane) gives an error, never a crash.
HullBuild build_hull(const std::vector<Vec3>& points);

/// Empty when `hull` satisfies the contract (Euler's formula, every edge in two
/// faces in opposite directions, planar convex faces with unit outward
/// normals); else the first problem found.
std::string validate_hull(const Hull& hull);

}  // namespace mfz

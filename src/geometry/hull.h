#pragma once
/// \file
/// Convex hulls as the contract defines them: extreme vertices only, maximal
/// planar faces as counter-clockwise loops (seen from outside) with outward
/// unit normals, every edge shared by two faces.
#include <memory>
#include <optional>
#include <string>
#include <utility>
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
  Hull() = default;
  // Copies share the shape; there is no move, so that a hull moved from
  // still holds its shape.
  Hull(const Hull&) = default;
  Hull& operator=(const Hull&) = default;

  int vertex_count() const { return static_cast<int>(shape_->vertices.size()); }
  int face_count() const { return static_cast<int>(shape_->face_normals.size()); }
  int edge_count() const { return static_cast<int>(shape_->edges.size()); }
  Vec3 vertex(int i) const { return to_vec(shape_->vertices[i]); }
  Vec3 face_normal(int f) const { return to_vec(shape_->face_normals[f]); }
  /// The face plane's offset: normal . x = offset for x on face f, the
  /// normal dotted with the loop's first vertex, taken once as the hull is
  /// made.
  double face_offset(int f) const { return shape_->plane_offsets[f]; }
  /// Every face's offset, in face order.
  const double* face_offsets() const { return shape_->plane_offsets.data(); }
  int face_size(int f) const { return shape_->face_offsets[f + 1] - shape_->face_offsets[f]; }
  int face_vertex(int f, int k) const { return shape_->face_vertices[shape_->face_offsets[f] + k]; }
  const std::vector<HullEdge>& edges() const { return shape_->edges; }
  /// Greatest distance between two vertices.
  double diameter() const { return shape_->diameter; }
  /// Length of the shortest edge.
  double shortest_edge() const { return shape_->shortest_edge; }
  /// Sine of the smallest angle between the two edges at a corner of a face.
  double sharpest_corner() const { return shape_->sharpest_corner; }
  /// The first edge, in loop order, whose loop steps are not one each way
  /// (from, to: its first step), or nothing where every edge pairs up;
  /// found as from_faces makes the edges (validate_hull reads it).
  std::optional<std::pair<int, int>> unpaired_edge() const { return shape_->unpaired_edge; }
  /// The ABI view; valid while this hull or a copy of it lives.
  mfz_hull view() const;

  /// This hull scaled about its local origin by `s` > 0 (metamorphic relations).
  Hull scaled(double s) const;
  /// This hull numbered the other way: vertices and faces in reverse order,
  /// each loop starting one vertex later. The same polyhedron; every index
  /// moves (the vertex-order relation).
  Hull renumbered() const;

  /// Assembles a hull from loops and normals already computed (hull builder,
  /// tests); computes edges, diameter, shortest edge and sharpest corner.
  /// No validation: see `validate_hull`.
  static Hull from_faces(std::vector<Vec3> vertices, std::vector<std::vector<int>> loops,
                         std::vector<Vec3> normals);

 private:
  // The arrays and the measures of the shape, shared by every copy: a hull
  // never changes once built, and a case's relations pose it ten times (a
  // copy was five allocations).
  struct Shape {
    std::vector<mfz_vec3> vertices;
    std::vector<int32_t> face_offsets;
    std::vector<int32_t> face_vertices;
    std::vector<mfz_vec3> face_normals;
    std::vector<double> plane_offsets;  // face_offset's
    std::vector<HullEdge> edges;
    double diameter = 0;
    double shortest_edge = 0;
    double sharpest_corner = 1;
    std::optional<std::pair<int, int>> unpaired_edge;
  };
  std::shared_ptr<Shape> shape_ = std::make_shared<Shape>();
  /// Fills in the measures of a hull being built.
  void measure_shape();
  /// The same but the diameter.
  void measure_corners_and_edges();
  /// Takes each face's plane offset from its normal and first vertex.
  void take_plane_offsets();
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

/// Every face split into a fan of triangles from its first corner, each with
/// the face's own normal, as a mesh exported from a modelling tool arrives:
/// the diagonals lie between coplanar faces (the triangulated-faces
/// relation, and the generator's flat edges).
Hull fan_triangulated(const Hull& hull);

}  // namespace mfz

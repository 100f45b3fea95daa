#include "geometry/hull.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <utility>

#include "geometry/qhull_facets.h"
#include "geometry/simplicial_facets.h"
#include "geometry/tolerances.h"

namespace mfz {
namespace {

double diameter_of(const std::vector<mfz_vec3>& vertices) {
  double best = 0;
  for (size_t i = 0; i < vertices.size(); ++i)
    for (size_t j = i + 1; j < vertices.size(); ++j)
      best = std::max(best, (to_vec(vertices[i]) - to_vec(vertices[j])).squaredNorm());
  return std::sqrt(best);
}

// Thickness of the cloud: distance from the plane through a well-spread triangle
// to the point farthest from it. Zero-volume clouds are refused before Qhull so
// that the message says why, and the threshold is relative to the cloud's size.
std::string flatness_error(const std::vector<Vec3>& points) {
  size_t i0 = 0, i1 = 0;
  double far = 0;
  for (size_t i = 0; i < points.size(); ++i)
    for (size_t j = i + 1; j < points.size(); ++j) {
      const double d = (points[i] - points[j]).squaredNorm();
      if (d > far) far = d, i0 = i, i1 = j;
    }
  const double size = std::sqrt(far);
  if (size == 0) return "all points coincide";
  const Vec3 axis = (points[i1] - points[i0]) / size;
  size_t i2 = i0;
  double off_line = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    const Vec3 d = points[i] - points[i0];
    const double dist = (d - d.dot(axis) * axis).norm();
    if (dist > off_line) off_line = dist, i2 = i;
  }
  if (off_line <= tol::kFlatHull * size) return "all points lie on a line";
  const Vec3 plane_normal = axis.cross(points[i2] - points[i0]).normalized();
  double thickness = 0;
  for (const Vec3& p : points) thickness = std::max(thickness, std::abs(plane_normal.dot(p - points[i0])));
  if (thickness <= tol::kFlatHull * size) {
    std::ostringstream why;
    why << "all points lie within " << thickness / size << " L of a plane: the hull has no volume";
    return why.str();
  }
  return {};
}

// Most facets of a cloud are triangles: the sort below, without atan2. The
// loop starts where the sort's would (at the vertex before loop[0], whose
// angle is the only negative one), so both paths build the same hull.
// False, and `loop` untouched, where a vertex lies on u's line (angle 0 or
// pi): the sort then decides.
bool order_triangle(std::vector<int>& loop, const std::vector<Vec3>& points, const Vec3& centroid, const Vec3& v) {
  const double side_1 = (points[loop[1]] - centroid).dot(v), side_2 = (points[loop[2]] - centroid).dot(v);
  if (side_1 == 0 || side_2 == 0 || (side_1 > 0) == (side_2 > 0)) return false;
  const int first = loop[0], next = side_1 > 0 ? loop[1] : loop[2], before = side_1 > 0 ? loop[2] : loop[1];
  loop = {before, first, next};
  return true;
}

// Qhull gives each facet's vertices as an unordered set: order them
// counter-clockwise about the outward normal by angle around their centroid
// (a facet is convex, so the angular order is the loop).
void order_counter_clockwise(std::vector<int>& loop, const std::vector<Vec3>& points, const Vec3& normal) {
  Vec3 centroid = Vec3::Zero();
  for (int id : loop) centroid += points[id];
  centroid /= static_cast<double>(loop.size());
  const Vec3 u = (points[loop[0]] - centroid).normalized();
  const Vec3 v = normal.cross(u);
  if (loop.size() == 3 && order_triangle(loop, points, centroid, v)) return;
  std::vector<std::pair<double, int>> keyed;
  for (int id : loop) {
    const Vec3 d = points[id] - centroid;
    keyed.emplace_back(std::atan2(d.dot(v), d.dot(u)), id);
  }
  std::sort(keyed.begin(), keyed.end());
  for (size_t k = 0; k < loop.size(); ++k) loop[k] = keyed[k].second;
}

// A vertex that lies on a straight stretch of a loop is not extreme (it sits on
// an edge, or Qhull's merging left it inside a face): the contract lists
// extreme points only, so it leaves every loop. Returns true when one was found.
bool drop_one_non_extreme_vertex(std::vector<std::vector<int>>& loops, const std::vector<Vec3>& points) {
  std::vector<int> faces_of(points.size(), 0);
  for (const auto& loop : loops)
    for (int id : loop) ++faces_of[id];
  for (auto& loop : loops) {
    const size_t n = loop.size();
    for (size_t k = 0; k < n; ++k) {
      const int id = loop[k];
      const Vec3 in = points[id] - points[loop[(k + n - 1) % n]];
      const Vec3 out = points[loop[(k + 1) % n]] - points[id];
      const bool straight = in.cross(out).norm() <= 1e-12 * in.norm() * out.norm() && in.dot(out) > 0;
      if (faces_of[id] >= 3 && !straight) continue;
      for (auto& other : loops) other.erase(std::remove(other.begin(), other.end(), id), other.end());
      return true;
    }
  }
  return false;
}

// The loops' steps, in loop order, grouped by the edge they run along
// (their vertices are the hull's: from_faces is given valid loops only):
// `lead[k]` is the first step along step k's edge, and for a lead, `last`
// the last and `count` how many. Bucketed by the edge's lower vertex, whose
// neighbours are few, so that no sort is needed: sorting the steps, once to
// pair them into edges and twice to validate them, was a sixth of a
// 32-point scene once Qhull was out of it.
//
// from_faces keeps one per thread and clears it, so that its arrays keep
// their room from hull to hull (with validate_hull grouping the steps again,
// the nine allocations of the two groupings were a tenth of an 8-point
// hull's build; it now reads from_faces's unpaired edge instead).
struct StepsByEdge {
  std::vector<int> from, to, face;  // face: only where the edges are made
  int *lead = nullptr, *last = nullptr, *count = nullptr;  // into `grouped`

  StepsByEdge() = default;
  StepsByEdge(const StepsByEdge&) = delete;  // the pointers are into its own buffer

  void clear() { from.clear(), to.clear(), face.clear(); }

  void group(int vertex_count) {
    const int steps = static_cast<int>(from.size());
    grouped.assign(3 * static_cast<size_t>(steps), -1);
    lead = grouped.data(), last = lead + steps, count = last + steps;
    std::fill(count, count + steps, 0);
    scratch.assign(static_cast<size_t>(vertex_count) + 2 + static_cast<size_t>(steps), 0);
    int* start = scratch.data();
    int* bucket = start + vertex_count + 2;
    for (int k = 0; k < steps; ++k) ++start[std::min(from[k], to[k]) + 2];
    for (int v = 0; v <= vertex_count; ++v) start[v + 1] += start[v];
    for (int k = 0; k < steps; ++k) bucket[start[std::min(from[k], to[k]) + 1]++] = k;
    for (int v = 0; v < vertex_count; ++v)
      for (int i = start[v]; i < start[v + 1]; ++i) {
        const int k = bucket[i];
        if (lead[k] >= 0) continue;
        const int high = std::max(from[k], to[k]);
        for (int j = i; j < start[v + 1]; ++j) {
          const int other = bucket[j];
          if (std::max(from[other], to[other]) != high) continue;
          lead[other] = k, last[k] = other, ++count[k];
        }
      }
  }

 private:
  std::vector<int> grouped, scratch;
};

}  // namespace

// The measures are taken in local space: a rigid motion changes none of
// them.
void Hull::measure_shape() {
  shape_->diameter = diameter_of(shape_->vertices);
  measure_corners_and_edges();
}

// The sharpest corner is the sine of the smallest angle between the two
// edges meeting at a corner of a face.
void Hull::measure_corners_and_edges() {
  Shape& shape = *shape_;
  shape.shortest_edge = std::numeric_limits<double>::infinity();
  for (const HullEdge& e : shape.edges)
    shape.shortest_edge = std::min(shape.shortest_edge, (vertex(e.v1) - vertex(e.v0)).norm());
  shape.sharpest_corner = 1;
  for (int f = 0; f < face_count(); ++f)
    for (int k = 0, size = face_size(f); k < size; ++k) {
      const Vec3 corner = vertex(face_vertex(f, k));
      const Vec3 before = (vertex(face_vertex(f, (k + size - 1) % size)) - corner).normalized();
      const Vec3 after = (vertex(face_vertex(f, (k + 1) % size)) - corner).normalized();
      shape.sharpest_corner = std::min(shape.sharpest_corner, before.cross(after).norm());
    }
}

// Every distance to a face plane subtracts its offset: taken from the
// loop's first vertex on each query, the offsets were two fifths of the
// heights' pass, which the on-surface and within-both-hulls checks make
// for every contact of every run. A face left with no corners (a cloud
// 1e-129 across, whose corners were all dropped as not extreme) has no
// plane: its offset is 0, and validate_hull refuses the hull. Its first
// corner read the next face's, or past the loops (ASan, manifold_fuzzer).
void Hull::take_plane_offsets() {
  Shape& shape = *shape_;
  shape.plane_offsets.resize(shape.face_normals.size());
  for (int f = 0; f < face_count(); ++f)
    shape.plane_offsets[f] = face_size(f) > 0 ? face_normal(f).dot(vertex(face_vertex(f, 0))) : 0.0;
}

mfz_hull Hull::view() const {
  const Shape& shape = *shape_;
  return {vertex_count(), shape.vertices.data(), face_count(), shape.face_offsets.data(), shape.face_vertices.data(),
          shape.face_normals.data()};
}

namespace {

// Whether scaling by `s` scales every step of the measures exactly: s is a
// power of two, and the squared lengths the measures take, before and
// after, stay far inside the normal doubles, so that the square of a tiny
// coordinate difference, rounded apart from the rest, stays below half an
// ulp of the sum it joins.
bool scales_measures_exactly(double s, double shortest_edge, double diameter) {
  int exponent = 0;
  if (!(std::frexp(s, &exponent) == 0.5)) return false;
  constexpr double kSmallest = 1e-100, kLargest = 1e100;
  return std::min(1.0, s) * shortest_edge >= kSmallest && std::max(1.0, s) * diameter <= kLargest;
}

}  // namespace

Hull Hull::scaled(double s) const {
  Hull out;
  *out.shape_ = *shape_;
  for (mfz_vec3& v : out.shape_->vertices) v = to_abi(Vec3(s * to_vec(v)));
  // By a power of two every difference, square and root scales exactly and
  // every unit vector stays as it was, so the measures taken again would
  // be these to the bit (the scale relation scales both hulls by 2 in every
  // case, and taking them again was a sixth of its time on 8-point hulls).
  if (scales_measures_exactly(s, shortest_edge(), diameter())) {
    out.shape_->shortest_edge = s * shortest_edge();
  } else {
    out.measure_corners_and_edges();
  }
  out.shape_->diameter = s * diameter();
  out.take_plane_offsets();
  return out;
}

Hull Hull::renumbered() const {
  const int last = vertex_count() - 1, faces = face_count();
  Hull out;
  Shape& shape = *out.shape_;
  shape.vertices.assign(shape_->vertices.rbegin(), shape_->vertices.rend());
  shape.face_normals.assign(shape_->face_normals.rbegin(), shape_->face_normals.rend());
  // Sized once: the vertex-order relation renumbers both hulls on every
  // case, and growing four arrays step by step was 40 allocations a call.
  shape.face_offsets.reserve(faces + 1);
  shape.face_vertices.reserve(shape_->face_vertices.size());
  shape.edges.reserve(edges().size());
  shape.face_offsets.push_back(0);
  for (int f = faces - 1; f >= 0; --f) {
    const int n = face_size(f);
    for (int k = 1; k <= n; ++k) shape.face_vertices.push_back(last - face_vertex(f, k % n));
    shape.face_offsets.push_back(static_cast<int32_t>(shape.face_vertices.size()));
  }
  for (const HullEdge& e : edges())
    shape.edges.push_back({last - e.v0, last - e.v1, faces - 1 - e.face_left, faces - 1 - e.face_right});
  if (const auto edge = unpaired_edge()) shape.unpaired_edge = {last - edge->first, last - edge->second};
  // The same corners and edges, each between the same two vertices in the
  // same direction: the same measures, to the bit.
  shape.diameter = diameter();
  shape.shortest_edge = shortest_edge();
  shape.sharpest_corner = sharpest_corner();
  out.take_plane_offsets();  // each loop starts one vertex later
  return out;
}

Hull Hull::from_faces(std::vector<Vec3> vertices, std::vector<std::vector<int>> loops,
                      std::vector<Vec3> normals) {
  Hull hull;
  Shape& shape = *hull.shape_;
  size_t steps_total = 0;
  for (const auto& loop : loops) steps_total += loop.size();
  shape.vertices.reserve(vertices.size());
  shape.face_offsets.reserve(loops.size() + 1);
  shape.face_vertices.reserve(steps_total);
  shape.face_normals.reserve(normals.size());
  shape.edges.reserve(steps_total / 2);
  for (const Vec3& v : vertices) shape.vertices.push_back(to_abi(v));
  shape.face_offsets.push_back(0);
  for (const auto& loop : loops) {
    shape.face_vertices.insert(shape.face_vertices.end(), loop.begin(), loop.end());
    shape.face_offsets.push_back(static_cast<int32_t>(shape.face_vertices.size()));
  }
  for (const Vec3& n : normals) shape.face_normals.push_back(to_abi(n));
  // Edges keep the order of their first step; the step back gives the
  // face on the right.
  static thread_local StepsByEdge steps;
  steps.clear();
  for (int f = 0; f < static_cast<int>(loops.size()); ++f) {
    const auto& loop = loops[f];
    for (size_t k = 0; k < loop.size(); ++k)
      steps.from.push_back(loop[k]), steps.to.push_back(loop[(k + 1) % loop.size()]), steps.face.push_back(f);
  }
  steps.group(static_cast<int>(shape.vertices.size()));
  for (int k = 0; k < static_cast<int>(steps_total); ++k) {
    if (steps.lead[k] != k) continue;
    shape.edges.push_back(
        {steps.from[k], steps.to[k], steps.face[k], steps.count[k] > 1 ? steps.face[steps.last[k]] : -1});
    if (!shape.unpaired_edge && (steps.count[k] != 2 || steps.from[steps.last[k]] != steps.to[k]))
      shape.unpaired_edge = {steps.from[k], steps.to[k]};
  }
  hull.measure_shape();
  hull.take_plane_offsets();
  return hull;
}

namespace {

// The contract's hull from a builder's facets: loops ordered, vertices that
// are not extreme dropped, points renumbered, the result validated.
HullBuild hull_from_facets(const std::vector<Vec3>& points, std::vector<QhullFacet> facets) {
  std::vector<std::vector<int>> loops;
  std::vector<Vec3> normals;
  loops.reserve(facets.size());
  normals.reserve(facets.size());
  for (QhullFacet& facet : facets) {
    loops.push_back(std::move(facet.point_ids));
    normals.push_back(facet.normal.normalized());
    order_counter_clockwise(loops.back(), points, normals.back());
  }
  while (drop_one_non_extreme_vertex(loops, points)) {
  }

  // Renumber the surviving points as the hull's vertices, in input order so
  // that the numbering does not depend on Qhull's facet order.
  std::vector<int> index_of(points.size(), -1);
  for (const auto& loop : loops)
    for (int id : loop) index_of[id] = 0;
  std::vector<Vec3> vertices;
  for (size_t i = 0; i < points.size(); ++i)
    if (index_of[i] == 0) index_of[i] = static_cast<int>(vertices.size()), vertices.push_back(points[i]);
  for (auto& loop : loops)
    for (int& id : loop) id = index_of[id];

  Hull hull = Hull::from_faces(std::move(vertices), std::move(loops), std::move(normals));
  if (std::string why = validate_hull(hull); !why.empty()) return {std::nullopt, "invalid hull: " + why};
  return {std::move(hull), {}};
}

}  // namespace

HullBuild build_hull(const std::vector<Vec3>& points) {
  if (points.size() < 4) return {std::nullopt, "fewer than four points (" + std::to_string(points.size()) + ")"};
  double largest = 0;
  for (const Vec3& p : points) {
    if (!p.allFinite()) return {std::nullopt, "a point is NaN or infinite"};
    largest = std::max(largest, p.cwiseAbs().maxCoeff());
  }
  if (largest > tol::kLargestCoordinate) {
    char why[120];
    std::snprintf(why, sizeof why, "a coordinate of %.3g is past the limit of %g", largest, tol::kLargestCoordinate);
    return {std::nullopt, why};
  }
  if (std::string why = flatness_error(points); !why.empty()) return {std::nullopt, why};

  // A small cloud in general position without Qhull's set-up; where its
  // triangles do not close into a valid hull, Qhull decides as before.
  if (std::optional<std::vector<QhullFacet>> simplicial = simplicial_facets(points)) {
    HullBuild fast = hull_from_facets(points, std::move(*simplicial));
    if (fast.hull) return fast;
  }
  std::string qhull_error;
  std::vector<QhullFacet> facets = qhull_facets(points, /*triangulate=*/false, qhull_error);
  if (facets.empty()) return {std::nullopt, "qhull: " + qhull_error};
  return hull_from_facets(points, std::move(facets));
}

std::string validate_hull(const Hull& hull) {
  const int v = hull.vertex_count(), e = hull.edge_count(), f = hull.face_count();
  if (v < 4 || f < 4) return "fewer than four vertices or faces";
  // Every loop step from -> to once, and its reverse once: each edge's
  // steps are exactly two, one each way. from_faces grouped the steps into
  // edges and kept the first that does not pair up; grouping them again
  // here was a fifth of an 8-point hull's build.
  for (int face = 0; face < f; ++face)
    if (hull.face_size(face) < 3) return "a face has fewer than three vertices";
  if (const auto edge = hull.unpaired_edge())
    return "edge " + std::to_string(edge->first) + "-" + std::to_string(edge->second) +
           " is not shared by exactly two faces";
  // Every edge in two faces, checked first: an open surface is named as one.
  if (v - e + f != 2) return "Euler characteristic V - E + F = " + std::to_string(v - e + f) + ", not 2";
  const double slack = tol::kHullConvexity * hull.diameter();
  for (int face = 0; face < f; ++face) {
    const Vec3 n = hull.face_normal(face);
    if (std::abs(n.norm() - 1) > 1e-12) return "a face normal is not unit length";
    const double offset = hull.face_offset(face);
    Vec3 newell = Vec3::Zero();
    for (int k = 0; k < hull.face_size(face); ++k) {
      const Vec3 p = hull.vertex(hull.face_vertex(face, k));
      if (std::abs(n.dot(p) - offset) > slack) return "a face is not planar";
      newell += p.cross(hull.vertex(hull.face_vertex(face, (k + 1) % hull.face_size(face))));
    }
    if (newell.dot(n) <= 0) return "a face loop is not counter-clockwise seen from outside";
    for (int i = 0; i < v; ++i)
      if (n.dot(hull.vertex(i)) - offset > slack) return "the hull is not convex";
  }
  return {};
}

Hull fan_triangulated(const Hull& hull) {
  std::vector<Vec3> vertices;
  std::vector<std::vector<int>> loops;
  std::vector<Vec3> normals;
  for (int i = 0; i < hull.vertex_count(); ++i) vertices.push_back(hull.vertex(i));
  for (int f = 0; f < hull.face_count(); ++f)
    for (int k = 1; k + 1 < hull.face_size(f); ++k) {
      loops.push_back({hull.face_vertex(f, 0), hull.face_vertex(f, k), hull.face_vertex(f, k + 1)});
      normals.push_back(hull.face_normal(f));
    }
  return Hull::from_faces(std::move(vertices), std::move(loops), std::move(normals));
}

}  // namespace mfz

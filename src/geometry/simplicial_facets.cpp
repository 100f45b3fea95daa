#include "geometry/simplicial_facets.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "geometry/vector_lanes.h"

namespace mfz {
namespace {

// A triangle of the growing hull: its loop counter-clockwise seen from
// outside, and the plane through its first corner.
struct Triangle {
  std::array<int, 3> loop;
  Vec3 corner;  // the first corner, a
  Vec3 normal;  // (b - a) x (c - a): twice the area long
  double near;  // the band (kNearPlane x diameter, or more far out) in the units of normal's heights
  bool alive;
};

// How many points (columns x, y, z) lie above the plane through `corner`
// with normal `normal`, or less than `band` below it, in vector lanes.
MFZ_VECTOR_LANES int points_reaching(const double* x, const double* y, const double* z, int count,
                                     const Vec3& corner, const Vec3& normal, double band) {
  const double nx = normal.x(), ny = normal.y(), nz = normal.z();
  const double ax = corner.x(), ay = corner.y(), az = corner.z(), below = -band;
  int reaching = 0;
#pragma omp simd reduction(+ : reaching)
  for (int i = 0; i < count; ++i) reaching += nx * (x[i] - ax) + ny * (y[i] - ay) + nz * (z[i] - az) > below;
  return reaching;
}

// Builds the hull a point at a time (the beneath-beyond step of Barber,
// Dobkin and Huhdanpaa's Quickhull paper, without its merging, which a
// cloud in general position never needs). Declines, by returning false,
// wherever a point lies within the band of a final triangle's plane, as
// the brute force did of every supporting triple: there Qhull might merge,
// or call the point coplanar, and decides instead. The final check is
// the verdict; a point in a live triangle's band stops the growing early
// (add_point), which only ever sends a cloud to Qhull sooner.
//
// One per thread, grown anew for each cloud: its arrays keep their room
// from cloud to cloud, where growing an 8-point cloud made nine
// allocations, a sixth of what building its hull cost.
class IncrementalHull {
 public:
  bool build(const std::vector<Vec3>& points, double diameter, double band) {
    points_ = points.data(), n_ = static_cast<int>(points.size()), diameter_ = diameter, band_ = band;
    face_of_step_.assign(static_cast<size_t>(n_) * n_, -1);
    triangles_.clear(), alive_.clear(), seen_.clear(), horizon_.clear();
    std::array<int, 4> start;
    if (!first_tetrahedron(start)) return false;
    for (int i = 0; i < n_; ++i)
      if (std::find(start.begin(), start.end(), i) == start.end() && !add_point(i)) return false;
    return every_point_clearly_below();
  }

  // The live triangles as the brute force over triples gave them: each
  // from its smallest index, in the order of their sorted indices, the
  // plane taken from the sorted triple (so that both give the same bits).
  std::vector<QhullFacet> facets() {
    std::vector<std::array<int, 3>>& sorted = sorted_;
    sorted.clear();
    for (int t : alive_) {
      std::array<int, 3> ids = triangles_[t].loop;
      std::sort(ids.begin(), ids.end());
      sorted.push_back(ids);
    }
    std::sort(sorted.begin(), sorted.end());
    std::vector<QhullFacet> out;
    out.reserve(sorted.size());
    for (const auto& [i, j, k] : sorted) {
      const Vec3 normal = (points_[j] - points_[i]).cross(points_[k] - points_[i]);
      const double twice_area = normal.norm();
      const bool outward = winds_as_built(i, j, k);
      QhullFacet facet;
      facet.normal = (outward ? normal : Vec3(-normal)) / twice_area;
      facet.offset = facet.normal.dot(points_[i]);
      facet.point_ids = outward ? std::vector<int>{i, j, k} : std::vector<int>{i, k, j};
      out.push_back(std::move(facet));
    }
    return out;
  }

 private:
  int& face_of(int from, int to) { return face_of_step_[static_cast<size_t>(from) * n_ + to]; }
  int face_of(int from, int to) const { return face_of_step_[static_cast<size_t>(from) * n_ + to]; }

  // Whether the step i -> j belongs to the triangle i, j, k as built, that
  // is, whether i, j, k runs counter-clockwise seen from outside.
  bool winds_as_built(int i, int j, int k) const {
    const int t = face_of(i, j);
    return t >= 0 && std::find(triangles_[t].loop.begin(), triangles_[t].loop.end(), k) != triangles_[t].loop.end();
  }

  // The point's height over the triangle's plane, in the units of its
  // normal's length.
  static double height(const Triangle& t, const Vec3& point) { return t.normal.dot(point - t.corner); }

  // A triangle from a -> b -> c (counter-clockwise seen from outside);
  // false for one too thin to trust its plane.
  bool add_triangle(int a, int b, int c) {
    const Vec3 normal = (points_[b] - points_[a]).cross(points_[c] - points_[a]);
    const double twice_area = normal.norm();
    if (!(twice_area > kNearPlane * diameter_ * diameter_)) return false;
    const int index = static_cast<int>(triangles_.size());
    triangles_.push_back({{a, b, c}, points_[a], normal, band_ * twice_area, true});
    alive_.push_back(index);
    face_of(a, b) = face_of(b, c) = face_of(c, a) = index;
    return true;
  }

  // Four points spanning the most volume a cheap search finds: the point
  // furthest from the first, the one furthest from their line, the one
  // furthest from their plane.
  bool first_tetrahedron(std::array<int, 4>& start) {
    const auto furthest = [&](auto&& distance) {
      int best = 0;
      double best_d = -1;
      for (int i = 0; i < n_; ++i)
        if (const double d = distance(points_[i]); d > best_d) best = i, best_d = d;
      return best;
    };
    const Vec3 p0 = points_[0];
    const int i1 = furthest([&](const Vec3& p) { return (p - p0).squaredNorm(); });
    const Vec3 line = points_[i1] - p0;
    const int i2 = furthest([&](const Vec3& p) { return (p - p0).cross(line).squaredNorm(); });
    const Vec3 across = line.cross(points_[i2] - p0);
    const int i3 = furthest([&](const Vec3& p) { return std::abs(across.dot(p - p0)); });
    if (i1 == 0 || i2 == 0 || i2 == i1 || i3 == 0 || i3 == i1 || i3 == i2) return false;
    start = {0, i1, i2, i3};
    // The base 0, i1, i2 counter-clockwise seen from below, where i3 is not.
    const bool i3_above = across.dot(points_[i3] - p0) > 0;
    const int b1 = i3_above ? i2 : i1, b2 = i3_above ? i1 : i2;
    if (!add_triangle(0, b1, b2) || !add_triangle(0, i3, b1) || !add_triangle(b1, i3, b2) ||
        !add_triangle(b2, i3, 0))
      return false;
    return true;
  }

  // The beneath-beyond step: the triangles the point sees go, and the
  // horizon's steps, each joined to the point, close the hole. In general
  // position the seen triangles make one disc, its rim one loop.
  bool add_point(int point) {
    seen_.clear();
    const Vec3 p = points_[point];
    for (int t : alive_) {
      const double h = height(triangles_[t], p);
      // A point in a live triangle's band ends the growing at once: nearly
      // always the final triangles have one too (a box's fourth corner on a
      // face), and the fuzzer's clouds are mostly such. Growing them to the
      // end first cost a seventh of what Qhull then spent on them (a corpus
      // grown by manifold_fuzzer: 2,530 of its 3,184 clouds went to Qhull).
      // Where the triangle would not have lasted, Qhull builds the cloud.
      if (std::abs(h) <= triangles_[t].near) return false;
      if (h > 0) seen_.push_back(t);
    }
    if (seen_.empty()) return true;  // inside: not a vertex
    horizon_.clear();
    for (int t : seen_) triangles_[t].alive = false;
    alive_.erase(std::remove_if(alive_.begin(), alive_.end(), [&](int t) { return !triangles_[t].alive; }),
                 alive_.end());
    for (int t : seen_) {
      const std::array<int, 3> loop = triangles_[t].loop;
      for (int k = 0; k < 3; ++k) {
        const int from = loop[k], to = loop[(k + 1) % 3];
        const int beyond = face_of(to, from);
        if (beyond >= 0 && triangles_[beyond].alive) horizon_.push_back({from, to});
        face_of(from, to) = -1;
      }
    }
    for (const auto& [from, to] : horizon_)
      if (!add_triangle(from, to, point)) return false;
    return true;
  }

  // Every point not on a triangle clearly below it, as the brute force
  // asked of every triple: a later triangle was never tried against the
  // points added before it. Counted over all the points in columns, the
  // triangle's own corners among them: their heights are rounding alone,
  // far inside the band, so exactly three points reach it.
  bool every_point_clearly_below() {
    x_.resize(n_), y_.resize(n_), z_.resize(n_);
    for (int i = 0; i < n_; ++i) x_[i] = points_[i].x(), y_[i] = points_[i].y(), z_[i] = points_[i].z();
    for (int index : alive_) {
      const Triangle& t = triangles_[index];
      if (points_reaching(x_.data(), y_.data(), z_.data(), n_, t.corner, t.normal, t.near) != 3) return false;
    }
    return true;
  }

  // The cloud being grown.
  const Vec3* points_ = nullptr;
  int n_ = 0;
  double diameter_ = 0;
  double band_ = 0;  // a point nearer a triangle's plane than this lies on it
  std::vector<int> face_of_step_;  // the triangle holding each step from -> to, n x n
  std::vector<Triangle> triangles_;
  std::vector<int> alive_;  // the live triangles, in the order they were made
  std::vector<int> seen_;
  std::vector<std::array<int, 2>> horizon_;
  std::vector<double> x_, y_, z_;  // the points' coordinates as columns
  std::vector<std::array<int, 3>> sorted_;  // the final triangles' sorted corners
};

}  // namespace

std::optional<std::vector<QhullFacet>> simplicial_facets(const std::vector<Vec3>& points) {
  const int n = static_cast<int>(points.size());
  if (n < 4 || n > kSimplicialMaxPoints) return std::nullopt;
  double diameter = 0, largest = 0;
  for (int i = 0; i < n; ++i) {
    largest = std::max(largest, points[i].cwiseAbs().maxCoeff());
    for (int j = i + 1; j < n; ++j) diameter = std::max(diameter, (points[i] - points[j]).squaredNorm());
  }
  diameter = std::sqrt(diameter);
  if (!(diameter > 0) || !std::isfinite(diameter) || !std::isfinite(largest)) return std::nullopt;
  const double band = std::max(kNearPlane * diameter, kCoordinateRounding * largest);
  static thread_local IncrementalHull hull;
  if (!hull.build(points, diameter, band)) return std::nullopt;
  return hull.facets();
}

}  // namespace mfz

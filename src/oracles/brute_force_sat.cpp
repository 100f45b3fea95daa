#include "oracles/brute_force_sat.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/posed_hull.h"
#include "geometry/tolerances.h"
#include "geometry/vector_lanes.h"

namespace mfz {

double directed_overlap(const std::vector<Vec3>& world_a, const std::vector<Vec3>& world_b, const Vec3& n) {
  double max_a = -std::numeric_limits<double>::infinity(), min_b = std::numeric_limits<double>::infinity();
  for (const Vec3& p : world_a) max_a = std::max(max_a, n.dot(p));
  for (const Vec3& p : world_b) min_b = std::min(min_b, n.dot(p));
  return max_a - min_b;
}

namespace {

// World vertices as three arrays: the projections below are the oracle's
// whole cost (E_A x E_B axes times V_A + V_B points), and plain arrays let
// the compiler keep them in registers.
struct PointColumns {
  std::vector<double> xyz;  // x[0..n), y[0..n), z[0..n): one allocation
  size_t n;
  explicit PointColumns(const std::vector<Vec3>& points) : xyz(3 * points.size()), n(points.size()) {
    for (size_t i = 0; i < n; ++i) xyz[i] = points[i].x(), xyz[n + i] = points[i].y(), xyz[2 * n + i] = points[i].z();
  }
  void project(const Vec3& axis, double& lowest, double& highest) const {
    double low = INFINITY, high = -INFINITY;
    const double ax = axis.x(), ay = axis.y(), az = axis.z();
    const double *px = xyz.data(), *py = px + n, *pz = py + n;
    // The points are finite (hulls are validated), so min and max may run
    // in vector lanes in any order: the result is the same number.
#pragma omp simd reduction(min : low) reduction(max : high)
    for (size_t i = 0; i < n; ++i) {
      const double d = ax * px[i] + ay * py[i] + az * pz[i];
      low = d < low ? d : low;
      high = d > high ? d : high;
    }
    lowest = low, highest = high;
  }
};

// The row's loops are built for AVX2 and for any x86-64
// (geometry/vector_lanes.h). With the normalisation in lanes too (this
// file's options in src/CMakeLists.txt), the oracle went from 7.3 to 5.5 us
// on 8-point hulls and from 234 to 211 us on 32-point hulls, with the same
// bits on 18.5 million axes.

// A row's unit axes: A's edge `ea` (of length `length_a`) crossed with each
// of B's edges (columns vx, vy, vz, lengths length_b), normalised, or zero
// where the edges are parallel (no axis: a unit axis is never zero). The
// same sums as Eigen's cross() and norm() on Vec3, (x * x + y * y) + z * z,
// so the same bits.
MFZ_VECTOR_LANES void axes_of_row(const Vec3& ea, double length_a, const double* vx, const double* vy,
                                  const double* vz, const double* length_b, size_t row, double* nx, double* ny,
                                  double* nz) {
  const double ax = ea.x(), ay = ea.y(), az = ea.z();
  const double parallel = tol::kParallelEdges * length_a;
#pragma omp simd
  for (size_t j = 0; j < row; ++j) {
    const double cx = ay * vz[j] - az * vy[j], cy = az * vx[j] - ax * vz[j], cz = ax * vy[j] - ay * vx[j];
    const double length = std::sqrt(cx * cx + cy * cy + cz * cz);
    const bool spans = !(length <= parallel * length_b[j]);
    // Every lane divides, by 1 where the edges are parallel: no branch.
    const double divisor = spans ? length : 1.0;
    const double ux = cx / divisor, uy = cy / divisor, uz = cz / divisor;
    nx[j] = spans ? ux : 0.0;
    ny[j] = spans ? uy : 0.0;
    nz[j] = spans ? uz : 0.0;
  }
}

// Every point projected onto a row of axes (columns nx, ny, nz): the least
// and the greatest projection per axis, four points at a time in vector
// lanes (project_onto_axes, geometry/posed_hull.h), the same bits as
// PointColumns::project.
void project_row(const PointColumns& points, const double* nx, const double* ny, const double* nz, size_t row,
                 double* lowest, double* highest) {
  const double *px = points.xyz.data(), *py = px + points.n, *pz = py + points.n;
  project_onto_axes(px, py, pz, static_cast<int>(points.n), nx, ny, nz, static_cast<int>(row), lowest, highest);
}

// A row's edge axes each the smaller way (an edge pair counts either way):
// its sign, overlap and the overlap the other way; and the least overlap
// either way of the row's axes, where the edges are not parallel (no axis).
// Chosen in lanes rather than pair by pair: which way is smaller is a coin
// toss from pair to pair, which no branch predicts. Times -1 is negation,
// to the bit.
MFZ_VECTOR_LANES void ways_of_row(const double* nx, const double* ny, const double* nz, const double* min_a,
                                  const double* max_a, const double* min_b, const double* max_b, size_t row,
                                  double* way, double* overlap, double* reverse, double& least,
                                  double& least_reverse) {
  double low = INFINITY, low_reverse = INFINITY;
#pragma omp simd reduction(min : low, low_reverse)
  for (size_t j = 0; j < row; ++j) {
    const double along = max_a[j] - min_b[j], against = max_b[j] - min_a[j];
    const bool along_first = along <= against;
    way[j] = along_first ? 1.0 : -1.0;
    overlap[j] = along_first ? along : against;
    reverse[j] = along_first ? against : along;
    const bool parallel = nx[j] == 0 && ny[j] == 0 && nz[j] == 0;
    const double key = parallel ? INFINITY : overlap[j], reverse_key = parallel ? INFINITY : reverse[j];
    low = key < low ? key : low;
    low_reverse = reverse_key < low_reverse ? reverse_key : low_reverse;
  }
  least = low, least_reverse = low_reverse;
}

// A face of A counts outward and a face of B inward only: those are the faces
// of the Minkowski difference (reversed, a face normal meets an edge or a
// vertex of its hull). Edge pairs count either way.
RankedAxis ranked_axis(const PointColumns& a, const PointColumns& b, const Vec3& axis, AxisKind kind, int fa, int fb) {
  // One pass gives both directions: along = max_a - min_b, against = max_b - min_a.
  double min_a, max_a, min_b, max_b;
  a.project(axis, min_a, max_a);
  b.project(axis, min_b, max_b);
  const double along = max_a - min_b, against = max_b - min_a;
  constexpr double no_facet = INFINITY;
  if (kind == AxisKind::face_a) return {axis, along, no_facet, kind, fa, fb};
  if (kind == AxisKind::face_b) return {-axis, against, no_facet, kind, fa, fb};
  if (along <= against) return {axis, along, against, kind, fa, fb};
  return {-axis, against, along, kind, fa, fb};
}

// Best first, but only as far as anyone reads: the axes within `window` of
// the least overlap (and at least three) are sorted, stably; the rest follow
// in no order. Sorting all E_A x E_B axes cost a tenth of a case, and a
// stable partition's buffer a fiftieth.
//
// The ranking is told the least overlap as the axes are written, and each
// axis that came within `window` of the least so far: every axis within the
// window of the final least is among those, since the least only falls (and
// adding the window rounds the same way), so the front is gathered from
// them, with the same swaps in the same order, and the 8,000 axes of two
// 32-point hulls (450 KB) are not read twice more. With those two passes,
// the vector zeroed before it was written and each pair's way chosen by a
// branch (ways_of_row), the bookkeeping was half the oracle's time on
// 32-point hulls (perf); without them the oracle takes 189-193 us there
// where it took 224-228, and 5.2 us on 8-point hulls where it took 6.3
// (property_bench, least of seven runs), the same axes in the same order
// to the bit on 15,329 scenes (the bench families, the corpus, clouds of 4
// to 64 points, each also moved far from the origin).
class AxisRanking {
 public:
  explicit AxisRanking(double window) : window_(window) {}
  /// Lowers the least overlap to `overlap` where that is less.
  void lower(double overlap) { least_ = std::min(least_, overlap); }
  /// What an axis must not pass to be among the near ones: the least so far
  /// and the window.
  double near_limit() const { return least_ + window_; }
  /// Axis k, written with this overlap, may end within the window.
  void near(size_t k) { near_.push_back(k); }

  void rank(std::vector<RankedAxis>& axes) const {
    if (axes.empty()) return;
    // Swapping keeps the front in its order (it only ever moves forward past
    // axes of the rest) and scrambles only the rest. Each swap touches the
    // front and axis k, neither after k: the axes after k are as written
    // when their turn comes.
    size_t front = 0;
    for (const size_t k : near_)
      if (axes[k].overlap <= least_ + window_) std::swap(axes[front++], axes[k]);
    const auto by_overlap = [](const RankedAxis& x, const RankedAxis& y) { return x.overlap < y.overlap; };
    if (front < 3) {
      front = std::min<size_t>(3, axes.size());
      std::partial_sort(axes.begin(), axes.begin() + front, axes.end(), by_overlap);
    }
    if (front <= 16) {
      // Insertion sort: stable, and no buffer for the usual handful of axes.
      for (size_t k = 1; k < front; ++k)
        for (size_t j = k; j > 0 && by_overlap(axes[j], axes[j - 1]); --j) std::swap(axes[j], axes[j - 1]);
    } else {
      std::stable_sort(axes.begin(), axes.begin() + front, by_overlap);
    }
  }

 private:
  double window_;
  double least_ = INFINITY;
  std::vector<size_t> near_;
};

}  // namespace

std::vector<RankedAxis> rank_sat_axes(const Scene& s, double* least_reverse) {
  const PointColumns a(s.world_a), b(s.world_b);
  const auto& edges_a = s.hull_a.edges();
  const auto& edges_b = s.hull_b.edges();
  AxisRanking ranking(s.length_tolerance(kRankedWindow));
  double least_reverse_found = INFINITY;  // a face axis's other way is no facet: +inf
  // Room for every candidate, each written once: sized with zeroed axes
  // first and written over, the vector was walked twice.
  std::vector<RankedAxis> axes;
  axes.reserve(s.hull_a.face_count() + s.hull_b.face_count() + edges_a.size() * edges_b.size());
  const auto add_face = [&](const RankedAxis& axis) {
    ranking.lower(axis.overlap);
    if (axis.overlap <= ranking.near_limit()) ranking.near(axes.size());
    axes.push_back(axis);
  };
  for (int f = 0; f < s.hull_a.face_count(); ++f)
    add_face(ranked_axis(a, b, s.pose_a.rotate(s.hull_a.face_normal(f)), AxisKind::face_a, f, -1));
  for (int f = 0; f < s.hull_b.face_count(); ++f)
    add_face(ranked_axis(a, b, s.pose_b.rotate(s.hull_b.face_normal(f)), AxisKind::face_b, -1, f));
  // The edge pairs a row at a time: one edge of A against every edge of B,
  // the row's axes as columns, each vertex projected onto the whole row in
  // vector lanes. Each projection is the same sum as PointColumns::project's,
  // (x + y) + z, so every overlap is the same to the bit; per axis, the
  // loops over eight vertices left the lanes mostly idle.
  const size_t row = edges_b.size();
  std::vector<double> columns(14 * row);
  double *vx = columns.data(), *vy = vx + row, *vz = vy + row;  // B's edge vectors
  double *nx = vz + row, *ny = nx + row, *nz = ny + row;        // the row's unit axes
  double *length_b = nz + row, *min_a = length_b + row, *max_a = min_a + row;
  double *min_b = max_a + row, *max_b = min_b + row;
  double *way = max_b + row, *overlap = way + row, *reverse = overlap + row;
  // A row's axes are written here first, then appended together: pushed
  // one by one, the vector's end went back to memory with every axis (the
  // oracle took 1.07x the time on 32-point hulls).
  std::vector<RankedAxis> row_axes(row);
  for (size_t j = 0; j < row; ++j) {
    const Vec3 v = s.world_b[edges_b[j].v1] - s.world_b[edges_b[j].v0];
    vx[j] = v.x(), vy[j] = v.y(), vz[j] = v.z(), length_b[j] = v.norm();
  }
  for (size_t i = 0; i < edges_a.size(); ++i) {
    const Vec3 ea = s.world_a[edges_a[i].v1] - s.world_a[edges_a[i].v0];
    const double length_a = ea.norm();
    axes_of_row(ea, length_a, vx, vy, vz, length_b, row, nx, ny, nz);
    project_row(a, nx, ny, nz, row, min_a, max_a);
    project_row(b, nx, ny, nz, row, min_b, max_b);
    double row_least = INFINITY, row_least_reverse = INFINITY;
    ways_of_row(nx, ny, nz, min_a, max_a, min_b, max_b, row, way, overlap, reverse, row_least, row_least_reverse);
    ranking.lower(row_least);
    least_reverse_found = std::min(least_reverse_found, row_least_reverse);
    const double near_limit = ranking.near_limit();
    const size_t first = axes.size();
    size_t kept = 0;
    for (size_t j = 0; j < row; ++j) {
      if (nx[j] == 0 && ny[j] == 0 && nz[j] == 0) continue;  // parallel edges: no axis
      if (overlap[j] <= near_limit) ranking.near(first + kept);
      row_axes[kept++] = {Vec3(way[j] * nx[j], way[j] * ny[j], way[j] * nz[j]), overlap[j], reverse[j],
                          AxisKind::edge_edge, static_cast<int>(i), static_cast<int>(j)};
    }
    axes.insert(axes.end(), row_axes.begin(), row_axes.begin() + static_cast<std::ptrdiff_t>(kept));
  }
  ranking.rank(axes);
  if (least_reverse) *least_reverse = least_reverse_found;
  return axes;
}

double least_reverse_overlap(const std::vector<RankedAxis>& ranked) {
  double least = INFINITY;
  for (const RankedAxis& axis : ranked) least = std::min(least, axis.reverse_overlap);
  return least;
}

double depth_after_moving_b(const std::vector<RankedAxis>& axes, const Vec3& t, double stop_at) {
  double depth = INFINITY;
  for (const RankedAxis& axis : axes) {
    const double along = axis.normal.dot(t);
    depth = std::min({depth, axis.overlap - along, axis.reverse_overlap + along});
    if (depth <= stop_at) return depth;
  }
  return depth;
}

bool surely_overlapping_after_moving_b(const std::vector<RankedAxis>& ranked, const Vec3& t) {
  // |n . t| rounds to at most |t| (1 + 8 ulps) for |n| within ulps of 1;
  // an overlap above it, less it, stays above zero once rounded.
  return !ranked.empty() && ranked[0].overlap > t.norm() * (1 + 1e-12);
}

bool has_axis_tie(const std::vector<RankedAxis>& ranked, double tie, double least_reverse) {
  if (ranked.empty()) return false;
  // docs/contract.md's ties: two candidates within `tie` that can lead to other
  // manifolds: axes pointing other ways (a face axis and a slightly tilted
  // edge axis among them: a polygon or one point), and two faces of one hull
  // (two reference polygons). Candidates along one direction are one face of
  // the Minkowski difference: a face of A and a parallel face of B clip to the
  // same region, an edge pair along a face normal lies in those faces, and
  // parallel edge pairs give one axis. None of those is a tie.
  // "Along one direction" is the generator's coplanarity (a sine of 1e-11):
  // a cosine test cannot see angles near 1e-6, as 1 - cos underflows.
  const RankedAxis& best = ranked[0];
  // An edge pair's other way is a facet of A - B too: crossing needles
  // overlap by their thickness both ways, and n and -n tie (the contract's
  // symmetric case). Those overlaps are not ranked; the least of them tells.
  if (least_reverse - best.overlap <= tie) return true;
  int face_a = -1, face_b = -1;
  for (size_t k = 0; k < ranked.size() && ranked[k].overlap - best.overlap <= tie; ++k) {
    const RankedAxis& other = ranked[k];
    if (!coplanar_normals(other.normal, best.normal)) return true;
    if (other.kind == AxisKind::face_a) {
      if (face_a >= 0 && face_a != other.feature_a) return true;
      face_a = other.feature_a;
    }
    if (other.kind == AxisKind::face_b) {
      if (face_b >= 0 && face_b != other.feature_b) return true;
      face_b = other.feature_b;
    }
  }
  return false;
}

bool has_minimal_face_axis(const std::vector<RankedAxis>& ranked, double tie) {
  for (size_t k = 0; k < ranked.size() && ranked[k].overlap - ranked[0].overlap <= tie; ++k)
    if (ranked[k].kind != AxisKind::edge_edge && coplanar_normals(ranked[k].normal, ranked[0].normal)) return true;
  return false;
}

}  // namespace mfz

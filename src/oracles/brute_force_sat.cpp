#include "oracles/brute_force_sat.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "posed_hull.h"
#include "tolerances.h"

namespace mfz {

double directed_overlap(const std::vector<Vec3>& world_a, const std::vector<Vec3>& world_b, const Vec3& n) {
  double max_a = -std::numeric_limits<double>::infinity(), min_b = std::numeric_limits<double>::infinity();
  for (const Vec3& p : world_a) max_a = std::max(max_a, n.dot(p));
  for (const Vec3& p : world_b) min_b = std::min(min_b, n.dot(p));
  return max_a - min_b;
}

namespace {

// A face of A counts outward and a face of B inward only: those are the faces
// of the Minkowski difference (reversed, a face normal meets an edge or a
// vertex of its hull). Edge pairs count either way.
void add_axis(const Scene& s, const Vec3& axis, AxisKind kind, int fa, int fb, std::vector<RankedAxis>& out) {
  // One pass gives both directions: along = max_a - min_b, against = max_b - min_a.
  double min_a = INFINITY, max_a = -INFINITY, min_b = INFINITY, max_b = -INFINITY;
  for (const Vec3& p : s.world_a) {
    const double d = axis.dot(p);
    min_a = std::min(min_a, d), max_a = std::max(max_a, d);
  }
  for (const Vec3& p : s.world_b) {
    const double d = axis.dot(p);
    min_b = std::min(min_b, d), max_b = std::max(max_b, d);
  }
  const double along = max_a - min_b, against = max_b - min_a;
  constexpr double no_facet = INFINITY;
  if (kind == AxisKind::face_a) return out.push_back({axis, along, no_facet, kind, fa, fb});
  if (kind == AxisKind::face_b) return out.push_back({-axis, against, no_facet, kind, fa, fb});
  if (along <= against)
    out.push_back({axis, along, against, kind, fa, fb});
  else
    out.push_back({-axis, against, along, kind, fa, fb});
}

}  // namespace

std::vector<RankedAxis> rank_sat_axes(const Scene& s) {
  std::vector<RankedAxis> axes;
  axes.reserve(s.hull_a.face_count() + s.hull_b.face_count() + s.hull_a.edges().size() * s.hull_b.edges().size());
  for (int f = 0; f < s.hull_a.face_count(); ++f)
    add_axis(s, s.pose_a.rotate(s.hull_a.face_normal(f)), AxisKind::face_a, f, -1, axes);
  for (int f = 0; f < s.hull_b.face_count(); ++f)
    add_axis(s, s.pose_b.rotate(s.hull_b.face_normal(f)), AxisKind::face_b, -1, f, axes);
  const auto& edges_a = s.hull_a.edges();
  const auto& edges_b = s.hull_b.edges();
  for (size_t i = 0; i < edges_a.size(); ++i) {
    const Vec3 ea = s.world_a[edges_a[i].v1] - s.world_a[edges_a[i].v0];
    for (size_t j = 0; j < edges_b.size(); ++j) {
      const Vec3 eb = s.world_b[edges_b[j].v1] - s.world_b[edges_b[j].v0];
      const Vec3 axis = ea.cross(eb);
      const double length = axis.norm();
      if (length <= tol::kParallelEdges * ea.norm() * eb.norm()) continue;
      add_axis(s, axis / length, AxisKind::edge_edge, static_cast<int>(i), static_cast<int>(j), axes);
    }
  }
  std::stable_sort(axes.begin(), axes.end(),
                   [](const RankedAxis& x, const RankedAxis& y) { return x.overlap < y.overlap; });
  return axes;
}

double depth_after_moving_b(const std::vector<RankedAxis>& axes, const Vec3& t) {
  double depth = INFINITY;
  for (const RankedAxis& axis : axes) {
    const double along = axis.normal.dot(t);
    depth = std::min({depth, axis.overlap - along, axis.reverse_overlap + along});
  }
  return depth;
}

bool has_axis_tie(const std::vector<RankedAxis>& ranked, double tie) {
  if (ranked.empty()) return false;
  // CONTRACT.md's ties: two candidates within `tie` that can lead to other
  // manifolds: axes pointing other ways (a face axis and a slightly tilted
  // edge axis among them: a polygon or one point), and two faces of one hull
  // (two reference polygons). Candidates along one direction are one face of
  // the Minkowski difference: a face of A and a parallel face of B clip to the
  // same region, an edge pair along a face normal lies in those faces, and
  // parallel edge pairs give one axis. None of those is a tie.
  // "Along one direction" is the generator's coplanarity (a sine of 1e-11):
  // a cosine test cannot see angles near 1e-6, as 1 - cos underflows.
  const RankedAxis& best = ranked[0];
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

}  // namespace mfz

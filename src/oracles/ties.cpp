#include "oracles/ties.h"

#include <algorithm>
#include <cmath>

#include "geometry/posed_hull.h"
#include "geometry/tolerances.h"

namespace mfz {
namespace {

// The greatest projection of `points` on `d`.
double extreme(const std::vector<Vec3>& points, const Vec3& d) {
  double best = -INFINITY;
  for (const Vec3& p : points) best = std::max(best, d.dot(p));
  return best;
}

// Two or more faces touching the support of `hull` along `d` (vertices within
// `window` of the extreme) are equally aligned with `d`, to `alignment_tie`.
bool tied_incident_faces(const Hull& hull, const Pose& pose, const std::vector<Vec3>& world, const Vec3& d,
                         double window, double alignment_tie) {
  const double top = extreme(world, d);
  double best = -INFINITY;
  std::vector<double> alignments;
  for (int f = 0; f < hull.face_count(); ++f) {
    bool touches = false;
    for (int k = 0; k < hull.face_size(f) && !touches; ++k) touches = d.dot(world[hull.face_vertex(f, k)]) >= top - window;
    if (!touches) continue;
    const double alignment = pose.rotate(hull.face_normal(f)).dot(d);
    alignments.push_back(alignment);
    best = std::max(best, alignment);
  }
  const auto equal = std::count_if(alignments.begin(), alignments.end(),
                                   [&](double a) { return a >= best - alignment_tie; });
  return equal >= 2;
}

// A face of `hull` perpendicular to `d` to within `resolution`: whether it
// faces the other hull is rounding.
bool has_perpendicular_face(const Hull& hull, const Pose& pose, const Vec3& d, double resolution) {
  for (int f = 0; f < hull.face_count(); ++f)
    if (std::abs(pose.rotate(hull.face_normal(f)).dot(d)) <= resolution) return true;
  return false;
}

// More than one edge of `hull` has both ends within `window` of its support along `d`.
bool several_supporting_edges(const Hull& hull, const std::vector<Vec3>& world, const Vec3& d, double window) {
  const double top = extreme(world, d);
  int count = 0;
  for (const HullEdge& e : hull.edges())
    if (d.dot(world[e.v0]) >= top - window && d.dot(world[e.v1]) >= top - window && ++count > 1) return true;
  return false;
}

}  // namespace

Ties classify_ties(const Scene& s, const std::vector<RankedAxis>& ranked, double tie, double least_reverse) {
  Ties ties;
  if (ranked.empty()) return ties;
  const RankedAxis& best = ranked[0];
  const double window = s.length_tolerance(tol::kSupportWindow);
  // An edge pair's other way is a facet of A - B too (crossing needles
  // overlap by their thickness both ways); those overlaps are not ranked,
  // and the least of them tells (h4).
  if (least_reverse - best.overlap <= tie) ties.direction = true;
  for (size_t k = 1; k < ranked.size() && ranked[k].overlap - best.overlap <= tie; ++k) {
    const RankedAxis& other = ranked[k];
    if (!coplanar_normals(other.normal, best.normal)) {
      ties.direction = true;
      continue;
    }
    const bool same_feature = other.kind == best.kind && other.feature_a == best.feature_a &&
                              other.feature_b == best.feature_b;
    if (!same_feature) ties.feature = true;
  }
  const Vec3& n = best.normal;
  // A profile's precision (float) resolves alignments only to its ulps.
  const double alignment_tie = tol::kIncidentAlignment + tol::kWorldUlps * s.precision_epsilon;
  ties.incident_face = tied_incident_faces(s.hull_a, s.pose_a, s.world_a, n, window, alignment_tie) ||
                       tied_incident_faces(s.hull_b, s.pose_b, s.world_b, -n, window, alignment_tie);
  ties.perpendicular_face = s.precision_epsilon > 0 && (has_perpendicular_face(s.hull_a, s.pose_a, n, alignment_tie) ||
                                                        has_perpendicular_face(s.hull_b, s.pose_b, n, alignment_tie));
  for (size_t k = 0; k < ranked.size() && ranked[k].overlap - best.overlap <= tie && !ties.supporting_edge; ++k)
    if (ranked[k].kind == AxisKind::edge_edge)
      ties.supporting_edge = several_supporting_edges(s.hull_a, s.world_a, ranked[k].normal, window) ||
                             several_supporting_edges(s.hull_b, s.world_b, -ranked[k].normal, window);
  return ties;
}

Ties classify_ties_along(const Scene& s, const std::vector<RankedAxis>& ranked, const Vec3& normal, double tie) {
  const RankedAxis* along = nullptr;
  for (const RankedAxis& axis : ranked)
    if (axis.kind != AxisKind::edge_edge && coplanar_normals(axis.normal, normal) &&
        (!along || axis.overlap < along->overlap))
      along = &axis;
  if (!along) {
    Ties open;
    open.direction = true;
    return open;
  }
  // The ranking is sorted only near the least axis: every axis is read.
  std::vector<RankedAxis> near{*along};
  for (const RankedAxis& axis : ranked)
    if (&axis != along && std::abs(axis.overlap - along->overlap) <= tie) near.push_back(axis);
  std::sort(near.begin() + 1, near.end(),
            [](const RankedAxis& x, const RankedAxis& y) { return x.overlap < y.overlap; });
  return classify_ties(s, near, tie, least_reverse_overlap(near));
}

}  // namespace mfz

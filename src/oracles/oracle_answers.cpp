#include "oracles/oracle_answers.h"

#include <algorithm>
#include <cmath>

#include "geometry/tolerances.h"

namespace mfz {

namespace {

// Along a face axis among the least along that direction, the depth gets
// no room: a face's normal is known to the rounding of its own plane,
// however nearly parallel the edges that also span it (a tetrahedron around
// a cube, an edge pair along A's face normal: Bullet's recorded depth-exact
// finding, B3, which a first version passed).
LeastEdgePair least_edge_pair(const Scene& s, const std::vector<RankedAxis>& axes, bool face_contact) {
  LeastEdgePair pair;
  if (axes.empty() || axes[0].kind != AxisKind::edge_edge) return pair;
  pair.along_a_face = face_contact;
  const HullEdge& ea = s.hull_a.edges()[axes[0].feature_a];
  const HullEdge& eb = s.hull_b.edges()[axes[0].feature_b];
  const Vec3 a = s.world_a[ea.v1] - s.world_a[ea.v0];
  const Vec3 b = s.world_b[eb.v1] - s.world_b[eb.v0];
  const double sine = a.cross(b).norm() / (a.norm() * b.norm());
  if (!(sine > 0)) return pair;
  pair.present = true;
  pair.sine = sine;
  pair.shorter_edge = std::min(a.norm(), b.norm());
  pair.conditioning = sine * pair.shorter_edge / s.scale;
  return pair;
}

}  // namespace

OracleAnswers consult_oracles(const Scene& s) {
  OracleAnswers o;
  o.sat_axes = rank_sat_axes(s, &o.least_reverse_overlap);
  o.exact = exact_depth(s, o.sat_axes);
  const double touching = s.length_tolerance(tol::kTouching);
  o.ccd = ask_libccd(s);
  o.touching = std::abs(o.exact.signed_depth) <= touching;
  o.axis_tie = has_axis_tie(o.sat_axes, s.length_tolerance(tol::kTie), o.least_reverse_overlap);
  o.ties = classify_ties(s, o.sat_axes, s.length_tolerance(tol::kTie), o.least_reverse_overlap);
  o.face_contact = has_minimal_face_axis(o.sat_axes, s.length_tolerance(tol::kTie));
  o.least_edge_pair = least_edge_pair(s, o.sat_axes, o.face_contact);
  return o;
}

}  // namespace mfz

#include "generator/box_axis.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/parallelepiped.h"
#include "geometry/tolerances.h"

namespace mfz {

namespace {

// A box as SAT needs it: its centre, the unit directions of its three
// edge zones (hull_topology.h) and half their lengths, so that its reach
// from the centre along a unit axis is a sum of three products, and two
// boxes' fifteen axes are read off the nine cosines between their
// directions (the oriented-box test of Gottschalk, Lin and Manocha).
struct BoxFrame {
  Vec3 centre = Vec3::Zero();
  Vec3 axis[3];
  double half[3];
};

// Whether the hull is a box (geometry/parallelepiped.h: a parallelepiped
// whose three edge vectors are square to tol::kBoxSquareness in the hull's
// own frame, where a box's corners are exact), and its frame in the world.
// Square edges make the cosines between two boxes' directions their whole
// rotation, and make each face beside a box's incident face run straight
// into the box.
bool box_frame(const PosedHull& hull, BoxFrame& box) {
  if (!is_box(hull)) return false;
  for (int z = 0; z < 3; ++z) {
    const Vec3 world = zone_direction(hull, z);
    const double length = world.norm();
    box.axis[z] = world / length;
    box.half[z] = 0.5 * length;
  }
  for (int v = 0; v < 8; ++v) box.centre += hull.world_vertex(v);
  box.centre /= 8;
  return true;
}

// One face axis of the race: whose box, which direction, which way out.
struct FaceAxis {
  AxisKind kind = AxisKind::face_a;
  int direction = -1;
  double sign = 1;
};

// The best face axis, and the least overlap of every other face. Every
// face is counted only in its own direction (F7). Near a tie the race
// answers nothing, so the order it meets faces in does not matter.
struct FaceRace {
  double best = std::numeric_limits<double>::infinity(), runner_up = std::numeric_limits<double>::infinity();
  FaceAxis winner;
  void enter(double overlap, AxisKind kind, int direction, double sign) {
    if (overlap < best) {
      runner_up = best, best = overlap, winner = {kind, direction, sign};
    } else {
      runner_up = std::min(runner_up, overlap);
    }
  }
};

// The face of `hull` whose normal is `direction` (a box's faces' normals
// are its edge directions, each way), or -1 where none is within 1e-6.
int face_along(const PosedHull& hull, const Vec3& direction) {
  for (int f = 0; f < hull.face_count(); ++f)
    if (hull.world_face_normal(f).dot(direction) > 1 - 1e-6) return f;
  return -1;
}

// The face of `hull` most aligned with `direction`, and by how much it
// leads the next. Nothing ties in a box but two faces nearly equally
// turned, and the significant-face rules pick the most aligned face of a
// box when none ties (significant_faces.h: the faces at a box's support
// corner, edge or face are the faces that face `direction`).
int most_aligned_face(const PosedHull& hull, const Vec3& direction, double& lead) {
  double best = -2, second = -2;
  int face = -1;
  for (int f = 0; f < hull.face_count(); ++f) {
    const double alignment = hull.world_face_normal(f).dot(direction);
    if (alignment > best) {
      second = best, best = alignment, face = f;
    } else {
      second = std::max(second, alignment);
    }
  }
  lead = best - second;
  return face;
}

// Two boxes as the oriented-box test reads them: the cosines between their
// directions, the centres' offset in each box's directions, and each box's
// reach along the other's directions.
struct BoxPair {
  const BoxFrame &a, &b;
  double cosine[3][3], size[3][3], along_a[3], along_b[3], reach_a[3], reach_b[3];

  BoxPair(const BoxFrame& box_a, const BoxFrame& box_b) : a(box_a), b(box_b) {
    const Vec3 offset = b.centre - a.centre;
    for (int i = 0; i < 3; ++i) {
      along_a[i] = offset.dot(a.axis[i]);
      along_b[i] = offset.dot(b.axis[i]);
      for (int j = 0; j < 3; ++j) cosine[i][j] = a.axis[i].dot(b.axis[j]), size[i][j] = std::abs(cosine[i][j]);
    }
    // B's reach along A's direction i, A's along B's j.
    for (int i = 0; i < 3; ++i) {
      reach_b[i] = b.half[0] * size[i][0] + b.half[1] * size[i][1] + b.half[2] * size[i][2];
      reach_a[i] = a.half[0] * size[0][i] + a.half[1] * size[1][i] + a.half[2] * size[2][i];
    }
  }

  // Every face axis, each in its own direction (F7).
  FaceRace face_race() const {
    FaceRace race;
    for (int i = 0; i < 3; ++i)
      for (const double sign : {1.0, -1.0}) {
        race.enter(a.half[i] + reach_b[i] - sign * along_a[i], AxisKind::face_a, i, sign);
        race.enter(b.half[i] + reach_a[i] + sign * along_b[i], AxisKind::face_b, i, sign);
      }
    return race;
  }
};

// The nine edge axes, A's direction i across B's j: each one's overlap
// (the lesser of its two ways, a box being symmetric about its centre), and
// what the box frames' rounding may move it by, which grows as the edges
// near parallel (the axis is their cross product divided by its length).
struct EdgeRace {
  double overlap[3][3], rounding[3][3];
  int best_i = -1, best_j = -1;

  // False where two edges are within 1e-6 of parallel: the bounded SAT's
  // test of parallel edges (1e-9) may fall either side.
  bool run(const BoxPair& p, double box_rounding) {
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const double length2 = 1 - p.cosine[i][j] * p.cosine[i][j];
        if (!(length2 > 1e-12)) return false;
        const int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
        const double reaches = p.a.half[i1] * p.size[i2][j] + p.a.half[i2] * p.size[i1][j] +
                               p.b.half[j1] * p.size[i][j2] + p.b.half[j2] * p.size[i][j1];
        const double apart = std::abs(p.along_a[i2] * p.cosine[i1][j] - p.along_a[i1] * p.cosine[i2][j]);
        const double length = std::sqrt(length2);
        overlap[i][j] = (reaches - apart) / length;
        rounding[i][j] = box_rounding / length;
        if (best_i < 0 || overlap[i][j] < overlap[best_i][best_j]) best_i = i, best_j = j;
      }
    return true;
  }
  // Every edge axis overlaps more than `beaten` beyond its rounding: none
  // replaces the face.
  bool all_above(double beaten) const {
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        if (!(overlap[i][j] - rounding[i][j] > beaten)) return false;
    return true;
  }
  // The least edge axis overlaps less than every other beyond both their
  // roundings: SAT's last replacement is it, in any order.
  bool clear_winner() const {
    const double top = overlap[best_i][best_j] + rounding[best_i][best_j];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        if ((i != best_i || j != best_j) && !(overlap[i][j] - rounding[i][j] > top)) return false;
    return true;
  }
};

// The face axis `race` won, as the bounded SAT answers it: the face's own
// normal and both hulls projected onto it; and the other box's incident
// face. False where the incident face is not clear or lies parallel (F50).
bool decide_face_axis(const PosedHull& a, const PosedHull& b, const BoxPair& p, const FaceRace& race, double rounding,
                      BoxAxis& out) {
  const bool face_of_a = race.winner.kind == AxisKind::face_a;
  const PosedHull& reference = face_of_a ? a : b;
  const PosedHull& other = face_of_a ? b : a;
  const BoxFrame& reference_box = face_of_a ? p.a : p.b;
  const BoxFrame& other_box = face_of_a ? p.b : p.a;
  const int reference_face = face_along(reference, race.winner.sign * reference_box.axis[race.winner.direction]);
  if (reference_face < 0) return false;
  const Vec3 axis = reference.world_face_normal(reference_face);
  const Interval ia = a.project(axis), ib = b.project(axis);
  SatResult sat;
  sat.normal = face_of_a ? axis : Vec3(-axis);
  sat.depth = face_of_a ? ia.max - ib.min : ib.max - ia.min;
  sat.kind = race.winner.kind;
  sat.feature_a = face_of_a ? reference_face : -1;
  sat.feature_b = face_of_a ? -1 : reference_face;
  // The incident face: the other box's face most aligned against the
  // reference face, clear of the next by more than a tie, and not its
  // mirror (F50 clips a face of each with equal areas both ways round).
  double lead = 0;
  const int incident = most_aligned_face(other, -axis, lead);
  if (!(lead > tol::kBoxIncidentLead)) return false;
  const Vec3 incident_normal = other.world_face_normal(incident);
  if (coplanar_normals(axis, -incident_normal)) return false;
  // F27 adds nothing where the other box stands inside the reference
  // prism's sides (its reach along each side's direction, about the
  // centres' offset, short of the reference box's half) and its corners
  // off the incident face stand above the reference plane (the deepest
  // corner, the incident face's, raised by the box's edge across it).
  const double* offset_in_reference = face_of_a ? p.along_a : p.along_b;
  const double* reach_of_other = face_of_a ? p.reach_b : p.reach_a;
  bool inside_sides = true;
  for (int j = 0; j < 3; ++j)
    if (j != race.winner.direction)
      inside_sides &= std::abs(offset_in_reference[j]) + reach_of_other[j] < reference_box.half[j] - rounding;
  int across = 0;
  for (int k = 1; k < 3; ++k)
    if (std::abs(incident_normal.dot(other_box.axis[k])) > std::abs(incident_normal.dot(other_box.axis[across])))
      across = k;
  const double raised = 2 * other_box.half[across] * std::abs(axis.dot(other_box.axis[across]));
  out.sat = sat;
  out.incident_face = incident;
  out.side_faces_add_nothing = inside_sides && raised - sat.depth > rounding;
  return true;
}

// The edge axis of A's zone i and B's zone j, as SAT's parallelepiped phase
// answers it (sat.cpp): the cross product of the zones' first edges in
// world coordinates, divided by its length, both hulls projected onto it,
// the normal the way B is pushed out less, and each hull's supporting edge
// of its zone.
void decide_edge_axis(const PosedHull& a, const PosedHull& b, int zone_a, int zone_b, BoxAxis& out) {
  const Vec3 axis = zone_direction(a, zone_a).cross(zone_direction(b, zone_b));
  const Vec3 unit = axis / axis.norm();
  const Interval ia = a.project(unit), ib = b.project(unit);
  const double b_above = ia.max - ib.min, b_below = ib.max - ia.min;
  const bool b_along_axis = b_above <= b_below;
  SatResult sat;
  sat.normal = b_along_axis ? unit : Vec3(-unit);
  sat.depth = b_along_axis ? b_above : b_below;
  sat.kind = AxisKind::edge_edge;
  sat.feature_a = supporting_zone_edge(a, zone_a, sat.normal);
  sat.feature_b = supporting_zone_edge(b, zone_b, -sat.normal);
  out.sat = sat;
  out.incident_face = -1;
  out.side_faces_add_nothing = false;
}

}  // namespace

bool clear_box_axis(const PosedHull& a, const PosedHull& b, BoxAxis& out) {
  BoxFrame box_a, box_b;
  if (!box_frame(a, box_a) || !box_frame(b, box_b)) return false;
  const BoxPair pair(box_a, box_b);
  const FaceRace race = pair.face_race();
  // The margins. Rounding: these overlaps and the bounded SAT's differ by
  // the boxes' squareness and parallelism (1e-12 of the size) and the
  // world's rounding. F3's bias and F14's tie take the bounded SAT's slack
  // (sat.cpp), whose size lies between the larger span and twice it: each
  // decision must hold at both ends. An edge pair 6.6e-9 shallower than A's
  // top, under a slack of 7.4e-9 at twice the span, won the bounded SAT at
  // its own (BoxPath.AnswersAsTheGeneralPathToTheBit...).
  const double span = std::max(a.span(), b.span());
  const double world = std::max(a.reach_from_origin(), b.reach_from_origin());
  const double rounding = tol::kBoxAxisRounding * 2 * span + 16 * tol::world_rounding(world + 2 * span);
  const double least_slack = tol::kEdgeAxisBias * span + tol::world_rounding(world);
  const double most_slack = tol::kEdgeAxisBias * 2 * span + tol::world_rounding(world);
  if (!(race.best > rounding)) return false;  // apart, touching, or to rounding
  EdgeRace edges;
  if (!edges.run(pair, rounding)) return false;
  // A face: no edge axis replaces it (each short of F3's bias at the
  // least slack), and no other face ties with it (F14) or nearly.
  if (edges.all_above(race.best - least_slack)) {
    if (!(race.runner_up > race.best + most_slack + rounding)) return false;
    return decide_face_axis(a, b, pair, race, rounding, out);
  }
  // An edge pair: it replaces every face at the most slack, even a face
  // F14 kept over a slightly shallower parallel one, and every other edge
  // pair, and the hulls overlap along it by more than rounding.
  const int i = edges.best_i, j = edges.best_j;
  const double edge_top = edges.overlap[i][j] + edges.rounding[i][j];
  if (!(edge_top + most_slack + rounding < race.best)) return false;
  if (!edges.clear_winner() || !(edges.overlap[i][j] - edges.rounding[i][j] > rounding)) return false;
  decide_edge_axis(a, b, i, j, out);
  return true;
}

}  // namespace mfz

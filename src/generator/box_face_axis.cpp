#include "generator/box_face_axis.h"

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

// Whether the hull is a box, and its frame in the world: a parallelepiped
// (geometry/parallelepiped.h: a cube's loops, each zone's edges parallel,
// so each face is a parallelogram) whose three edge vectors are square to
// tol::kBoxSquareness in the hull's own frame, where a box's corners are
// exact. Square edges make the cosines between two boxes' directions their
// whole rotation, and make each face beside a box's incident face run
// straight into the box.
bool box_frame(const PosedHull& hull, BoxFrame& box) {
  if (!is_parallelepiped(hull)) return false;
  const HullTopology* topology = hull.topology();
  Vec3 edge[3];
  for (int z = 0; z < 3; ++z) {
    const TopologyEdge& e = topology->edge(topology->zone_edge(z, 0));
    edge[z] = hull.local_vertex(e.v1) - hull.local_vertex(e.v0);
  }
  for (int i = 0; i < 3; ++i) {
    const Vec3 &x = edge[i], &y = edge[(i + 1) % 3];
    const double cosine = x.dot(y);
    if (!(cosine * cosine <= tol::kBoxSquareness * tol::kBoxSquareness * x.squaredNorm() * y.squaredNorm()))
      return false;
  }
  for (int z = 0; z < 3; ++z) {
    const TopologyEdge& e = topology->edge(topology->zone_edge(z, 0));
    const Vec3 world = hull.world_vertex(e.v1) - hull.world_vertex(e.v0);
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

}  // namespace

bool clear_box_face_axis(const PosedHull& a, const PosedHull& b, BoxFaceAxis& out) {
  BoxFrame box_a, box_b;
  if (!box_frame(a, box_a) || !box_frame(b, box_b)) return false;
  // The cosines between the boxes' directions, and the centres' offset in
  // each box's directions.
  double cosine[3][3], size[3][3], along_a[3], along_b[3];
  const Vec3 offset = box_b.centre - box_a.centre;
  for (int i = 0; i < 3; ++i) {
    along_a[i] = offset.dot(box_a.axis[i]);
    along_b[i] = offset.dot(box_b.axis[i]);
    for (int j = 0; j < 3; ++j) cosine[i][j] = box_a.axis[i].dot(box_b.axis[j]), size[i][j] = std::abs(cosine[i][j]);
  }
  // Every face axis: B's reach along A's direction i, A's along B's j.
  double reach_b[3], reach_a[3];
  for (int i = 0; i < 3; ++i) {
    reach_b[i] = box_b.half[0] * size[i][0] + box_b.half[1] * size[i][1] + box_b.half[2] * size[i][2];
    reach_a[i] = box_a.half[0] * size[0][i] + box_a.half[1] * size[1][i] + box_a.half[2] * size[2][i];
  }
  FaceRace race;
  for (int i = 0; i < 3; ++i)
    for (const double sign : {1.0, -1.0}) {
      race.enter(box_a.half[i] + reach_b[i] - sign * along_a[i], AxisKind::face_a, i, sign);
      race.enter(box_b.half[i] + reach_a[i] + sign * along_b[i], AxisKind::face_b, i, sign);
    }
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
  if (!(race.runner_up > race.best + most_slack + rounding)) return false;  // faces tie (F14) or nearly
  // Every edge axis, A's direction i across B's j, unnormalised: an edge
  // axis replaces a face only when shallower by F3's bias. Edges within
  // 1e-6 of parallel are left to the bounded SAT, whose test of parallel
  // edges (1e-9) they may be either side of.
  const double edge_beaten = race.best - least_slack;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const double length2 = 1 - cosine[i][j] * cosine[i][j];
      if (!(length2 > 1e-12)) return false;
      const int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
      const double reaches = box_a.half[i1] * size[i2][j] + box_a.half[i2] * size[i1][j] +
                             box_b.half[j1] * size[i][j2] + box_b.half[j2] * size[i][j1];
      const double apart = std::abs(along_a[i2] * cosine[i1][j] - along_a[i1] * cosine[i2][j]);
      if (!(reaches - apart > std::sqrt(length2) * edge_beaten + rounding)) return false;
    }
  // The bounded SAT's normal and depth, to the bit: the face's own normal
  // and both hulls projected onto it.
  const bool face_of_a = race.winner.kind == AxisKind::face_a;
  const PosedHull& reference = face_of_a ? a : b;
  const PosedHull& other = face_of_a ? b : a;
  const BoxFrame& reference_box = face_of_a ? box_a : box_b;
  const BoxFrame& other_box = face_of_a ? box_b : box_a;
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
  const double* offset_in_reference = face_of_a ? along_a : along_b;
  const double* reach_of_other = face_of_a ? reach_b : reach_a;
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

}  // namespace mfz

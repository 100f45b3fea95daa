#include "generator/sat.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>

#include "generator/coplanar_patch.h"
#include "generator/arc_bounds.h"
#include "generator/arc_end_pairs.h"
#include "generator/edge_arcs.h"
#include "generator/edge_pair_batch.h"
#include "generator/pair_bounds.h"
#include "generator/supporting_edges.h"
#include "geometry/parallelepiped.h"
#include "geometry/tolerances.h"

namespace mfz {

double overlap_along(const PosedHull& a, const PosedHull& b, const Vec3& axis, bool& b_along_axis) {
  const Interval ia = a.project(axis), ib = b.project(axis);
  const double b_above = ia.max - ib.min;  // overlap if B is pushed out along +axis
  const double b_below = ib.max - ia.min;  // overlap if B is pushed out along -axis
  b_along_axis = b_above <= b_below;
  return b_along_axis ? b_above : b_below;
}

namespace {

// The area of the face's coplanar patch: a triangulated face weighs as much
// as the whole face it came from.
double face_area_of(const PosedHull& a, const PosedHull& b, const SatResult& axis) {
  return axis.kind == AxisKind::face_a ? patch_area(a, axis.feature_a) : patch_area(b, axis.feature_b);
}

// Faces of the two hulls along one direction with overlaps within the
// slack, which is asked for only when both are faces.
template <class Slack>
bool parallel_face_tie(const SatResult& x, const SatResult& y, Slack&& slack) {
  const bool faces = x.kind != AxisKind::edge_edge && y.kind != AxisKind::edge_edge && x.kind != y.kind;
  return faces && coplanar_normals(x.normal, y.normal) && std::abs(x.depth - y.depth) <= slack();
}

// Tries one candidate axis (unit length). Returns false when it separates.
// An edge axis must beat a face axis by tol::kEdgeAxisBias of the
// extent (F3), and a face normal counts for depth only in the direction of a
// face of the Minkowski difference: A's outward, B's inward (F7). Reversed,
// a face normal still proves separation, but the hull's support along it is
// an edge or a vertex, not that face, and the penetration axis lies among
// the other candidates.
bool consider_projected(const PosedHull& a, const PosedHull& b, const Interval& ia, const Interval& ib,
                        const Vec3& axis, AxisKind kind, int fa, int fb, SatResult& best) {
  const double b_above = ia.max - ib.min, b_below = ib.max - ia.min;
  if (b_above < 0 || b_below < 0) {
    const bool along = b_above <= b_below;
    best = {true, along ? axis : Vec3(-axis), along ? b_above : b_below, kind, fa, fb};
    return false;
  }
  bool b_along_axis = b_above <= b_below;
  if (kind == AxisKind::face_a) b_along_axis = true;
  if (kind == AxisKind::face_b) b_along_axis = false;
  const double overlap = b_along_axis ? b_above : b_below;
  // The margin adds the frame's rounding (F9): far from the origin an edge
  // pair along a face normal can come out smaller by rounding alone. It is
  // the rounding of the vertices' coordinates, not of their projections: a
  // vertex 2.8e17 from A's position projects to 1.2e9 along a normal nearly
  // perpendicular to it, and carries a rounding of 60 into it; an edge pair
  // lying in a sliver's face and a face of B came out 16 shallower than
  // that face in a turned frame, and its one point replaced the sliver's
  // contacts 2e14 long (F38, rigid-motion, manifuzz fuzz after F37).
  //
  // The bias is a fraction of the hulls' size, not only of their extent
  // along the axis: an edge axis tilted 4.6e-12 rad from the face normal of
  // a slab 5e-4 thick, across a needle 0.5 long lying on that face, came
  // out 9e-13 shallower than the face, past a bias of 1e-9 of the 5e-4
  // extent, and its one point stood for an edge lying on the face, 0.15
  // from the middle of the 0.3 it touched (spans-contact-region, manifuzz
  // check --strict --seed 2026112611, F41). The span is at most twice a
  // hull's reach, inside the bounded SAT's room for ties.
  // Measured only where a tie is asked about.
  const auto slack = [&] {
    const double world = std::max(a.reach_from_origin(), b.reach_from_origin());
    const double size = std::max({ia.max - ia.min, ib.max - ib.min, a.span(), b.span()});
    return tol::kEdgeAxisBias * size + tol::world_rounding(world);
  };
  const bool edge_after_face = kind == AxisKind::edge_edge && best.kind != AxisKind::edge_edge;
  const Vec3 normal = b_along_axis ? axis : Vec3(-axis);
  const SatResult candidate{false, normal, overlap, kind, fa, fb};
  if (overlap < best.depth - (edge_after_face ? slack() : 0.0)) {
    // F14: a face that ties with a parallel face of the other hull only
    // rounds below it; the larger face stays the reference, whatever the
    // order of the hulls or the motion.
    if (!(parallel_face_tie(candidate, best, slack) && face_area_of(a, b, candidate) <= face_area_of(a, b, best)))
      best = candidate;
  } else if (parallel_face_tie(candidate, best, slack) && face_area_of(a, b, candidate) > face_area_of(a, b, best)) {
    best = candidate;
  }
  return true;
}

bool consider(const PosedHull& a, const PosedHull& b, const Vec3& axis, AxisKind kind, int fa, int fb,
              SatResult& best) {
  return consider_projected(a, b, a.project(axis), b.project(axis), axis, kind, fa, fb, best);
}

// One edge pair's unit axis, with both hulls' projections onto it. Returns
// false when it separates. `flat` says whether either edge lies between
// coplanar faces; it is asked only of an axis about to win.
template <class FlatTest>
bool consider_projected_pair(const PosedHull& a, const PosedHull& b, const Interval& ia, const Interval& ib,
                             const Vec3& axis, int ea, int eb, SatResult& best, FlatTest&& flat) {
  SatResult candidate = best;
  const bool separated = !consider_projected(a, b, ia, ib, axis, AxisKind::edge_edge, ea, eb, candidate);
  if (!separated && candidate.depth == best.depth) return true;
  if (flat()) return true;
  best = candidate;
  return !separated;
}

// Whether edges are parallel: they span no new axis (a face normal covers
// it), and dividing by a vanishing length would only amplify rounding.
// `length` is their cross product's; `length_a` and `length_b` theirs.
bool parallel_edges(double length_a, double length_b, double length) {
  return length <= tol::kParallelEdges * length_a * length_b;
}
bool parallel_edges(const Vec3& edge_a, const Vec3& edge_b, double length) {
  return parallel_edges(edge_a.norm(), edge_b.norm(), length);
}

Vec3 world_edge(const PosedHull& hull, int v0, int v1) { return hull.world_vertex(v1) - hull.world_vertex(v0); }

// One edge pair's axis, measured in full. Returns false when it separates.
template <class FlatTest>
bool consider_edge_pair(const PosedHull& a, const PosedHull& b, int ea, int a0, int a1, int eb, int b0, int b1,
                        SatResult& best, FlatTest&& flat) {
  const Vec3 edge_a = world_edge(a, a0, a1), edge_b = world_edge(b, b0, b1);
  const Vec3 axis = edge_a.cross(edge_b);
  const double length = axis.norm();
  if (parallel_edges(edge_a, edge_b, length)) return true;
  const Vec3 unit = axis / length;
  return consider_projected_pair(a, b, a.project(unit), b.project(unit), unit, ea, eb, best, flat);
}

// A stretch of B's edges against one edge of A, measured as
// consider_edge_pair measures each pair, with the same bits, but in vector
// lanes: the pairs' axes go into a batch (edge_pair_batch.h), which makes
// them unit and projects both hulls onto all of them at once, then the
// pairs are considered in order. A pair at a time, each waited on its
// square roots, its divisions and two projections: F39's pass over every
// pair of two 51-point hulls just touching took 1.5 million instructions a
// call, a third of a fuzz execution where it ran (manifold_fuzzer, the
// grown corpus).
class EdgePairStretch {
 public:
  static constexpr int kPairs = 64;

  EdgePairStretch(const PosedHull& a, const PosedHull& b) : a_(a), b_(b) {}

  // A's edge v0 -> v1 of `face` is the row's; the stretch is empty.
  void start_row(int ea, int a0, int a1, int face) {
    ea_ = ea, a0_ = a0, a1_ = a1, face_a_ = face;
    edge_a_ = world_edge(a_, a0, a1);
    length_a_ = edge_a_.norm();
    batch_.clear();
  }
  // Adds B's edge eb (v0 -> v1 of `face`); false once the stretch is full.
  bool add(int eb, int b0, int b1, int face) {
    const Vec3 edge_b = world_edge(b_, b0, b1);
    edges_b_[batch_.size()] = {b0, b1, face, edge_b.norm()};
    batch_.add(ea_, eb, edge_a_.cross(edge_b));
    return batch_.has_room_for(1);
  }
  // Considers the stretch's pairs in order, and empties it; false once one
  // separates the hulls.
  bool consider_all(SatResult& best) {
    batch_.project(a_, b_);
    bool apart = false;
    for (int k = 0; k < batch_.size() && !apart; ++k) {
      const EdgeOfB& edge = edges_b_[k];
      if (parallel_edges(length_a_, edge.length, batch_.axis_length(k))) continue;
      apart = !consider_projected_pair(a_, b_, batch_.projection_a(k), batch_.projection_b(k), batch_.axis(k), ea_,
                                       batch_.arc_b(k), best, [&] {
                                         return a_.is_flat_edge(a0_, a1_, face_a_) ||
                                                b_.is_flat_edge(edge.v0, edge.v1, edge.face);
                                       });
    }
    batch_.clear();
    return !apart;
  }

 private:
  struct EdgeOfB {
    int v0, v1, face;
    double length;
  };
  const PosedHull &a_, &b_;
  int ea_ = -1, a0_ = -1, a1_ = -1, face_a_ = -1;
  Vec3 edge_a_ = Vec3::Zero();
  double length_a_ = 0;
  EdgePairBatchOf<kPairs> batch_;
  EdgeOfB edges_b_[kPairs];
};

// Every edge pair: the reference the pruning is checked against, the
// fallback for a hull whose edge arcs are incomplete, and F39's pass.
void all_edge_pairs(const PosedHull& a, const PosedHull& b, SatResult& best) {
  bool separated = false;
  if (!a.has_world_columns() || !b.has_world_columns()) {
    a.for_each_edge([&](int ea, int a0, int a1, int face_a) {
      b.for_each_edge([&](int eb, int b0, int b1, int face_b) {
        separated = !consider_edge_pair(a, b, ea, a0, a1, eb, b0, b1, best, [&] {
          return a.is_flat_edge(a0, a1, face_a) || b.is_flat_edge(b0, b1, face_b);
        });
        return !separated;
      });
      return !separated;
    });
    return;
  }
  EdgePairStretch stretch(a, b);
  a.for_each_edge([&](int ea, int a0, int a1, int face_a) {
    stretch.start_row(ea, a0, a1, face_a);
    b.for_each_edge([&](int eb, int b0, int b1, int face_b) {
      if (!stretch.add(eb, b0, b1, face_b)) separated = !stretch.consider_all(best);
      return !separated;
    });
    if (!separated) separated = !stretch.consider_all(best);
    return !separated;
  });
}

// The harness's fixes F3 (face axes win near-ties), F4 (flat edges span no
// axis), F7 (face normals count one way only) and F14 (parallel faces tie to
// the larger), every axis measured in full: the reference the bounded SAT
// below is checked against.
SatResult sat_every_pair(const PosedHull& a, const PosedHull& b) {
  SatResult best;
  best.depth = std::numeric_limits<double>::infinity();
  for (int f = 0; f < a.face_count(); ++f)
    if (!consider(a, b, a.world_face_normal(f), AxisKind::face_a, f, -1, best)) return best;
  for (int f = 0; f < b.face_count(); ++f)
    if (!consider(a, b, b.world_face_normal(f), AxisKind::face_b, -1, f, best)) return best;
  all_edge_pairs(a, b, best);
  return best;
}

// Two parallelepipeds (geometry/parallelepiped.h): one edge pair per pair of
// directions, each zone's first edge standing for its four, in the order of
// those edges. Every pair of directions spans faces of the Minkowski
// difference and all its edge pairs share one axis, so the nine axes are the
// candidates the Gauss-map test would keep, without building the arcs or
// bounding the 18 or so pairs it keeps (boxes spent two thirds of a call in
// the edge phase). The winning axis is then named by the edges that support
// it, as the crossing pair would have been. The nine axes are projected
// at once, in vector lanes (generator/edge_pair_batch.h), onto the unit axes
// the pair-at-a-time measure divided out, so each is measured on the same
// bits; one pair at a time, the projections were 11% of a box pair's call.
// An axis overlapping no less than the best cannot win (an edge axis
// replaces a face only by F3's bias, another edge only by less), and is
// passed by.
void parallelepiped_edge_axes(const PosedHull& a, const PosedHull& b, SatResult& best) {
  const HullTopology &ta = *a.topology(), &tb = *b.topology();
  Vec3 direction_a[3], direction_b[3];
  for (int z = 0; z < 3; ++z) direction_a[z] = zone_direction(a, z), direction_b[z] = zone_direction(b, z);
  ParallelepipedPairs pairs;
  for (int za = 0; za < 3; ++za)
    for (int zb = 0; zb < 3; ++zb) pairs.add(za, zb, direction_a[za].cross(direction_b[zb]));
  pairs.project(a, b);
  int won_a = -1, won_b = -1;
  for (int k = 0; k < pairs.size(); ++k) {
    const int za = pairs.arc_a(k), zb = pairs.arc_b(k);
    if (parallel_edges(direction_a[za], direction_b[zb], pairs.axis_length(k))) continue;
    if (pairs.least_overlap(k) >= best.depth) continue;
    const SatResult before = best;
    const bool separated = !consider_projected_pair(a, b, pairs.projection_a(k), pairs.projection_b(k), pairs.axis(k),
                                                    ta.zone_edge(za, 0), tb.zone_edge(zb, 0), best, [] { return false; });
    if (separated || best.depth != before.depth || best.kind != before.kind) won_a = za, won_b = zb;
    if (separated) break;
  }
  if (won_a >= 0 && best.kind == AxisKind::edge_edge) {
    best.feature_a = supporting_zone_edge(a, won_a, best.normal);
    best.feature_b = supporting_zone_edge(b, won_b, -best.normal);
  }
}

// The bounded SAT: the same candidates in the same order, each first given a
// cheap lower bound on its overlap, and measured in full (by `consider`, as
// before) only when the bound leaves it a chance to win or to tie. For a face
// of A, A's top along its normal is at least the face's own height and B's
// bottom at most that of any vertex of B, here the one a climb on B's vertices
// reaches (on hulls of up to 32 vertices, B's projection itself); for an edge
// pair, the edges' own vertices bound the overlap one way, the balls inside the
// hulls about their centres the other way, each closed in by a climb where it
// leaves the pair a chance (a 128-point pair measures 0.9 of its 323 crossing
// pairs in full, a 64-gon cylinder pair 0.2 of 2,198, where they measured 35
// and 992 before the balls and the climbs). Large hulls bound more at once,
// before any climb: a face by the other hull's ball, and a whole row of edge
// pairs (an arc of A against every arc of B) over the arc where their axes lie,
// so that most rows and most of B's arcs never reach the crossing test (on
// 128-point hulls 303 of 378 rows end there, and 304 of B's 378 arcs; the
// family's calls take 1.7-2.6x less time, 32-point hulls' 1.3x less). A
// skipped axis could not have changed `best`: its overlap exceeds the best
// by more than any tie's slack. A face normal skipped this way is not a
// separating axis in its own direction; reversed it may be, and then a later
// axis proves the separation (SAT's axes in their own directions suffice),
// with another normal, which a separated manifold does not report.
struct HullSummary {
  Vec3 centre = Vec3::Zero();
  double reach = 0;  ///< largest distance of a vertex from the centre
  double inner = 0;  ///< the radius of a ball about the centre inside the hull
  double extent = 0;  ///< largest absolute world coordinate
};

// summary_of over the world columns: each coordinate summed in the
// vertices' order, as the Vec3 sum adds them, and each squared distance
// summed (x + y) + z, as squaredNorm does, so the same bits; the greatest
// of each is exact in any order, so it runs in lanes. Through Vec3s a box's
// two summaries were 4.6% of its call.
HullSummary summary_of_columns(const PosedHull& hull) {
  const int n = hull.vertex_count();
  const double *xs = hull.world_xs(), *ys = hull.world_ys(), *zs = hull.world_zs();
  double cx = 0, cy = 0, cz = 0;
  for (int i = 0; i < n; ++i) cx += xs[i], cy += ys[i], cz += zs[i];
  const double count = static_cast<double>(n);
  cx /= count, cy /= count, cz /= count;
  double reach2 = 0, extent = 0;
#pragma omp simd reduction(max : reach2, extent)
  for (int i = 0; i < n; ++i) {
    const double dx = xs[i] - cx, dy = ys[i] - cy, dz = zs[i] - cz;
    const double d2 = (dx * dx + dy * dy) + dz * dz;
    reach2 = d2 > reach2 ? d2 : reach2;
    const double largest = std::max(std::max(std::abs(xs[i]), std::abs(ys[i])), std::abs(zs[i]));
    extent = largest > extent ? largest : extent;
  }
  HullSummary s;
  s.centre = Vec3(cx, cy, cz);
  s.reach = std::sqrt(reach2);
  s.extent = extent;
  return s;
}

HullSummary summary_of(const PosedHull& hull) {
  if (hull.has_world_columns()) return summary_of_columns(hull);
  HullSummary s;
  for (int i = 0; i < hull.vertex_count(); ++i) s.centre += hull.world_vertex(i);
  s.centre /= static_cast<double>(hull.vertex_count());
  // The square root of the largest square is the largest root, to the bit.
  double reach2 = 0;
  for (int i = 0; i < hull.vertex_count(); ++i) {
    const Vec3 p = hull.world_vertex(i);
    reach2 = std::max(reach2, (p - s.centre).squaredNorm());
    s.extent = std::max(s.extent, p.cwiseAbs().maxCoeff());
  }
  s.reach = std::sqrt(reach2);
  return s;
}

// The ball inside: the nearest face plane from the centre, less the planes'
// rounding. Only the edge pairs need it; a face axis often separates first.
void add_inner_ball(const PosedHull& hull, HullSummary& s) {
  s.inner = std::numeric_limits<double>::infinity();
  for (int f = 0; f < hull.face_count(); ++f) {
    const Vec3 n = hull.world_face_normal(f);
    s.inner = std::min(s.inner, n.dot(hull.world_face_point(f, 0) - s.centre));
  }
  s.inner = std::max(0.0, s.inner - 4 * tol::world_rounding(s.extent + s.reach));
}

// A corner of face f along its normal n: like any vertex, at most the
// hull's top along n, which is all a lower bound on the overlap needs, and
// the face's corners all lie on its plane, so the first is as high as the
// highest to rounding (taking the highest was 6% of a box pair's call).
double face_height(const PosedHull& hull, int f, const Vec3& n) { return n.dot(hull.world_face_point(f, 0)); }

// Hulls of more vertices than this climb to their support (it needs their
// topology, built on first sight); smaller ones scan their vertices.
constexpr int kClimbFromVertices = 64;

// An edge pair between hulls of at most this many vertices each is bounded
// by its overlap itself: both hulls projected onto its axis in vector lanes,
// which costs less than the balls and four climbs on so few vertices (8-point
// hulls 17% faster, boxes 3-6%, 32-point 3%; the same answers to the bit on
// every bench pair). Up to 64: the fuzzer's 30-gon cylinders, 61 vertices
// each, spent 40% of their property runs bounding edge pairs by climbs
// (their runs 28% faster; random hulls of 48 and 64 points 4-6%). On 64-gon
// cylinders, 128 vertices, the climbs cost less: projecting took 1.5x.
// clang 14 keeps a floating-point min and max reduction out of vector lanes
// unless NaNs and zeros' signs may be ignored, so its projections onto one
// axis take one point at a time, and its builds stopped at 32: up to 64 its
// fuzzer had spent a quarter of its time projecting, twice what the climbs
// cost. The pairs are now projected a batch at a time (edge_pair_batch.h),
// where each axis keeps its bounds in a lane of its own and clang uses the
// lanes too: up to 64 for both compilers. A clang-built manifold_fuzzer
// replays a grown corpus of 2,510 inputs in 4.63-4.75 s where it took
// 5.08-5.16 s with 32.
constexpr int kScanPairVertices = 64;

// A pair with a hull of more vertices than this bounds each face by the
// other hull's ball before it projects or climbs: on 32-point hulls most
// faces face away and end there, where projecting the other hull for each
// of them was an eighth of the call (5% faster; the same answers).
constexpr int kFaceBallVertices = 16;

// Hulls with more edge pairs than this bound each row of pairs first, and
// B's arcs, which leaves most of B's arcs out of the rows' crossing test
// (32-point hulls 5% faster than with every arc tested).
constexpr int kRowBoundPairs = 1000;

int support_towards(const PosedHull& hull, const Vec3& direction, int from) {
  return hull.vertex_count() > kClimbFromVertices ? hull.climb_to_support(direction, from)
                                                  : hull.support_vertex(direction);
}

// Rows of fewer pairs are bounded, and tested for an axis along an arc's
// end, one pair at a time only: a 128-point pair's rows hold one pair on
// average, and with rows of four in lanes the set-up and B's edge vectors
// cost its calls 0.7% more instructions (rows of eight, 0.35%). The arc-end
// test in lanes on rows of 16 or more rather than 8 saved those calls
// 0.03%.
constexpr int kPairsInLanes = 8;

// A row's pairs as bound_pairs_in_lanes reads them: B's edges, gathered.
struct PairBoundWork {
  double b0_x[kMaxArcs], b0_y[kMaxArcs], b0_z[kMaxArcs];
  double edge_x[kMaxArcs], edge_y[kMaxArcs], edge_z[kMaxArcs];
  int64_t hopeless[kMaxArcs];
};

// B's side of a row's pairs gathered for the arc-end test in lanes
// (generator/arc_end_pairs.h), and the pairs it leaves.
struct ArcEndWork {
  double face_x[kMaxArcs], face_y[kMaxArcs], face_z[kMaxArcs];
  double twin_x[kMaxArcs], twin_y[kMaxArcs], twin_z[kMaxArcs];
  double across_x[kMaxArcs], across_y[kMaxArcs], across_z[kMaxArcs];
  double edge_x[kMaxArcs], edge_y[kMaxArcs], edge_z[kMaxArcs];
  int64_t along[kMaxArcs];
  int left[kMaxArcs];  ///< the row's arcs of B not along an end, in the row's order
};

// What SAT's edge phase keeps off the call's stack (the arcs, rows and
// margins, sized for hulls of 1,024 vertices: about 1.3 MB): one per
// thread, allocated on the thread's first call, as a call runs to its end
// before the thread makes another. Allocated, not a thread-local object
// itself, so that a thread that never calls the generator carries none of
// it. Looked up once per call and held by reference: each use of a
// thread-local object inside SAT's lambdas looked its address up again,
// and those lookups were 1.7% of a 32-point call's instructions.
struct SatWorkspace {
  EdgeArcs arcs_a, arcs_b;
  EdgePairBatch batch;
  ArcColumns kept_b;  ///< B's arcs the row bounds leave in
  int kept_index[kMaxArcs];
  int near[kMaxArcs];            ///< a row's crossing arcs
  bool left_out[kMaxArcs];       ///< B's arcs left out of every row
  double row_margin[kMaxArcs];   ///< arcs_above of A's arcs
  double out_margin[kMaxArcs];   ///< and of B's
  double ball_bound_a[kTopologyMaxFaces];  ///< each face of A bounded by B's ball (FaceCeiling)
  double ball_bound_b[kTopologyMaxFaces];  ///< and each face of B by A's
  AxisSupport support;  ///< what an edge axis was named by
  PairBoundWork pairs;  ///< a row's pairs, bounded in lanes
  ArcEndWork arc_ends;  ///< a row's pairs, tested for an axis along an arc's end in lanes
  int measured_in_full = 0;  ///< edge pairs projected in full (edge_pairs_measured_in_full)
  int formed_alone = 0;      ///< large hulls' pairs whose axis was formed one at a time (edge_pairs_formed_alone)
  int faces_past_balls = 0;  ///< faces the other hull's ball left a chance (faces_past_the_balls)
};

[[gnu::noinline]] SatWorkspace& sat_workspace() {
  static thread_local std::unique_ptr<SatWorkspace> work;
  if (!work) work = std::make_unique<SatWorkspace>();
  return *work;
}

// One hull projected onto every face normal of another, in vector lanes
// (project_onto_axes: the bits of projecting onto each alone), for hulls of
// at most kFaceBallVertices each, which bound every face by the other
// hull's whole projection. One face at a time, those projections were a
// tenth of a box pair's call and of an 8-point pair's, and the lanes take
// about half the instructions. A pair that a face separates early has
// projected the other faces for nothing: separated pairs seldom get that
// far, as the last call's axis tries first.
class FaceNormalProjections {
 public:
  /// `other` onto each of `hull`'s face normals; false, projecting nothing,
  /// for a hull of more faces than the columns hold.
  bool project(const PosedHull& hull, const PosedHull& other) {
    const int count = hull.face_count();
    if (count > kFaces) return false;
    for (int f = 0; f < count; ++f) {
      const Vec3 n = hull.world_face_normal(f);
      x_[f] = n.x(), y_[f] = n.y(), z_[f] = n.z();
    }
    other.project_onto_axes(x_, y_, z_, count, low_, high_);
    return true;
  }
  Interval operator[](int f) const { return {low_[f], high_[f]}; }

 private:
  // A closed hull of 16 vertices has at most 28 faces.
  static constexpr int kFaces = 32;
  double x_[kFaces], y_[kFaces], z_[kFaces], low_[kFaces], high_[kFaces];
};

// Large hulls' faces bounded by the other hull's ball, all before any is
// measured, and the overlap along the face the balls bound least, measured
// in full: a ceiling on the depth SAT finds, as the hint's is on the edge
// pairs' (a face axis that wins overlaps at most F14's slack more than
// that face, less than the tie room). A face bounded past it by the room
// could not have won or tied, wherever it comes in the faces' order. Its
// overlap counts in the face's own direction, held at zero or above, so
// that no face that separates the hulls in its own direction is left out.
// Unlike the hint's overlap (F43), it is measured in this call, so every
// call of a pair bounds its faces alike, whatever came before. Bounded
// only by the faces measured before it, each face in the loops' order
// that came before the deepest had its climb and often its measure:
// 128-point hulls climbed 39 times a call and measured 9 faces, and their
// calls take 7% less time since.
class FaceCeiling {
 public:
  /// False, bounding nothing, for a hull of more faces than the workspace
  /// holds.
  bool bound(const PosedHull& a, const PosedHull& b, const HullSummary& sa, const HullSummary& sb, double* ball_a,
             double* ball_b) {
    if (a.face_count() > kTopologyMaxFaces || b.face_count() > kTopologyMaxFaces) return false;
    ball_a_ = ball_a, ball_b_ = ball_b;
    const int least_a = bound_faces(a, sb, ball_a), least_b = bound_faces(b, sa, ball_b);
    if (least_a >= 0) {
      const Vec3 n = a.world_face_normal(least_a);
      ceiling_ = std::min(ceiling_, a.project(n).max - b.project(n).min);
    }
    if (least_b >= 0) {
      const Vec3 n = b.world_face_normal(least_b);
      ceiling_ = std::min(ceiling_, b.project(n).max - a.project(n).min);
    }
    ceiling_ = std::max(0.0, ceiling_);
    return true;
  }
  double ceiling() const { return ceiling_; }
  double ball_a(int f) const { return ball_a_[f]; }
  double ball_b(int f) const { return ball_b_[f]; }

 private:
  // Each face of `hull` bounded by the ball inside `other` (its overlap is
  // at least the face's height over the ball's centre and the ball's
  // radius); returns the face bounded least, or -1 for none.
  static int bound_faces(const PosedHull& hull, const HullSummary& other, double* ball) {
    int least = -1;
    for (int f = 0; f < hull.face_count(); ++f) {
      ball[f] = hull.world_face_normal(f).dot(hull.world_face_point(f, 0) - other.centre) + other.inner;
      if (least < 0 || ball[f] < ball[least]) least = f;
    }
    return least;
  }
  double ceiling_ = std::numeric_limits<double>::infinity();
  const double *ball_a_ = nullptr, *ball_b_ = nullptr;
};

// An edge axis is named by the edges that support the hulls along it, the
// first pair of them (in the hulls' order) that spans it: the same axis to
// kAxisAlongFaceSine, overlapping as deep to the world's rounding. Parallel
// edges give one axis from many pairs, each to its own rounding, and the
// Gauss-map test's slack lets through pairs that do not cross, whose
// bounds then hold only for the pairs that do; which of them SAT measured
// and kept was the bounds' choice, and a hint moves the bounds. The
// supporting pair is a function of the axis alone, so each call answers
// with its bits. A 29-point hull with five edges along one direction
// against a 7-point hull with two: the first call kept A's edge 60 with
// B's 11 (neither supports its hull), the second, bounded by that axis,
// left A's row 60 out and kept 18 with 11, an axis 1.1e-16 off and
// 1.2e-16 deeper (F51, deterministic, manifuzz fuzz --strict, open as O17).
// Where no supporting pair spans the axis, the answer stands as found.
void name_by_supporting_edges(const PosedHull& a, const PosedHull& b, SatResult& best, AxisSupport& support) {
  support.take(a, b, best.normal);
  // SAT's own pair first among the supporting edges of both hulls is the
  // pair the loop below would name first: most often it is the only one.
  if (support.a->first() == best.feature_a && support.b->first() == best.feature_b) {
    best.support = &support;
    return;
  }
  const double rounding = 4 * tol::world_rounding(std::max(a.reach_from_origin(), b.reach_from_origin()));
  const double room = tol::kAxisAlongFaceSine * tol::kAxisAlongFaceSine;
  bool named = false, moved = false;
  support.a->each([&](int ea, int a0, int a1) {
    if (named) return;
    support.b->each([&](int eb, int b0, int b1) {
      if (named) return;
      // SAT's own pair, after others that do not span the axis: measured
      // on these bits already.
      if (ea == best.feature_a && eb == best.feature_b) {
        named = true;
        return;
      }
      const Vec3 edge_a = world_edge(a, a0, a1), edge_b = world_edge(b, b0, b1);
      const Vec3 axis = edge_a.cross(edge_b);
      const double length = axis.norm();
      if (parallel_edges(edge_a, edge_b, length)) return;
      const Vec3 unit = axis / length;
      if (!(unit.cross(best.normal).squaredNorm() <= room)) return;
      const Interval ia = a.project(unit), ib = b.project(unit);
      const bool b_along_axis = unit.dot(best.normal) > 0;
      const double overlap = b_along_axis ? ia.max - ib.min : ib.max - ia.min;
      if (!(std::abs(overlap - best.depth) <= rounding)) return;
      best = {false, b_along_axis ? unit : Vec3(-unit), overlap, AxisKind::edge_edge, ea, eb};
      named = moved = true;
    });
  });
  // Named by another pair: the edges are taken again along its axis, so
  // that the contact reads the sets of the axis answered.
  if (moved) support.take(a, b, best.normal);
  best.support = &support;
}

// Within this of each other two axes' overlaps tie: F41's bias for an edge
// axis, of the hulls' reach, and four times the rounding of the bounds,
// taken at `magnitude`, the largest coordinate they read.
double axis_tie_room(double reach, double magnitude) {
  return tol::kEdgeAxisBias * 2 * reach + 4 * tol::world_rounding(magnitude);
}

// `hint_overlap`: the overlap along the axis that answered the pair's last
// call (infinite without one), which bounds the depth this call finds: no
// axis overlaps less than the penetration depth, and the axis SAT picks
// overlaps at most F3's bias or F14's slack more than the least, each less
// than the tie room. So the hint plus the room is a ceiling on the depth
// found, and an axis bounded past the ceiling by the room again could not
// have won or tied, whatever the axes measured before it. (With the hint
// less the room, SatHint.* finds answers that differ.)
SatResult bounded_sat(const PosedHull& a, const PosedHull& b, double hint_overlap) {
  // Pairs of small hulls bound their edge pairs without the balls.
  const bool scan_pairs = a.vertex_count() <= kScanPairVertices && b.vertex_count() <= kScanPairVertices;
  HullSummary sa = summary_of(a), sb = summary_of(b);
  a.turn_face_normals(), b.turn_face_normals();
  // More than any tie's slack in `consider` (its extents are at most twice
  // the reach), plus the bounds' own rounding.
  const double tie_room =
      axis_tie_room(std::max(sa.reach, sb.reach), std::max(sa.extent, sb.extent) + sa.reach + sb.reach);
  SatResult best;
  best.depth = std::numeric_limits<double>::infinity();
  FaceCeiling faces;  // bounds nothing until `bound`
  const auto hopeless = [&](double lower) { return lower > std::min(best.depth, faces.ceiling()) + tie_room; };
  // The hint bounds the edge pairs only: their bounds hold in both
  // directions along the axis, so no pair left out could have separated
  // the hulls, while a face is bounded in its own direction alone, and its
  // normal reversed may separate hulls that touch to rounding. Bounded by
  // the hint, such a face was left out where the call without the hint
  // measured it first and said apart, and the pair's second call said
  // colliding (F43: a tetrahedron 1.1e-16 behind a face, deterministic,
  // manifuzz check --strict --seed 2026112701). The ceiling is at least
  // the room above zero, so it leaves out no separating axis.
  const double ceiling = std::max(0.0, hint_overlap) + tie_room;
  const auto edge_hopeless = [&](double lower) { return lower > std::min(best.depth, ceiling) + tie_room; };
  bool balls = false;  // sa.inner and sb.inner measured
  const auto measure_balls = [&] {
    if (!balls) add_inner_ball(a, sa), add_inner_ball(b, sb), balls = true;
  };
  // B's ball first bounds a face of A, and A's ball a face of B, at the
  // cost of a dot product: most face away from the other hull. Large hulls
  // then climb to each face's support.
  const bool face_balls = a.vertex_count() > kFaceBallVertices || b.vertex_count() > kFaceBallVertices;
  if (face_balls) measure_balls();
  SatWorkspace& work = sat_workspace();
  work.faces_past_balls = 0;
  const bool balls_kept = face_balls && faces.bound(a, b, sa, sb, work.ball_bound_a, work.ball_bound_b);
  int on_b = 0, on_a = 0;  // where the last climbs ended: the next one starts there
  // Hulls small enough to project whole without the balls: each onto every
  // face normal of the other at once, in vector lanes.
  FaceNormalProjections b_on_a_faces, a_on_b_faces;
  const bool faces_in_lanes = !face_balls && b_on_a_faces.project(a, b) && a_on_b_faces.project(b, a);
  for (int f = 0; f < a.face_count(); ++f) {
    const Vec3 n = a.world_face_normal(f);
    if (face_balls &&
        hopeless(balls_kept ? faces.ball_a(f) : n.dot(a.world_face_point(f, 0) - sb.centre) + sb.inner))
      continue;
    work.faces_past_balls += face_balls;
    if (scan_pairs) {
      // Small hulls: B's whole projection bounds the face, and is kept for
      // `consider` if the face has a chance.
      const Interval ib = faces_in_lanes ? b_on_a_faces[f] : b.project(n);
      if (hopeless(face_height(a, f, n) - ib.min)) continue;
      if (!consider_projected(a, b, a.project(n), ib, n, AxisKind::face_a, f, -1, best)) return best;
      continue;
    }
    on_b = support_towards(b, -n, on_b);
    if (hopeless(face_height(a, f, n) - n.dot(b.world_vertex(on_b)))) continue;
    if (!consider(a, b, n, AxisKind::face_a, f, -1, best)) return best;
  }
  for (int f = 0; f < b.face_count(); ++f) {
    const Vec3 n = b.world_face_normal(f);
    if (face_balls &&
        hopeless(balls_kept ? faces.ball_b(f) : n.dot(b.world_face_point(f, 0) - sa.centre) + sa.inner))
      continue;
    work.faces_past_balls += face_balls;
    if (scan_pairs) {
      const Interval ia = faces_in_lanes ? a_on_b_faces[f] : a.project(n);
      if (hopeless(face_height(b, f, n) - ia.min)) continue;
      if (!consider_projected(a, b, ia, b.project(n), n, AxisKind::face_b, -1, f, best)) return best;
      continue;
    }
    on_a = support_towards(a, -n, on_a);
    if (hopeless(face_height(b, f, n) - n.dot(a.world_vertex(on_a)))) continue;
    if (!consider(a, b, n, AxisKind::face_b, -1, f, best)) return best;
  }
  if (is_parallelepiped(a) && is_parallelepiped(b)) {
    parallelepiped_edge_axes(a, b, best);
    return best;
  }
  work.measured_in_full = 0, work.formed_alone = 0;
  // The answer once every edge pair has had its chance: an edge axis named
  // by its supporting edges (two parallelepipeds name theirs by zones).
  const auto named = [&] {
    if (!best.separated && best.kind == AxisKind::edge_edge) name_by_supporting_edges(a, b, best, work.support);
    return best;
  };
  work.arcs_a.build(a);
  work.arcs_b.build(b);
  const EdgeArcs &arcs_a = work.arcs_a, &arcs_b = work.arcs_b;
  if (!arcs_a.complete() || !arcs_b.complete()) {
    all_edge_pairs(a, b, best);
    return named();
  }
  const bool row_bounds = arcs_a.size() * arcs_b.size() > kRowBoundPairs;
  if (row_bounds || !scan_pairs) measure_balls();
  const Vec3 centres = sb.centre - sa.centre;
  int back_a = 0, back_b = 0;  // where the last climbs against an axis ended
  // Whether A's arc x or B's arc j spans no fold: an edge between
  // coplanar faces gives no axis (F4).
  const auto is_flat_pair = [&](const EdgeArc& x, int j) {
    const EdgeArc arc_b = arcs_b[j];
    return coplanar_normals(x.n_face, x.n_twin) || coplanar_normals(arc_b.n_face, arc_b.n_twin);
  };
  // One edge pair measured in full; false when it separates the hulls.
  const auto measure_pair = [&](int i, const EdgeArc& x, int j) {
    ++work.measured_in_full;
    const ArcIndices& y = arcs_b.indices(j);
    return consider_edge_pair(a, b, i, x.v0, x.v1, j, y.v0, y.v1, best, [&] { return is_flat_pair(x, j); });
  };
  // Small hulls: the pairs that may cross wait in a batch for their
  // projections (generator/edge_pair_batch.h), then are bounded, and those
  // with a chance measured on those projections, in the order they came.
  // False when a pair separates the hulls.
  EdgePairBatch& batch = work.batch;
  batch.clear();
  const auto settle_batch = [&] {
    batch.project(a, b);
    for (int k = 0; k < batch.size(); ++k) {
      if (edge_hopeless(batch.least_overlap(k))) continue;
      const int i = batch.arc_a(k), j = batch.arc_b(k);
      const EdgeArc x = arcs_a[i];
      const ArcIndices& y = arcs_b.indices(j);
      if (parallel_edges(world_edge(a, x.v0, x.v1), world_edge(b, y.v0, y.v1), batch.axis_length(k))) continue;
      ++work.measured_in_full;
      if (!consider_projected_pair(a, b, batch.projection_a(k), batch.projection_b(k), batch.axis(k), i, j, best,
                                   [&] { return is_flat_pair(x, j); }))
        return false;
    }
    batch.clear();
    return true;
  };
  const auto pair_is_hopeless = [&](const EdgeArc& x, const ArcIndices& y, const Vec3& axis) {
    const Vec3 a0 = a.world_vertex(x.v0), b0 = b.world_vertex(y.v0);
    const double length = axis.norm();
    if (!(length > 0)) return false;
    // m leaves A through its edge: along m the edges bound the overlap,
    // against m the balls inside the hulls about their centres do.
    const Vec3 m = (axis.dot(a0 - sa.centre) >= 0 ? axis : Vec3(-axis)) / length;
    // Against m: A's support along -m and B's along m, bounded first by the
    // balls, then, where that leaves the pair a chance, by the vertices a
    // climb reaches (a cylinder's bottom rim against the other's top rim:
    // 990 such pairs per 64-gon pair had the cap contact's depth against m,
    // the balls alone did not tell them from it). The vertices where the
    // last climbs ended bound it before any step: a climb only raises the
    // bound, and the axes of one row lie close together (on 64-gon
    // cylinders the balls left 48% of the pairs, and the last ends told
    // 96% of those, which had cost two climbs each).
    const auto ends_hopeless = [&] {
      return edge_hopeless(m.dot(b.world_vertex(back_b)) - m.dot(a.world_vertex(back_a)));
    };
    if (!edge_hopeless(m.dot(centres) + sa.inner + sb.inner) && !ends_hopeless()) {
      back_a = a.climb_to_support(-m, back_a), back_b = b.climb_to_support(m, back_b);
      if (!ends_hopeless()) return false;
    }
    if (edge_hopeless(m.dot(a0) - m.dot(b0))) return true;
    // Along m the edges are the supports only where the arcs truly cross;
    // where the Gauss-map test's slack let the pair through, a climb from
    // the edges finds vertices further along that bound it closer.
    const int top = a.climb_to_support(m, x.v0), bottom = b.climb_to_support(-m, y.v0);
    return edge_hopeless(m.dot(a.world_vertex(top)) - m.dot(b.world_vertex(bottom)));
  };
  // Large hulls: a row's pairs first bounded all at once, in vector lanes,
  // by the bounds pair_is_hopeless takes before it climbs, with the row's
  // last climbs' ends and threshold (generator/pair_bounds.h); those they
  // leave go to pair_is_hopeless one at a time, as before. A 64-gon
  // cylinder's rim against the other's rim gives 2,048 pairs a call that
  // the Gauss test lets through, nearly all hopeless: bound alone, each
  // took about 200 instructions; the lanes tell 88% of them, and the
  // benchmark's cylinders take 20% fewer instructions a call.
  PairBoundWork& pairs = work.pairs;
  bool edge_vectors_b = false;  // written by the call's first row of kPairsInLanes pairs or more
  const auto bound_row_in_lanes = [&](const EdgeArc& x, const Vec3& edge_a, const int* js, int count) {
    const ArcColumns& columns_b = arcs_b.columns();
    const EdgeVectors& edges_b = arcs_b.edge_vectors();
    RowOfPairs row;
    row.edge_a = edge_a;
    row.vertex_a = a.world_vertex(x.v0);
    row.out_of_a = row.vertex_a - sa.centre;
    row.centres = centres;
    row.inner_a = sa.inner, row.inner_b = sb.inner;
    row.back_a = a.world_vertex(back_a), row.back_b = b.world_vertex(back_b);
    row.threshold = std::min(best.depth, ceiling) + tie_room;
    for (int k = 0; k < count; ++k) {
      const int j = js[k];
      pairs.b0_x[k] = columns_b.v0_x[j], pairs.b0_y[k] = columns_b.v0_y[j], pairs.b0_z[k] = columns_b.v0_z[j];
      pairs.edge_x[k] = edges_b.x[j], pairs.edge_y[k] = edges_b.y[j], pairs.edge_z[k] = edges_b.z[j];
    }
    for (int k = count; k < lanes_of(count); ++k)
      pairs.b0_x[k] = pairs.b0_y[k] = pairs.b0_z[k] = pairs.edge_x[k] = pairs.edge_y[k] = pairs.edge_z[k] = 0;
    bound_pairs_in_lanes(row, {pairs.b0_x, pairs.b0_y, pairs.b0_z, pairs.edge_x, pairs.edge_y, pairs.edge_z}, count,
                         pairs.hopeless);
    return pairs.hopeless;
  };
  // Of the `count` pairs of a row of many on large hulls (B's arcs in
  // ends.left), those whose axis lies along an arc's end left out, all at
  // once in vector lanes, as the single test would leave them out
  // (generator/arc_end_pairs.h). Two of one 64-gon prism stacked cap on
  // cap and turned alike meet so in 16,260 pairs a call (each rim edge
  // against the other's at the caps' normal, each side edge against every
  // other, parallel), which no bound tells from the cap contact: tested
  // one at a time, the benchmark's cylinders stacked alike took 8.7M
  // instructions a call, 2.9M since. Keeps the pairs left in ends.left,
  // in the row's order; returns how many.
  ArcEndWork& ends = work.arc_ends;
  const auto leave_out_along_arc_ends = [&](const EdgeArc& x, const Vec3& edge_a, int count) {
    const ArcColumns& columns_b = arcs_b.columns();
    const EdgeVectors& edges_b = arcs_b.edge_vectors();
    for (int k = 0; k < count; ++k) {
      const int j = ends.left[k];
      ends.face_x[k] = columns_b.face_x[j], ends.face_y[k] = columns_b.face_y[j], ends.face_z[k] = columns_b.face_z[j];
      ends.twin_x[k] = columns_b.twin_x[j], ends.twin_y[k] = columns_b.twin_y[j], ends.twin_z[k] = columns_b.twin_z[j];
      ends.across_x[k] = columns_b.across_x[j], ends.across_y[k] = columns_b.across_y[j],
      ends.across_z[k] = columns_b.across_z[j];
      ends.edge_x[k] = edges_b.x[j], ends.edge_y[k] = edges_b.y[j], ends.edge_z[k] = edges_b.z[j];
    }
    for (int k = count; k < lanes_of(count); ++k)
      ends.face_x[k] = ends.face_y[k] = ends.face_z[k] = ends.twin_x[k] = ends.twin_y[k] = ends.twin_z[k] =
          ends.across_x[k] = ends.across_y[k] = ends.across_z[k] = ends.edge_x[k] = ends.edge_y[k] = ends.edge_z[k] =
              0;
    axes_along_arc_ends_in_lanes(x, edge_a,
                                 {ends.face_x, ends.face_y, ends.face_z, ends.twin_x, ends.twin_y, ends.twin_z,
                                  ends.across_x, ends.across_y, ends.across_z, ends.edge_x, ends.edge_y, ends.edge_z},
                                 count, ends.along);
    int left = 0;
    for (int k = 0; k < count; ++k) ends.left[left] = ends.left[k], left += static_cast<int>(ends.along[k] == 0);
    return left;
  };
  // The `count` pairs of B's arcs `js` that the lanes' bounds leave, kept
  // in ends.left in the row's order (js may be ends.left); returns how many.
  const auto leave_out_hopeless = [&](const EdgeArc& x, const Vec3& edge_a, const int* js, int count) {
    const int64_t* hopeless = bound_row_in_lanes(x, edge_a, js, count);
    int left = 0;
    for (int k = 0; k < count; ++k) ends.left[left] = js[k], left += static_cast<int>(hopeless[k] == 0);
    return left;
  };
  bool ends_first = false;  // the arc-end test left out most of the last row's pairs it was given
  // A row: arc i of A against the arcs of B the lanes let through. False
  // when a pair separates the hulls.
  //
  // F4 before any pair is formed: consider_projected_pair passes by every
  // pair with an arc between coplanar faces (is_flat_pair), so such an
  // arc's row is left out here, and B's are kept out of the rows (below),
  // to the same answer. Kept in, every diagonal of one hull's triangulated
  // faces met every diagonal of the other's, an arc of one point crossing
  // another within the Gauss test's slack: 64-gon cylinders with
  // triangulated faces took 35.4M instructions a call, 26 times the 1.35M
  // of their merged faces, and the triangulated-faces relation was a
  // quarter of a strict fuzz execution on a grown corpus.
  const bool flat_a = arcs_a.may_have_flat(), flat_b = arcs_b.may_have_flat();
  //
  // A pair's axis is A's edge, formed once a row, crossed with B's edge,
  // read from B's edge vectors once a row of many pairs has written them
  // (once a call): the same differences of the same turned vertices as
  // world_edge's, so the same axis to the bit. Formed pair by pair, two
  // 257-gon prisms cap to cap turned four vertices for each of the 66,000
  // rim pairs that meet at the caps' normal (hulls of more than
  // kCachedVertices turn a vertex each time it is read): over stacked
  // prisms of 16 to 257 sides, 42% of SAT's instructions went to turning
  // those edges. Written on every call of large hulls, the edge vectors
  // cost 128-point hulls 1.2% more instructions: most of their rows hold
  // one pair.
  const EdgeVectors& edges_b = arcs_b.edge_vectors();  // read once written (edge_vectors_b)
  const auto against = [&](int i, const EdgeArc& x, const int* js, int count) {
    if (count == 0 || (flat_a && is_flat_arc(x))) return true;
    const Vec3 edge_a = world_edge(a, x.v0, x.v1);
    if (scan_pairs) {
      if (!batch.has_room_for(count) && !settle_batch()) return false;
      for (int k = 0; k < count; ++k) {
        const int j = js[k];
        if (!arcs_b.may_cross(x, j)) continue;
        const ArcIndices& y = arcs_b.indices(j);
        const Vec3 axis = edge_a.cross(world_edge(b, y.v0, y.v1));
        if (!axis_along_arc_end(axis, x, arcs_b[j])) batch.add(i, j, axis);
      }
      return true;
    }
    // A row of many pairs: the lanes' bounds and the arc-end test in lanes,
    // each on the pairs the other leaves, whichever left out more of the
    // last row first; the pairs left after both go on one at a time, in the
    // row's order. Either order measures the same pairs: a pair the lanes
    // would bound is bound by pair_is_hopeless too (pair_bounds.h), and
    // the arc-end test in lanes is the single test's.
    bool ends_told = false;
    if (count >= kPairsInLanes) {
      if (!edge_vectors_b) work.arcs_b.write_edge_vectors(b), edge_vectors_b = true;
      const bool ends_before_bounds = ends_first;
      if (ends_before_bounds) {
        std::copy(js, js + count, ends.left);
      } else {
        count = leave_out_hopeless(x, edge_a, js, count);
      }
      if (count >= kPairsInLanes) {
        const int tested = count;
        count = leave_out_along_arc_ends(x, edge_a, count), ends_told = true;
        ends_first = 2 * (tested - count) > tested;
      }
      if (ends_before_bounds && count >= kPairsInLanes) count = leave_out_hopeless(x, edge_a, ends.left, count);
      js = ends.left;
    }
    for (int k = 0; k < count; ++k) {
      const int j = js[k];
      if (!arcs_b.may_cross(x, j)) continue;
      const ArcIndices& y = arcs_b.indices(j);
      ++work.formed_alone;
      const Vec3 axis =
          edge_a.cross(edge_vectors_b ? Vec3(edges_b.x[j], edges_b.y[j], edges_b.z[j]) : world_edge(b, y.v0, y.v1));
      if ((!ends_told && axis_along_arc_end(axis, x, arcs_b[j])) || pair_is_hopeless(x, y, axis)) continue;
      if (!measure_pair(i, x, j)) return false;
    }
    return true;
  };
  int* near = work.near;
  ArcColumns& kept_b = work.kept_b;
  int* kept_index = work.kept_index;
  bool* left_out = work.left_out;
  if (!row_bounds) {
    // Each arc of A against the arcs of B that may cross it, found for the
    // whole row in vector lanes: the pair loop was most of a small hull's
    // SAT, and with only the first of the three tests in lanes, ten pairs
    // in eleven reached the loop to fail the other two (32-point hulls).
    // B's flat arcs, where it has any, are kept out first.
    int kept = 0;
    if (flat_b) {
      for (int j = 0; j < arcs_b.size(); ++j) left_out[j] = arcs_b.is_flat(j);
      kept = keep_arcs(arcs_b.columns(), arcs_b.size(), left_out, kept_b, kept_index);
    }
    for (int i = 0; i < arcs_a.size(); ++i) {
      const EdgeArc x = arcs_a[i];
      const int count = flat_b ? crossing_among(kept_b, kept, kept_index, x, near) : arcs_b.crossing(x, near);
      if (!against(i, x, near, count)) return best;
    }
    settle_batch();
    return named();
  }
  // Whole rows at once, before their candidates are found: every pair in
  // a row has its axis m on A's arc, where A's edge is A's support, so
  // along m its overlap is at least m . (a0 - B's centre) + B's ball, and
  // against m at least the balls' bound, both least somewhere on the arc.
  // On large hulls most rows end here. All rows are bounded at once, in
  // vector lanes, by the best depth when the phase starts: a shallower axis
  // found later does not tighten the rows after it, which costs less than
  // bounding each row in turn did (a fifth of a 128-point call).
  const double past = std::min(best.depth, ceiling) + tie_room;
  double* row_margin = work.row_margin;
  arcs_above(arcs_a, sb.centre, past - sb.inner, centres, past - sa.inner - sb.inner, row_margin);
  // B's arcs bounded the same way, each over its arc negated (where -m
  // meets it, B's edge is B's support along -m): an arc whose every pair
  // is hopeless is left out, and each row is tested against the arcs left
  // in only. Most are out: the test over every arc of B was a fifth of a
  // 32-point pair's call. The arcs left in are few enough that the lanes
  // pass over them costs less than a grid on the Gauss sphere offering
  // each row the arcs in the cells it passes (128-point hulls took 1.24x
  // the time with the grid, 64-gon cylinders 1.08x).
  double* out_margin = work.out_margin;
  arcs_above(arcs_b, sa.centre, past - sa.inner, -centres, past - sa.inner - sb.inner, out_margin);
  for (int j = 0; j < arcs_b.size(); ++j) left_out[j] = out_margin[j] > 0;
  if (flat_b)
    for (int j = 0; j < arcs_b.size(); ++j) left_out[j] = left_out[j] || arcs_b.is_flat(j);
  const int kept = keep_arcs(arcs_b.columns(), arcs_b.size(), left_out, kept_b, kept_index);
  for (int i = 0; i < arcs_a.size(); ++i) {
    if (row_margin[i] > 0) continue;
    const EdgeArc x = arcs_a[i];
    if (!against(i, x, near, crossing_among(kept_b, kept, kept_index, x, near))) return best;
  }
  settle_batch();
  return named();
}

// The hint's axis in this call's poses, and its overlap (the lesser of the
// two directions: no less than the penetration depth either way). Returns
// false, with `separated` the answer, where the axis separates the hulls by
// more than their projections' rounding: SAT would find them apart too (the
// axis of greatest gap is among its candidates), so whether they collide
// never depends on the hint. A hint whose features the hulls lack, or
// edges that have turned parallel, bounds nothing.
bool hint_overlap(const PosedHull& a, const PosedHull& b, const AxisHint& hint, double& overlap,
                  SatResult& separated) {
  Vec3 axis;
  const double reach = std::max(a.reach_from_origin(), b.reach_from_origin());
  // What the projections' rounding may move an overlap by; an edge axis
  // adds its own turn (below).
  double uncertain = 4 * tol::world_rounding(reach);
  if (hint.kind == AxisKind::face_a) {
    if (hint.feature_a < 0 || hint.feature_a >= a.face_count()) return true;
    axis = a.world_face_normal(hint.feature_a);
  } else if (hint.kind == AxisKind::face_b) {
    if (hint.feature_b < 0 || hint.feature_b >= b.face_count()) return true;
    axis = b.world_face_normal(hint.feature_b);
  } else {
    const HullTopology *ta = a.topology(), *tb = b.topology();
    if (!ta || !tb || hint.feature_a < 0 || hint.feature_a >= ta->edge_count() || hint.feature_b < 0 ||
        hint.feature_b >= tb->edge_count())
      return true;
    const TopologyEdge &x = ta->edge(hint.feature_a), &y = tb->edge(hint.feature_b);
    const Vec3 edge_a = world_edge(a, x.v0, x.v1), edge_b = world_edge(b, y.v0, y.v1);
    axis = edge_a.cross(edge_b);
    const double length = axis.norm();
    if (parallel_edges(edge_a, edge_b, length)) return true;
    axis /= length;
    // The hint names the edges that support the axis, and SAT took the axis
    // from another pair along it (a parallelepiped's zones' first edges, a
    // crossing pair renamed by its supporting edges): each end rounded to
    // the world's resolution, the two pairs' axes part by up to this turn,
    // and the overlap by the turn over the reach of both hulls. Within
    // that, the hint proves no separation, and SAT decides as without it.
    // Two needles 1e-3 and 1e-6 wide touching 1e3 out, corner to corner: B's
    // edge 1e-3 long named by the hint turned the axis by 4e-11 from the
    // zone's first edge SAT used, and the overlap by 3.5e-14, past the
    // rounding's 2.8e-14: the second call said apart, the first colliding
    // 5.5e-15 deep (F56, deterministic, manifuzz check --strict --family
    // needle).
    // The rounding over each edge's length, over the sine between them:
    const double turn = tol::world_rounding(reach) * (edge_a.norm() + edge_b.norm()) / length;
    uncertain += 2 * reach * turn;
  }
  bool b_along_axis = true;
  overlap = overlap_along(a, b, axis, b_along_axis);
  if (std::isnan(overlap)) overlap = std::numeric_limits<double>::infinity();  // bounds nothing
  if (!(overlap < -uncertain)) return true;
  separated = {true, b_along_axis ? axis : Vec3(-axis), overlap, hint.kind, hint.feature_a, hint.feature_b};
  return false;
}

// The axis that answered a pair's last call, per thread, in a table indexed
// by a hash of the hulls' vertex addresses. An address is no proof of the
// same hull (a caller's next hull often lands where the last was freed),
// and need not be: any axis's overlap bounds the depth, so a stranger's
// hint costs one projection and changes no answer.
struct RememberedAxis {
  const mfz_vec3* vertices_a = nullptr;
  const mfz_vec3* vertices_b = nullptr;
  int32_t count_a = 0, count_b = 0;
  AxisHint hint;

  bool same_pair(const PosedHull& a, const PosedHull& b) const {
    return vertices_a == a.abi_hull().vertices && vertices_b == b.abi_hull().vertices &&
           count_a == a.vertex_count() && count_b == b.vertex_count();
  }
  void remember(const PosedHull& a, const PosedHull& b, const AxisHint& axis) {
    vertices_a = a.abi_hull().vertices, vertices_b = b.abi_hull().vertices;
    count_a = a.vertex_count(), count_b = b.vertex_count(), hint = axis;
  }
};

// 4,096 pairs: the benchmark's 1,024 per family, and a property case's
// relations, each with its own copies of the hulls; four to a set, the
// least recently used making room. With one pair to a slot, a pair lost
// its axis whenever another pair's hash took its slot, and a quarter of
// the benchmark's 1,024 separated pairs started from nothing on every lap
// (SatHint.AThousandPairsEachKeepTheirLastAxis: 204 to 245 of 1,024);
// four to a set, a pair loses it only where four others share its set (5
// to 57), and separated pairs of that benchmark take 30% fewer instructions.
constexpr int kRememberedPairs = 4096;
constexpr int kRememberedWays = 4;
constexpr int kRememberedSets = kRememberedPairs / kRememberedWays;

struct RememberedSet {
  RememberedAxis way[kRememberedWays];
  uint32_t last_use[kRememberedWays] = {};  // the set's clock at each way's last call
  uint32_t clock = 0;
};

RememberedSet& remembered_set(const PosedHull& a, const PosedHull& b) {
  static thread_local RememberedSet table[kRememberedSets];
  const auto address = [](const mfz_vec3* p) { return static_cast<uint64_t>(reinterpret_cast<uintptr_t>(p)); };
  const uint64_t key = address(a.abi_hull().vertices) * 0x9E3779B97F4A7C15ull ^
                       address(b.abi_hull().vertices) * 0xC2B2AE3D27D4EB4Full;
  return table[(key >> 32) % kRememberedSets];
}

}  // namespace

SatResult run_sat_with_hint(const PosedHull& a, const PosedHull& b, const AxisHint& hint) {
  double overlap = std::numeric_limits<double>::infinity();
  SatResult separated;
  if (!hint_overlap(a, b, hint, overlap, separated)) return separated;
  const SatResult sat = bounded_sat(a, b, overlap);
  // Another axis than the hint's, no shallower than it to the bounds' tie
  // room: the two tie, and which one the bounds met first was the hint's
  // doing, so the call without it decides. Two edge axes 7 degrees apart,
  // both 2.0008883439004421e-11 deep at touching, answered by the hint's
  // ceiling in one order and without it in the other (F54, deterministic,
  // manifuzz fuzz --strict). An axis further below the hint's is the pose's
  // doing, and stands.
  const bool hinted_other = std::isfinite(overlap) && !sat.separated &&
                            (sat.kind != hint.kind || sat.feature_a != hint.feature_a || sat.feature_b != hint.feature_b);
  if (!hinted_other) return sat;
  // The reach from the origin bounds bounded_sat's reach and coordinates.
  const double reach = std::max(a.reach_from_origin(), b.reach_from_origin());
  if (sat.depth < overlap - 2 * axis_tie_room(reach, 3 * reach)) return sat;
  return bounded_sat(a, b, std::numeric_limits<double>::infinity());
}

SatResult run_sat(const PosedHull& a, const PosedHull& b) {
  RememberedSet& set = remembered_set(a, b);
  int way = 0;
  while (way < kRememberedWays && !set.way[way].same_pair(a, b)) ++way;
  const bool same_pair = way < kRememberedWays;
  const SatResult sat = run_sat_with_hint(a, b, same_pair ? set.way[way].hint : AxisHint{});
  // A pair met for the first time takes the least recently used way. (The
  // clock wraps after 4e9 calls to the set; the order is then wrong once.)
  if (!same_pair) way = static_cast<int>(std::min_element(set.last_use, set.last_use + kRememberedWays) - set.last_use);
  set.last_use[way] = ++set.clock;
  set.way[way].remember(a, b, {sat.kind, sat.feature_a, sat.feature_b});
  return sat;
}
int edge_pairs_measured_in_full() { return sat_workspace().measured_in_full; }
int edge_pairs_formed_alone() { return sat_workspace().formed_alone; }
int faces_past_the_balls() { return sat_workspace().faces_past_balls; }

SatResult run_sat_every_pair(const PosedHull& a, const PosedHull& b) { return sat_every_pair(a, b); }

SatResult least_edge_axis(const PosedHull& a, const PosedHull& b) {
  SatResult best;
  best.depth = std::numeric_limits<double>::infinity();
  best.kind = AxisKind::edge_edge;  // edge after edge: no bias
  all_edge_pairs(a, b, best);
  return best;
}

}  // namespace mfz

#include "relations.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <cstring>
#include <limits>

#include "case/case_file.h"
#include "crossing_slide.h"
#include "geometry/closest_point.h"
#include "geometry/posed_hull.h"
#include "geometry/tolerances.h"

namespace mfz::props {
namespace {

/// Contact sets larger than this are not compared point by point (see relations.h).
constexpr int kComparedContacts = 3;

// ---- running the generator on a transformed case ----

struct Posed {
  const Hull* a;
  Pose pose_a;
  const Hull* b;
  Pose pose_b;
};

// A picture of a finding shows the transformed run beside the case: the
// caller may ask for the last one to be kept (RelationInput::keep).
std::optional<Finding> call(GeneratorSession& g, const Posed& p, mfz_manifold& out, const std::string& relation,
                            const RelationInput& in) {
  const mfz_hull a = p.a->view(), b = p.b->view();
  const mfz_pose pa = p.pose_a.to_abi(), pb = p.pose_b.to_abi();
  int32_t status = 0;
  std::string failure;
  const CallOutcome outcome = g.generate(a, pa, b, pb, out, status, failure);
  if (in.keep) {
    in.keep->relation = relation;
    in.keep->scene = posed_scene(*p.a, p.pose_a, *p.b, p.pose_b);
    in.keep->scene.precision_epsilon = in.profile.precision_epsilon;
    in.keep->manifold.reset();
    if (outcome == CallOutcome::done && status == 0) in.keep->manifold = out;
  }
  switch (outcome) {
    case CallOutcome::crashed: return Finding{"crash", failure + " (in the " + relation + " run)"};
    case CallOutcome::hung: return Finding{"hang", failure + " (in the " + relation + " run)"};
    case CallOutcome::interrupted: return Finding{kInterrupted, "(in the " + relation + " run)"};
    case CallOutcome::done: break;
  }
  if (status != 0) return Finding{"refused", "status " + std::to_string(status) + " in the " + relation + " run"};
  return std::nullopt;
}

// Calls the generator on the transformed case, then holds its manifold to the
// invariants too: in a tie the relation compares less, so each run must be
// right on its own (docs/contract.md, "Ties").
std::optional<Finding> run(GeneratorSession& g, const Posed& p, mfz_manifold& out, const RelationInput& in,
                           const std::string& relation, double depth_factor = 1) {
  if (auto f = call(g, p, out, relation, in)) return f;
  Scene scene = posed_scene(*p.a, p.pose_a, *p.b, p.pose_b);
  scene.precision_epsilon = in.profile.precision_epsilon;
  const std::optional<InvariantCheck> bad = check_transformed_manifold(scene, in.oracles, depth_factor, out, in.profile);
  if (bad) {
    char margin[96];
    std::snprintf(margin, sizeof margin, " (error %.3g L, tol %.3g L)", bad->error, bad->tolerance);
    return Finding{relation, "the " + relation + " run fails " + bad->name + ": " + bad->detail + margin, {},
                   bad->error, bad->tolerance};
  }
  return std::nullopt;
}

// ---- comparing two manifolds in the original frame ----

struct Contact {
  Vec3 on_a, on_b;
  double penetration;
};

struct Answer {
  bool colliding;
  Vec3 normal;
  double depth;
  std::vector<Contact> contacts;
};

Answer answer_of(const mfz_manifold& m) {
  Answer a{m.colliding == 1, to_vec(m.normal), -m.penetration, {}};
  a.contacts.reserve(static_cast<size_t>(std::clamp(m.contact_count, 0, MFZ_MAX_CONTACTS)));
  for (int i = 0; i < m.contact_count && i < MFZ_MAX_CONTACTS; ++i)
    a.contacts.push_back({to_vec(m.contacts[i].point_on_a), to_vec(m.contacts[i].point_on_b), m.contacts[i].penetration});
  return a;
}

double distance_to_hull_of(const Vec3& p, const std::vector<Vec3>& points) {
  if (points.size() == 1) return (p - points[0]).norm();
  if (points.size() == 2) return (p - closest_on_segment(p, points[0], points[1])).norm();
  double best = INFINITY;
  for (size_t i = 0; i < points.size(); ++i)
    for (size_t j = i + 1; j < points.size(); ++j)
      for (size_t k = j + 1; k < points.size(); ++k)
        best = std::min(best, (p - closest_on_triangle(p, points[i], points[j], points[k])).norm());
  return best;
}

// Where a contact of one run may slide to meet the other's: along a
// grazing crossing (crossing_slide.h), in the frame of the scene.
struct SlideRoom {
  const Scene* scene = nullptr;
  double on_edge = 0;   ///< a point this near an edge lies on it
  double rounding = 0;  ///< the coarser run's rounding, which moves a crossing
};

// The farthest a contact of `x` lies from the region of `y`'s contacts, on
// either hull, with its two points slid by `t` along `slide`.
double off_region(const Contact& c, const CrossingSlide& slide, double t, const std::vector<Vec3>& ya,
                  const std::vector<Vec3>& yb) {
  const Vec3 on_a = c.on_a + t * (slide.incident_is_a ? slide.along_incident : slide.along_reference);
  const Vec3 on_b = c.on_b + t * (slide.incident_is_a ? slide.along_reference : slide.along_incident);
  return std::max(distance_to_hull_of(on_a, ya), distance_to_hull_of(on_b, yb));
}

// The least of off_region over the slide: a scan, then golden sections
// about the best sample (the distance to a convex region is convex along
// a line, so the scan only guards regions that are not quite convex).
double least_off_along(const Contact& c, const CrossingSlide& slide, const std::vector<Vec3>& ya,
                       const std::vector<Vec3>& yb) {
  constexpr int kSamples = 32;
  const double step = (slide.most - slide.least) / kSamples;
  int best = 0;
  double least = INFINITY;
  for (int k = 0; k <= kSamples; ++k)
    if (const double off = off_region(c, slide, slide.least + k * step, ya, yb); off < least) least = off, best = k;
  double lo = slide.least + std::max(best - 1, 0) * step, hi = slide.least + std::min(best + 1, kSamples) * step;
  const double golden = (std::sqrt(5.0) - 1) / 2;
  for (int k = 0; k < 80 && hi > lo; ++k) {
    const double m1 = hi - golden * (hi - lo), m2 = lo + golden * (hi - lo);
    if (off_region(c, slide, m1, ya, yb) <= off_region(c, slide, m2, ya, yb))
      hi = m2;
    else
      lo = m1;
  }
  return std::min(least, off_region(c, slide, (lo + hi) / 2, ya, yb));
}

// Each contact of `x` deeper than `tol` (see below) lies within `tol` of the region
// (convex hull) of `y`'s contacts, on both hulls. Regions, not points: where an
// incident edge runs along a side plane, rounding moves its crossing point
// along the edge, and both places are right.
//
// How far: by the coarser run's rounding over the sine of the edge's angle
// to the side plane, where that reaches past `tol` (the slides of
// crossing_slide.h). Two tetrahedra 1,000 across shared a corner to 1e-5
// and another to 0.15; B's edge between them ran 6.2e-9 rad off the side
// plane through A's edge, its end 1e-8 inside. At the origin the built-in
// crossed it 1.1 from that end; 1.2e4 L out (the world's rounding 1.7e-7
// there) it took the end itself for the crossing, as its bands do (F52),
// and Bullet's clip in double crossed it 0.21 from where it had at the
// origin: all right, and past the 1e-6 L the points were held to (h29,
// far-from-origin, manifuzz fuzz
// --max-points 5 on the built-in, open as O33).
//
// A contact no deeper than `tol` may be in one run alone: a point that may
// move by `tol` may move across the reference plane, where the tutorial's
// last step removes it. B's edge, 2.7e-4 rad off a side plane and as steep
// as the reference face, crossed both where the side plane meets that face;
// the world's rounding 2.6e5 out moved the crossing 1.1e-7 along it, 7.2e-10
// above the face in one frame and 1.03e-7 below in the moved one, a contact
// 0.29 from the first run's two (h22, rigid-motion, manifuzz fuzz --strict on
// the built-in, open as O24). Held to the depth tolerance (1e-9 L), this
// asked for a canonical side of a plane the point lies on. Only beside
// deeper contacts, which are compared: in a manifold no deeper than `tol`
// (a slab 1e-6 thick resting on a box, F19) every contact deeper than
// `depth_tol` is compared still, or none would be.
//
// A contact may also be in one run alone where it stands in the column of
// the other's region along n, to `tol` (which holds the coarser run's
// rounding), and no deeper than the other's deepest: a clipping generator
// may leave out a point of a face nearly perpendicular to the reference
// face that stands, to its frame's rounding, in the column of a point it
// keeps (F30), for its height there is rounding over the cosine. A face of B 1.4e-5 rad off
// perpendicular, 350 deep along n, had its corner 0.0049 across from the
// incident face's kept corner: at the origin past the built-in's column
// (4.1e-3, F46's share of the reference face's perimeter), 1e4 L out
// within that frame's rounding (7.4e-3), and the corner, 350 from the
// other run's contacts, was in one run alone (h32, far-from-origin,
// manifuzz fuzz --max-points 8 on the built-in).
bool within_region(const std::vector<Contact>& x, const Vec3& x_normal, const std::vector<Contact>& y, double tol,
                   double depth_tol, const SlideRoom& room, std::string& why) {
  std::vector<Vec3> ya, yb, ya_across, yb_across;
  ya.reserve(y.size()), yb.reserve(y.size()), ya_across.reserve(y.size()), yb_across.reserve(y.size());
  const auto across = [&](const Vec3& p) -> Vec3 { return p - p.dot(x_normal) * x_normal; };
  double deepest_y = 0;
  for (const Contact& c : y) {
    ya.push_back(c.on_a), yb.push_back(c.on_b);
    ya_across.push_back(across(c.on_a)), yb_across.push_back(across(c.on_b));
    deepest_y = std::max(deepest_y, std::abs(c.penetration));
  }
  double deepest = 0;
  for (const Contact& c : x) deepest = std::max(deepest, std::abs(c.penetration));
  const double optional_depth = deepest > tol ? tol : depth_tol;
  for (size_t i = 0; i < x.size(); ++i) {
    if (std::abs(x[i].penetration) <= optional_depth) continue;
    if (y.empty()) {
      why = "one run has contacts, the other none";
      return false;
    }
    double off = std::max(distance_to_hull_of(x[i].on_a, ya), distance_to_hull_of(x[i].on_b, yb));
    if (!(off <= tol) && room.scene)
      for (const CrossingSlide& slide :
           crossing_slides(*room.scene, x_normal, x[i].on_a, x[i].on_b, room.on_edge, room.rounding, tol))
        off = std::min(off, least_off_along(x[i], slide, ya, yb));
    if (!(off <= tol) && std::abs(x[i].penetration) <= deepest_y + depth_tol &&
        std::max(distance_to_hull_of(across(x[i].on_a), ya_across), distance_to_hull_of(across(x[i].on_b), yb_across)) <=
            tol)
      continue;  // in the column of the other's region
    if (!(off <= tol)) {
      why = "contact " + std::to_string(i) + " lies " + std::to_string(off) + " from the other run's contacts";
      return false;
    }
  }
  return true;
}

struct Tolerances {
  double depth, point, normal;
  /// How much coarser the transformed run's frame is than the original's:
  /// its extra rounding (a case moved far out, a float profile's rounding).
  double coarser = 0;
  /// The transformed run's frame's rounding, which `point` holds once.
  double rounding = 0;
};

// An edge pair's contact is the two edges' closest points, and where the
// edges are nearly parallel the frame's rounding of their ends moves that
// point along them by the rounding over the sine of their angle, as it
// moves a crossing along an edge grazing a clipping plane; both places are
// right. So it turns their axis, the edges' cross product, by the rounding
// over the shorter edge and that sine. A tetrahedron's edge 3.2e-5 rad off
// B's edge, crossing it at a depth of 3.2e-6, 1.7e7 from the origin (the
// world's rounding there 2.4e-7), had its contact 9e-6 from the moved
// run's, past the 1e-6 L the point tolerance held it to, and the tutorial's
// normal 5.3e-6 from its moved run's, past 1.5e-6 (h23, rigid-motion,
// manifuzz fuzz --strict on the built-in). The room is for the least
// axis's own edges, where it is an edge pair.
// The depth along that axis moves with it, each run's by its own frame's
// rounding (h31, oracle_answers.h).
struct EdgePairRoom {
  double point = 0, normal = 0, depth = 0;
};

EdgePairRoom edge_pair_room(const RelationInput& in, const Tolerances& tol) {
  const LeastEdgePair& pair = in.oracles.least_edge_pair;
  if (!pair.present) return {};
  return {tol.rounding / pair.sine, tol.rounding / (pair.shorter_edge * pair.sine),
          pair.depth_room(in.scene.rounding()) + pair.depth_room(tol.rounding)};
}

// In a frame coarser than the tie tolerance (a float engine's rounding 1e4 L
// out), another axis within that rounding of the least, pointing another
// way, ties there: only depth is determined. So does one within the least
// edge pair's depth room (h31): an axis the rounding leaves that uncertain
// is as deep as another within it. The needles of h31 took that pair in
// one frame and a face 0.11 rad from it, 3.9e-6 deeper, in the other, where
// the pair's overlap was known to 2.5e-3. Every axis is read, since only
// the front of the ranking is in order.
bool direction_tie_in_coarser_frame(const RelationInput& in, const Tolerances& tol, double room) {
  const double tie = in.scene.length_tolerance(tol::kTie), slack = tol.coarser + room;
  if (!(slack > tie) || in.oracles.sat_axes.empty()) return false;
  const RankedAxis& best = in.oracles.sat_axes[0];
  for (const RankedAxis& axis : in.oracles.sat_axes)
    if (axis.reverse_overlap - best.overlap <= tie + slack ||
        (axis.overlap - best.overlap <= tie + slack && !coplanar_normals(axis.normal, best.normal)))
      return true;
  return false;
}

// Contact sets, region against region both ways (see within_region). Under
// the profile's max-contacts k, a run with k contacts may have dropped some:
// its points must lie in the other run's region, not the other way round,
// and two such runs may have kept different points.
std::optional<std::string> compare_contacts(const Answer& original, const Answer& other, const Tolerances& tol,
                                            int max_contacts, const SlideRoom& room) {
  const int n1 = static_cast<int>(original.contacts.size()), n2 = static_cast<int>(other.contacts.size());
  if (n1 > kComparedContacts && n2 > kComparedContacts) return std::nullopt;
  if (n1 > 8 || n2 > 8) return std::nullopt;  // a region of many points is not compared
  const bool reduced1 = max_contacts > 0 && n1 >= max_contacts, reduced2 = max_contacts > 0 && n2 >= max_contacts;
  if (reduced1 && reduced2) return std::nullopt;
  std::string why;
  if ((!reduced2 && !within_region(original.contacts, original.normal, other.contacts, tol.point, tol.depth, room, why)) ||
      (!reduced1 && !within_region(other.contacts, other.normal, original.contacts, tol.point, tol.depth, room, why)))
    return why;
  return std::nullopt;
}

// Two candidates along one direction from different features: a single
// contact must lie in the region of the other answer's contacts. Not of a
// reduced answer's (at the profile's max-contacts): it keeps any k of its
// points, and the region of the four of largest area, the reducer the
// contract passes, need not hold the deepest. A pyramid standing on a face
// of a larger hull, its base in that face: one run answered with the apex
// alone (the base's corners 0 deep), the moved run's corners came out
// 4.6e-10 deep, and the variant kept them and not the apex, 1e4 above them
// (h21, manifuzz fuzz on the reducing variant).
std::optional<std::string> single_contact_in_region(const Answer& x, const Answer& y, const Tolerances& tol,
                                                    int max_contacts, const SlideRoom& room) {
  for (const auto* pair : {&x, &y}) {
    const Answer& one = *pair;
    const Answer& many = pair == &x ? y : x;
    if (one.contacts.size() != 1 || many.contacts.size() < 2) continue;
    if (max_contacts > 0 && static_cast<int>(many.contacts.size()) >= max_contacts) continue;
    std::string why;
    if (!within_region(one.contacts, one.normal, many.contacts, tol.point, tol.depth, room, why))
      return "a single contact: " + why;
  }
  return std::nullopt;
}

// What the geometry determines is compared (docs/contract.md, "Ties"). At the
// contract level: depth always; the normal unless another direction ties;
// the contact set unless a feature, incident-face or supporting-edge tie
// leaves it open. At the strict level the answer must be canonical: the
// normal and contacts are compared unless another minimal axis exists.
std::optional<std::string> compare(const Answer& original, const Answer& other, const RelationInput& in,
                                   const Tolerances& tol) {
  if (in.oracles.touching || separated_within_margin(in.scene, in.oracles, in.profile)) return std::nullopt;  // either answer passes; nothing to compare
  // Touching in the transformed frame too: a case moved 1e4 L out is
  // resolved only to that frame's rounding (a float engine's, with its profile).
  if (original.colliding != other.colliding) {
    if (std::abs(in.oracles.exact.signed_depth) <= tol.depth) return std::nullopt;
    return std::string("colliding ") + (original.colliding ? "1" : "0") + " vs " + (other.colliding ? "1" : "0");
  }
  if (!original.colliding) return std::nullopt;
  // face-bias: each run may take a face axis up to its fraction deeper than
  // the exact depth, and two runs may take different ones: only the depth,
  // within that fraction, is compared then.
  const double bias = in.profile.face_bias * std::max(0.0, in.oracles.exact.signed_depth);
  const EdgePairRoom room = edge_pair_room(in, tol);
  if (!(std::abs(original.depth - other.depth) <= tol.depth + bias + room.depth))
    return "depth " + std::to_string(original.depth) + " vs " + std::to_string(other.depth);
  if (bias > 0 && !((original.normal - other.normal).norm() <= tol.normal)) return std::nullopt;
  if (direction_tie_in_coarser_frame(in, tol, room.depth)) return std::nullopt;
  // face-bias: both runs took the same face axis, but not the least; which
  // features tie is read along that axis. A face of each hull parallel to
  // it is a tie the least axis does not show (the face-bias variant took
  // A's face in each order, and the other hull's faces reached below it:
  // swap-symmetry, --seed 2026112601, contacts 0.12 apart).
  const bool biased = bias > 0 && !in.oracles.sat_axes.empty() &&
                      !coplanar_normals(original.normal, in.oracles.sat_axes[0].normal);
  const Ties ties = biased ? classify_ties_along(in.scene, in.oracles.sat_axes, original.normal,
                                                 in.scene.length_tolerance(tol::kTie))
                           : in.oracles.ties;
  // Along such an axis the hulls may part before its own depth, as
  // `separates` allows: then no point of either reaches it, and where the
  // clip finds nothing a clipping generator answers with one point of its
  // fallbacks. Rays along n of one length fill a segment there (an edge of
  // one hull across a slab of the other), and which point is its choice:
  // a single contact is not compared (the face-bias variant's last resort,
  // 2,050 deep under a face axis 7,932 deep, took a point 3,010 from the
  // renumbered run's, of the same ray's length: vertex-order, --seed
  // 2026112602; one 0.001 outside the swapped run's six, swap-symmetry,
  // --seed 2026112601).
  const bool single = original.contacts.size() == 1 || other.contacts.size() == 1;
  if (biased && single &&
      !(depth_after_moving_b(in.oracles.sat_axes, (original.depth - tol.depth) * original.normal, 0.0) > 0))
    return std::nullopt;
  const bool strict = in.level == Level::strict;
  if (strict ? in.oracles.axis_tie : ties.direction) return std::nullopt;
  if (const double apart = (original.normal - other.normal).norm(); !(apart <= tol.normal + room.normal)) {
    char why[96];
    std::snprintf(why, sizeof why, "the normals differ by %.3g (tol %.3g)", apart, tol.normal + room.normal);
    return std::string(why);
  }
  // The finer ties (features, incident faces, supporting edges) are not
  // classified at a coarser frame's rounding: contacts are not compared there.
  if (tol.coarser > in.scene.length_tolerance(tol::kTie)) return std::nullopt;
  // Under a profile's precision the single contact of an edge pair within
  // its rounding of a face axis lies anywhere along nearly parallel edges
  // (a float variant answered a face contact with one vertex in one frame
  // and two points of an edge in another): not compared.
  // At the strict level too: a canonical choice made on inputs rounded to
  // the profile's precision is rounding's where the candidates lie along one
  // direction in double, as they lie along directions that rounding apart
  // for the generator (the float variant, --strict --seed 62: one edge
  // pair's point in one frame, a parallel pair's 0.22 L away in the moved).
  const bool precise = in.profile.precision_epsilon == 0;
  Tolerances contacts = tol;
  contacts.point += room.point;
  const SlideRoom slides{&in.scene, in.scene.point_tolerance() + tol.rounding, tol.rounding};
  if ((!strict || !precise) && ties.contacts_open())
    return ties.feature && precise ? single_contact_in_region(original, other, contacts, in.profile.max_contacts, slides)
                                    : std::nullopt;
  return compare_contacts(original, other, contacts, in.profile.max_contacts, slides);
}

// ---- the transformed cases ----

// An edge-edge normal is the cross product of two edges taken from world
// coordinates, so it turns by the world frame's resolution over the shorter
// edge: a 1e-4 edge 1e6 from the origin points only to within 1e-4 rad.
Tolerances tolerances_for(const Scene& s, double extra_extent = 0) {
  const double ulps = s.rounding(extra_extent);
  return {tol::kDepth * s.scale + ulps, tol::kRelationPoint * s.scale + ulps, tol::kRelationNormal + ulps / s.shortest_edge,
          ulps - s.rounding(), ulps};
}

std::optional<Finding> finding_if(const std::string& relation, const std::optional<std::string>& difference) {
  if (!difference) return std::nullopt;
  return Finding{relation, *difference};
}

// A motion the generator cannot special-case: a turn about a skew axis and a
// shift of about one L.
struct Motion {
  Quat rotation;
  Vec3 shift;
  Pose apply(const Pose& p) const { return {rotation * p.position + shift, (rotation * p.orientation).normalized()}; }
};

Answer moved_back(Answer a, const Motion& m) {
  const Quat inverse = m.rotation.conjugate();
  a.normal = inverse * a.normal;
  for (Contact& c : a.contacts) c.on_a = inverse * (c.on_a - m.shift), c.on_b = inverse * (c.on_b - m.shift);
  return a;
}

bool same_bits(const void* x, const void* y, size_t size) { return std::memcmp(x, y, size) == 0; }

// Field by field: the struct's padding holds whatever was there before.
// A manifold that does not collide says only that: the contract checks no
// normal or penetration there, and a generator that reports the separating
// axis it remembered from the pair's last call (as engines cache it, and as
// the built-in's SAT tries it first) gives another on a second call. It
// was compared, and the built-in's hint turned it into a finding on two
// cubes apart (the cold call's axis, then the remembered one by a product
// of its supporting edges: Relation.theSameInputGivesBitIdenticalOutput).
bool identical(const mfz_manifold& x, const mfz_manifold& y) {
  if (x.colliding != y.colliding || x.contact_count != y.contact_count) return false;
  if (x.colliding == 0 && x.contact_count == 0) return true;
  if (!same_bits(&x.normal, &y.normal, sizeof x.normal) || !same_bits(&x.penetration, &y.penetration, sizeof(double)))
    return false;
  for (int i = 0; i < std::clamp(x.contact_count, 0, MFZ_MAX_CONTACTS); ++i)
    if (!same_bits(&x.contacts[i], &y.contacts[i], sizeof(mfz_contact))) return false;
  return true;
}

// Each relation takes its parameters from the case file when it names them
// (a relation finding replays exactly), else derives them from the case, and
// writes the ones it used into its finding (`relation NAME numbers...`).
using Numbers = std::vector<double>;

Numbers given_or(const Numbers* given, Numbers defaults) {
  return given && given->size() == defaults.size() ? *given : defaults;
}

std::optional<Finding> recorded(std::optional<Finding> f, const std::string& relation, const Numbers& used) {
  if (f) {
    f->relation_line = "relation " + relation;
    for (const double x : used) f->relation_line += " " + format_double(x);
  }
  return f;
}

std::optional<Finding> deterministic(const RelationInput& in, GeneratorSession& g, const Numbers*) {
  mfz_manifold again;
  if (auto f = call(g, {&in.scene.hull_a, in.scene.pose_a, &in.scene.hull_b, in.scene.pose_b}, again, "deterministic", in))
    return recorded(f, "deterministic", {});
  if (!identical(in.manifold, again)) return recorded(Finding{"deterministic", "a second call gave different bits"}, "deterministic", {});
  return std::nullopt;
}

std::optional<Finding> swap_symmetry(const RelationInput& in, GeneratorSession& g, const Numbers*) {
  mfz_manifold swapped;
  if (auto f = run(g, {&in.scene.hull_b, in.scene.pose_b, &in.scene.hull_a, in.scene.pose_a}, swapped, in, "swap-symmetry"))
    return recorded(f, "swap-symmetry", {});
  Answer back = answer_of(swapped);
  back.normal = -back.normal;
  for (Contact& c : back.contacts) std::swap(c.on_a, c.on_b);
  return recorded(finding_if("swap-symmetry", compare(answer_of(in.manifold), back, in, tolerances_for(in.scene))),
                  "swap-symmetry", {});
}

Motion motion_of(const Numbers& x) { return {Quat(x[0], x[1], x[2], x[3]), Vec3(x[4], x[5], x[6])}; }

// One rigid motion of both poses: a turn about a skew axis and a shift of about one L.
std::optional<Finding> rigid_motion(const RelationInput& in, GeneratorSession& g, const Numbers* given) {
  const Quat turn(Eigen::AngleAxisd(0.9, Vec3(1, 2, 3).normalized()));
  const Vec3 shift = in.scene.scale * Vec3(0.7, -0.3, 0.2);
  const Numbers used = given_or(given, {turn.w(), turn.x(), turn.y(), turn.z(), shift.x(), shift.y(), shift.z()});
  const Motion m = motion_of(used);
  mfz_manifold out;
  if (auto f = run(g, {&in.scene.hull_a, m.apply(in.scene.pose_a), &in.scene.hull_b, m.apply(in.scene.pose_b)}, out,
                   in, "rigid-motion"))
    return recorded(f, "rigid-motion", used);
  return recorded(finding_if("rigid-motion", compare(answer_of(in.manifold), moved_back(answer_of(out), m), in,
                                                     tolerances_for(in.scene, m.shift.cwiseAbs().maxCoeff()))),
                  "rigid-motion", used);
}

std::optional<Finding> far_from_origin(const RelationInput& in, GeneratorSession& g, const Numbers* given) {
  const Vec3 shift = 1e4 * in.scene.scale * Vec3(0.6, -0.8, 0.3);
  const Numbers used = given_or(given, {shift.x(), shift.y(), shift.z()});
  const Motion m{Quat::Identity(), Vec3(used[0], used[1], used[2])};
  // Past what a profile's precision resolves, the generator promises nothing.
  if (in.scene.precision_rounding(m.shift.cwiseAbs().maxCoeff()) > tol::kProfileFarthestFrame * in.scene.scale)
    return std::nullopt;
  mfz_manifold out;
  if (auto f = run(g, {&in.scene.hull_a, m.apply(in.scene.pose_a), &in.scene.hull_b, m.apply(in.scene.pose_b)}, out,
                   in, "far-from-origin"))
    return recorded(f, "far-from-origin", used);
  return recorded(finding_if("far-from-origin", compare(answer_of(in.manifold), moved_back(answer_of(out), m), in,
                                                        tolerances_for(in.scene, m.shift.cwiseAbs().maxCoeff()))),
                  "far-from-origin", used);
}

std::optional<Finding> scale(const RelationInput& in, GeneratorSession& g, const Numbers* given) {
  const Numbers used = given_or(given, {2});  // a power of two: the scaled input is exact
  const double s = used[0];
  if (!(s > 0) || !std::isfinite(s)) return Finding{"scale", "the recorded factor is not a positive number"};
  const Hull a = in.scene.hull_a.scaled(s), b = in.scene.hull_b.scaled(s);
  Pose pa = in.scene.pose_a, pb = in.scene.pose_b;
  pa.position *= s;
  pb.position *= s;
  mfz_manifold out;
  if (auto f = run(g, {&a, pa, &b, pb}, out, in, "scale", s)) return recorded(f, "scale", used);
  Answer back = answer_of(out);
  back.depth /= s;
  for (Contact& c : back.contacts) c.on_a /= s, c.on_b /= s, c.penetration /= s;
  return recorded(finding_if("scale", compare(answer_of(in.manifold), back, in, tolerances_for(in.scene))), "scale",
                  used);
}

// The permutation is fixed: every vertex numbered backwards, the faces in
// reverse order, each loop starting one vertex later (Hull::renumbered).
std::optional<Finding> vertex_order(const RelationInput& in, GeneratorSession& g, const Numbers*) {
  const Hull a = in.scene.hull_a.renumbered(), b = in.scene.hull_b.renumbered();
  mfz_manifold out;
  if (auto f = run(g, {&a, in.scene.pose_a, &b, in.scene.pose_b}, out, in, "vertex-order"))
    return recorded(f, "vertex-order", {});
  return recorded(finding_if("vertex-order", compare(answer_of(in.manifold), answer_of(out), in, tolerances_for(in.scene))),
                  "vertex-order", {});
}

// Strict level only: the triangulated hull is outside the contract's hull
// definition (its faces are not maximal).
std::optional<Finding> triangulated_faces(const RelationInput& in, GeneratorSession& g, const Numbers*) {
  if (in.level != Level::strict) return std::nullopt;
  const Hull a = fan_triangulated(in.scene.hull_a), b = fan_triangulated(in.scene.hull_b);
  mfz_manifold out;
  if (auto f = run(g, {&a, in.scene.pose_a, &b, in.scene.pose_b}, out, in, "triangulated-faces"))
    return recorded(f, "triangulated-faces", {});
  return recorded(
      finding_if("triangulated-faces", compare(answer_of(in.manifold), answer_of(out), in, tolerances_for(in.scene))),
      "triangulated-faces", {});
}

// Moving B by 0.99 of the depth along n keeps contact; by 1.01 separates.
std::optional<Finding> move_along_normal(const RelationInput& in, GeneratorSession& g, const Numbers* given) {
  const mfz_manifold& m = in.manifold;
  const double depth = -m.penetration;
  if (m.colliding != 1 || !(depth > 1e3 * tolerances_for(in.scene).depth)) return std::nullopt;
  const Numbers used = given_or(given, {0.99, 1.01});
  const Vec3 n = to_vec(m.normal).normalized();
  for (const double fraction : used) {
    Pose pb = in.scene.pose_b;
    pb.position += fraction * depth * n;
    mfz_manifold out;
    if (auto f = call(g, {&in.scene.hull_a, in.scene.pose_a, &in.scene.hull_b, pb}, out, "move-along-normal", in))
      return recorded(f, "move-along-normal", used);
    const bool should_collide = fraction < 1;
    // margin: a gap within the margin may still be reported as colliding.
    // face-bias: a face axis deeper than the exact depth leaves the hulls
    // apart before its own depth.
    const double moved = fraction * depth, exact = in.oracles.exact.signed_depth;
    const bool either = should_collide ? in.profile.face_bias > 0 && moved >= exact - tolerances_for(in.scene).depth
                                       : (moved - depth) <= in.profile.margin * in.scene.scale;
    if (!either && (out.colliding == 1) != should_collide)
      return recorded(Finding{"move-along-normal", "moving B by " + format_double(fraction) +
                                                       " of the depth along n gives colliding " +
                                                       std::to_string(out.colliding)},
                      "move-along-normal", used);
  }
  return std::nullopt;
}

struct RelationRow {
  const char* name;
  std::optional<Finding> (*check)(const RelationInput&, GeneratorSession&, const Numbers*);
};

// The relations, in the order they run: one table gives the names and the dispatch.
constexpr RelationRow kRelations[] = {
    {"deterministic", deterministic},   {"swap-symmetry", swap_symmetry},     {"rigid-motion", rigid_motion},
    {"vertex-order", vertex_order},     {"scale", scale},                     {"far-from-origin", far_from_origin},
    {"move-along-normal", move_along_normal}, {"triangulated-faces", triangulated_faces},
};

}  // namespace

const std::vector<std::string>& relation_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> v;
    for (const RelationRow& row : kRelations) v.push_back(row.name);
    return v;
  }();
  return names;
}

std::optional<RelationCall> relation_in(const CaseFile& c, std::string& error) {
  for (const std::string& line : c.extensions) {
    if (line.rfind("relation ", 0) != 0) continue;
    std::istringstream words(line.substr(9));
    RelationCall call;
    words >> call.name;
    std::string word;
    while (words >> word) {
      char* end = nullptr;
      const double x = std::strtod(word.c_str(), &end);
      if (*end != '\0' || !std::isfinite(x)) {
        error = "relation line: '" + word + "' is not a finite number";
        return std::nullopt;
      }
      call.numbers.push_back(x);
    }
    const auto& names = relation_names();
    if (std::find(names.begin(), names.end(), call.name) == names.end()) {
      error = "relation line: no relation named '" + call.name + "'";
      return std::nullopt;
    }
    return call;
  }
  return std::nullopt;
}

std::optional<Finding> check_relation(const std::string& name, const RelationInput& in, GeneratorSession& g,
                                      const std::vector<double>* numbers) {
  for (const RelationRow& row : kRelations)
    if (name == row.name) return row.check(in, g, numbers);
  return Finding{name, "no such relation"};
}

}  // namespace mfz::props

#include "relations.h"

#include <cmath>
#include <cstring>
#include <limits>

#include "geometry/closest_point.h"
#include "geometry/tolerances.h"

namespace mfz::props {
namespace {

/// Normals of two runs of a relation agree within this (dimensionless), plus
/// the world frame's resolution over the shortest edge (tolerances_for).
constexpr double kRelationNormal = 1e-6;
/// Contact points of two runs agree within this (x L). Looser than the
/// invariants' 1e-9: where an incident edge grazes a clipping plane at an
/// angle t, rounding moves the crossing point along the edge by about eps M /
/// sin t, and both places are right. Depths stay at tol::kDepth.
constexpr double kRelationPoint = 1e-6;
/// Contact sets larger than this are not compared point by point (see relations.h).
constexpr int kComparedContacts = 3;

// ---- running the generator on a transformed case ----

struct Posed {
  const Hull* a;
  Pose pose_a;
  const Hull* b;
  Pose pose_b;
};

std::optional<Finding> run(GeneratorSession& g, const Posed& p, mfz_manifold& out, const std::string& relation) {
  const mfz_hull a = p.a->view(), b = p.b->view();
  const mfz_pose pa = p.pose_a.to_abi(), pb = p.pose_b.to_abi();
  int32_t status = 0;
  std::string failure;
  switch (g.generate(a, pa, b, pb, out, status, failure)) {
    case CallOutcome::crashed: return Finding{"crash", failure + " (in the " + relation + " run)"};
    case CallOutcome::hung: return Finding{"hang", failure + " (in the " + relation + " run)"};
    case CallOutcome::done: break;
  }
  if (status != 0) return Finding{"refused", "status " + std::to_string(status) + " in the " + relation + " run"};
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

// Each contact of `x` deeper than `depth_tol` lies within `tol` of the region
// (convex hull) of `y`'s contacts, on both hulls. Regions, not points: where an
// incident edge runs along a side plane, rounding moves its crossing point
// along the edge, and both places are right.
bool within_region(const std::vector<Contact>& x, const std::vector<Contact>& y, double tol, double depth_tol,
                   std::string& why) {
  std::vector<Vec3> ya, yb;
  for (const Contact& c : y) ya.push_back(c.on_a), yb.push_back(c.on_b);
  for (size_t i = 0; i < x.size(); ++i) {
    if (std::abs(x[i].penetration) <= depth_tol) continue;
    if (y.empty()) {
      why = "one run has contacts, the other none";
      return false;
    }
    const double off = std::max(distance_to_hull_of(x[i].on_a, ya), distance_to_hull_of(x[i].on_b, yb));
    if (!(off <= tol)) {
      why = "contact " + std::to_string(i) + " lies " + std::to_string(off) + " from the other run's contacts";
      return false;
    }
  }
  return true;
}

struct Tolerances {
  double depth, point, normal;
};

std::optional<std::string> compare(const Answer& original, const Answer& other, const RelationInput& in,
                                   const Tolerances& tol) {
  if (in.touching) return std::nullopt;  // either answer passes; nothing to compare
  if (original.colliding != other.colliding)
    return std::string("colliding ") + (original.colliding ? "1" : "0") + " vs " + (other.colliding ? "1" : "0");
  if (!original.colliding) return std::nullopt;
  if (!(std::abs(original.depth - other.depth) <= tol.depth))
    return "depth " + std::to_string(original.depth) + " vs " + std::to_string(other.depth);
  if (in.tie) return std::nullopt;
  if (!((original.normal - other.normal).norm() <= tol.normal)) return std::string("the normals differ");
  const int n1 = static_cast<int>(original.contacts.size()), n2 = static_cast<int>(other.contacts.size());
  if (n1 > kComparedContacts && n2 > kComparedContacts) return std::nullopt;
  if (n1 > 8 || n2 > 8) return std::nullopt;  // a region of many points is not compared
  std::string why;
  if (!within_region(original.contacts, other.contacts, tol.point, tol.depth, why) ||
      !within_region(other.contacts, original.contacts, tol.point, tol.depth, why))
    return why;
  return std::nullopt;
}

// ---- the transformed cases ----

// Every face split into a fan of triangles with the face's normal, as a mesh
// exported from a modelling tool arrives.
Hull triangulated(const Hull& h) {
  std::vector<Vec3> vertices;
  std::vector<std::vector<int>> loops;
  std::vector<Vec3> normals;
  for (int i = 0; i < h.vertex_count(); ++i) vertices.push_back(h.vertex(i));
  for (int f = 0; f < h.face_count(); ++f)
    for (int k = 1; k + 1 < h.face_size(f); ++k) {
      loops.push_back({h.face_vertex(f, 0), h.face_vertex(f, k), h.face_vertex(f, k + 1)});
      normals.push_back(h.face_normal(f));
    }
  return Hull::from_faces(vertices, loops, normals);
}

// An edge-edge normal is the cross product of two edges taken from world
// coordinates, so it turns by the world frame's resolution over the shorter
// edge: a 1e-4 edge 1e6 from the origin points only to within 1e-4 rad.
Tolerances tolerances_for(const Scene& s, double extra_extent = 0) {
  const double ulps = tol::world_rounding(s.world_extent + extra_extent);
  return {tol::kDepth * s.scale + ulps, kRelationPoint * s.scale + ulps, kRelationNormal + ulps / s.shortest_edge};
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
bool identical(const mfz_manifold& x, const mfz_manifold& y) {
  if (x.colliding != y.colliding || x.contact_count != y.contact_count) return false;
  if (!same_bits(&x.normal, &y.normal, sizeof x.normal) || !same_bits(&x.penetration, &y.penetration, sizeof(double)))
    return false;
  for (int i = 0; i < std::clamp(x.contact_count, 0, MFZ_MAX_CONTACTS); ++i)
    if (!same_bits(&x.contacts[i], &y.contacts[i], sizeof(mfz_contact))) return false;
  return true;
}

std::optional<Finding> deterministic(const RelationInput& in, GeneratorSession& g) {
  mfz_manifold again;
  if (auto f = run(g, {&in.scene.hull_a, in.scene.pose_a, &in.scene.hull_b, in.scene.pose_b}, again, "deterministic"))
    return f;
  if (!identical(in.manifold, again)) return Finding{"deterministic", "a second call gave different bits"};
  return std::nullopt;
}

std::optional<Finding> swap_symmetry(const RelationInput& in, GeneratorSession& g) {
  mfz_manifold swapped;
  if (auto f = run(g, {&in.scene.hull_b, in.scene.pose_b, &in.scene.hull_a, in.scene.pose_a}, swapped, "swap-symmetry"))
    return f;
  Answer back = answer_of(swapped);
  back.normal = -back.normal;
  for (Contact& c : back.contacts) std::swap(c.on_a, c.on_b);
  return finding_if("swap-symmetry", compare(answer_of(in.manifold), back, in, tolerances_for(in.scene)));
}

std::optional<Finding> rigid_motion(const RelationInput& in, GeneratorSession& g) {
  const Motion m{Quat(Eigen::AngleAxisd(0.9, Vec3(1, 2, 3).normalized())), in.scene.scale * Vec3(0.7, -0.3, 0.2)};
  mfz_manifold out;
  if (auto f = run(g, {&in.scene.hull_a, m.apply(in.scene.pose_a), &in.scene.hull_b, m.apply(in.scene.pose_b)}, out,
                   "rigid-motion"))
    return f;
  return finding_if("rigid-motion",
                    compare(answer_of(in.manifold), moved_back(answer_of(out), m), in, tolerances_for(in.scene, in.scene.scale)));
}

std::optional<Finding> far_from_origin(const RelationInput& in, GeneratorSession& g) {
  const Motion m{Quat::Identity(), 1e4 * in.scene.scale * Vec3(0.6, -0.8, 0.3)};
  mfz_manifold out;
  if (auto f = run(g, {&in.scene.hull_a, m.apply(in.scene.pose_a), &in.scene.hull_b, m.apply(in.scene.pose_b)}, out,
                   "far-from-origin"))
    return f;
  return finding_if("far-from-origin", compare(answer_of(in.manifold), moved_back(answer_of(out), m), in,
                                               tolerances_for(in.scene, m.shift.cwiseAbs().maxCoeff())));
}

std::optional<Finding> scale(const RelationInput& in, GeneratorSession& g) {
  const double s = 2;  // a power of two: the scaled input is exact
  const Hull a = in.scene.hull_a.scaled(s), b = in.scene.hull_b.scaled(s);
  Pose pa = in.scene.pose_a, pb = in.scene.pose_b;
  pa.position *= s;
  pb.position *= s;
  mfz_manifold out;
  if (auto f = run(g, {&a, pa, &b, pb}, out, "scale")) return f;
  Answer back = answer_of(out);
  back.depth /= s;
  for (Contact& c : back.contacts) c.on_a /= s, c.on_b /= s, c.penetration /= s;
  return finding_if("scale", compare(answer_of(in.manifold), back, in, tolerances_for(in.scene)));
}

std::optional<Finding> vertex_order(const RelationInput& in, GeneratorSession& g) {
  const Hull a = in.scene.hull_a.renumbered(), b = in.scene.hull_b.renumbered();
  mfz_manifold out;
  if (auto f = run(g, {&a, in.scene.pose_a, &b, in.scene.pose_b}, out, "vertex-order")) return f;
  return finding_if("vertex-order", compare(answer_of(in.manifold), answer_of(out), in, tolerances_for(in.scene)));
}

std::optional<Finding> triangulated_faces(const RelationInput& in, GeneratorSession& g) {
  const Hull a = triangulated(in.scene.hull_a), b = triangulated(in.scene.hull_b);
  mfz_manifold out;
  if (auto f = run(g, {&a, in.scene.pose_a, &b, in.scene.pose_b}, out, "triangulated-faces")) return f;
  return finding_if("triangulated-faces", compare(answer_of(in.manifold), answer_of(out), in, tolerances_for(in.scene)));
}

// Moving B by 0.99 of the depth along n keeps contact; by 1.01 separates.
std::optional<Finding> move_along_normal(const RelationInput& in, GeneratorSession& g) {
  const mfz_manifold& m = in.manifold;
  const double depth = -m.penetration;
  if (m.colliding != 1 || !(depth > 1e3 * tolerances_for(in.scene).depth)) return std::nullopt;
  const Vec3 n = to_vec(m.normal).normalized();
  for (const double fraction : {0.99, 1.01}) {
    Pose pb = in.scene.pose_b;
    pb.position += fraction * depth * n;
    mfz_manifold out;
    if (auto f = run(g, {&in.scene.hull_a, in.scene.pose_a, &in.scene.hull_b, pb}, out, "move-along-normal")) return f;
    const bool should_collide = fraction < 1;
    if ((out.colliding == 1) != should_collide)
      return Finding{"move-along-normal", std::string("moving B by ") + (should_collide ? "0.99" : "1.01") +
                                              " of the depth along n gives colliding " + std::to_string(out.colliding)};
  }
  return std::nullopt;
}

}  // namespace

const std::vector<std::string>& relation_names() {
  static const std::vector<std::string> names = {"deterministic", "swap-symmetry",   "rigid-motion",      "vertex-order",
                                                 "scale",         "far-from-origin", "move-along-normal", "triangulated-faces"};
  return names;
}

std::optional<Finding> check_relation(const std::string& name, const RelationInput& in, GeneratorSession& g) {
  if (name == "deterministic") return deterministic(in, g);
  if (name == "swap-symmetry") return swap_symmetry(in, g);
  if (name == "rigid-motion") return rigid_motion(in, g);
  if (name == "vertex-order") return vertex_order(in, g);
  if (name == "scale") return scale(in, g);
  if (name == "far-from-origin") return far_from_origin(in, g);
  if (name == "move-along-normal") return move_along_normal(in, g);
  if (name == "triangulated-faces") return triangulated_faces(in, g);
  return Finding{name, "no such relation"};
}

}  // namespace mfz::props

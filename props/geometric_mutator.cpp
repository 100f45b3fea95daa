#include "geometric_mutator.h"

#include <algorithm>
#include <cmath>

#include "case/scene.h"
#include "families.h"
#include "geometry/hull_cache.h"
#include "oracles/exact_depth.h"

namespace mfz::props {
namespace {

// ---- drawing numbers ----

int uniform_int(MutationRandom& r, int low, int high) { return std::uniform_int_distribution<int>(low, high)(r); }
double uniform(MutationRandom& r, double low, double high) { return std::uniform_real_distribution<double>(low, high)(r); }
bool coin(MutationRandom& r) { return uniform_int(r, 0, 1) == 1; }

Vec3 random_direction(MutationRandom& r) {
  std::normal_distribution<double> g;
  Vec3 d(g(r), g(r), g(r));
  return d.norm() > 1e-9 ? Vec3(d.normalized()) : Vec3(Vec3::UnitX());
}

// A size of change from one ulp's worth to a tenth, decade by decade: the
// interesting amounts for a contact generator are the tolerance-sized ones.
double small_amount(MutationRandom& r) { return std::pow(10.0, -uniform_int(r, 1, 15)); }

double hull_size(const std::vector<Vec3>& points) {
  Vec3 low = points[0], high = points[0];
  for (const Vec3& p : points) {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  return std::max((high - low).norm(), 1e-300);
}

std::vector<Vec3>& some_hull(FuzzCase& c, MutationRandom& r, Pose*& pose) {
  if (coin(r)) {
    pose = &c.file.pose_a;
    return c.file.points_a;
  }
  pose = &c.file.pose_b;
  return c.file.points_b;
}

// ---- the mutations ----

bool nudge_point(FuzzCase& c, MutationRandom& r) {
  Pose* pose;
  std::vector<Vec3>& points = some_hull(c, r, pose);
  Vec3& p = points[uniform_int(r, 0, static_cast<int>(points.size()) - 1)];
  if (coin(r)) {
    p += small_amount(r) * hull_size(points) * random_direction(r);
  } else {  // a few ulps on one coordinate
    double& x = p[uniform_int(r, 0, 2)];
    for (int k = uniform_int(r, 1, 4); k > 0; --k) x = std::nextafter(x, coin(r) ? INFINITY : -INFINITY);
  }
  return true;
}

bool add_point(FuzzCase& c, MutationRandom& r) {
  Pose* pose;
  std::vector<Vec3>& points = some_hull(c, r, pose);
  if (static_cast<int>(points.size()) >= kFuzzMaxPoints) return false;
  const int n = static_cast<int>(points.size());
  const Vec3 p = points[uniform_int(r, 0, n - 1)], q = points[uniform_int(r, 0, n - 1)],
             s = points[uniform_int(r, 0, n - 1)];
  switch (uniform_int(r, 0, 3)) {
    case 0: points.push_back(p); break;                    // a duplicate
    case 1: points.push_back(0.5 * (p + q)); break;        // on a segment: an edge, or inside
    case 2: points.push_back((p + q + s) / 3.0); break;    // on a triangle: a face, or inside
    default: {                                             // just off a point
      points.push_back(p + small_amount(r) * hull_size(points) * random_direction(r));
    }
  }
  return true;
}

bool remove_point(FuzzCase& c, MutationRandom& r) {
  Pose* pose;
  std::vector<Vec3>& points = some_hull(c, r, pose);
  if (points.size() <= 4) return false;
  points.erase(points.begin() + uniform_int(r, 0, static_cast<int>(points.size()) - 1));
  return true;
}

bool rotate_by_small_angle(FuzzCase& c, MutationRandom& r) {
  Pose* pose;
  some_hull(c, r, pose);
  const double angle = (coin(r) ? 1 : -1) * small_amount(r) * 3;
  pose->orientation = Quat(Eigen::AngleAxisd(angle, random_direction(r))) * pose->orientation.normalized();
  return true;
}

// Touching is where the exact depth is zero: B moved along the exact normal
// by the signed depth. Then exactly there, one ulp of the frame past it
// either way, or a decade of L in.
bool slide_to_touching(FuzzCase& c, MutationRandom& r) {
  const SceneBuild built = make_scene(c.file);
  if (!built.scene) return false;
  const Scene& scene = *built.scene;
  const ExactDepth exact = exact_depth(scene, rank_sat_axes(scene));
  Vec3& position = c.file.pose_b.position;
  position += exact.signed_depth * exact.normal;
  const double ulp = std::nextafter(std::max(scene.world_extent, 1e-300), INFINITY) - scene.world_extent;
  switch (uniform_int(r, 0, 3)) {
    case 0: break;
    case 1: position -= ulp * exact.normal; break;
    case 2: position += ulp * exact.normal; break;
    default: position -= small_amount(r) * scene.scale * exact.normal;
  }
  return true;
}

// A face folded: one of its vertices moved off its plane by a tiny fraction
// of L, in or out. The hull's vertex is found among the input points by value.
bool fold_face(FuzzCase& c, MutationRandom& r) {
  Pose* pose;
  std::vector<Vec3>& points = some_hull(c, r, pose);
  const HullBuild& built = thread_hull_cache().build(points);
  if (!built.hull) return false;
  const Hull& hull = *built.hull;
  const int f = uniform_int(r, 0, hull.face_count() - 1);
  const Vec3 corner = hull.vertex(hull.face_vertex(f, uniform_int(r, 0, hull.face_size(f) - 1)));
  const Vec3 normal = hull.face_normal(f);
  const double amount = (coin(r) ? 1 : -1) * small_amount(r) * hull.diameter();
  bool moved = false;
  for (Vec3& p : points)
    if (p == corner) {
      p += amount * normal;
      moved = true;
    }
  return moved;
}

bool scale(FuzzCase& c, MutationRandom& r) {
  const double factor = std::pow(10.0, uniform_int(r, -3, 4)) * (coin(r) ? 1 : uniform(r, 0.5, 2));
  if (coin(r)) {  // one hull about its own origin
    Pose* pose;
    for (Vec3& p : some_hull(c, r, pose)) p *= factor;
  } else {  // the whole case about the world origin: the same geometry, another unit
    for (auto* points : {&c.file.points_a, &c.file.points_b})
      for (Vec3& p : *points) p *= factor;
    c.file.pose_a.position *= factor;
    c.file.pose_b.position *= factor;
  }
  return true;
}

bool move_far(FuzzCase& c, MutationRandom& r) {
  const double size = std::max(hull_size(c.file.points_a), hull_size(c.file.points_b));
  const Vec3 shift = std::pow(10.0, uniform_int(r, 2, 7)) * size * random_direction(r);
  c.file.pose_a.position += shift;
  c.file.pose_b.position += shift;
  return true;
}

// Symmetric configurations are where ties live: B turned by an exact cube
// symmetry relative to A, both unrotated, both the same hull, or B's offset
// rounded to a few digits.
bool snap_to_symmetry(FuzzCase& c, MutationRandom& r) {
  Pose& a = c.file.pose_a;
  Pose& b = c.file.pose_b;
  switch (uniform_int(r, 0, 3)) {
    case 0: b.orientation = a.orientation.normalized() * cube_symmetries()[uniform_int(r, 0, 23)]; break;
    case 1: a.orientation = b.orientation = Quat::Identity(); break;
    case 2:
      if (coin(r)) c.file.points_b = c.file.points_a, c.family_b = c.family_a;
      else c.file.points_a = c.file.points_b, c.family_a = c.family_b;
      break;
    default: {
      const Vec3 offset = b.position - a.position;
      const double unit = std::pow(10.0, std::floor(std::log10(std::max(offset.cwiseAbs().maxCoeff(), 1e-300))) - 2);
      b.position = a.position + (offset / unit).array().round().matrix() * unit;
    }
  }
  return true;
}

bool redraw_hull(FuzzCase& c, MutationRandom& r) {
  const FuzzCase fresh = draw_fuzz_case(r());
  if (coin(r)) c.file.points_a = fresh.file.points_a, c.family_a = fresh.family_a;
  else c.file.points_b = fresh.file.points_b, c.family_b = fresh.family_b;
  return true;
}

bool swap_hulls(FuzzCase& c, MutationRandom&) {
  std::swap(c.file.points_a, c.file.points_b);
  std::swap(c.file.pose_a, c.file.pose_b);
  std::swap(c.family_a, c.family_b);
  return true;
}

uint8_t family_index(const std::string& name) {
  const auto& names = hull_family_names();
  return static_cast<uint8_t>(std::find(names.begin(), names.end(), name) - names.begin());
}

}  // namespace

const std::vector<Mutation>& geometric_mutations() {
  static const std::vector<Mutation> table = {
      {"nudge-point", nudge_point},
      {"add-point", add_point},
      {"remove-point", remove_point},
      {"rotate-by-small-angle", rotate_by_small_angle},
      {"slide-to-touching", slide_to_touching},
      {"fold-face", fold_face},
      {"scale", scale},
      {"move-far", move_far},
      {"snap-to-symmetry", snap_to_symmetry},
      {"redraw-hull", redraw_hull},
      {"swap-hulls", swap_hulls},
  };
  return table;
}

std::string mutate_geometrically(FuzzCase& c, MutationRandom& random) {
  const auto& table = geometric_mutations();
  for (int attempt = 0; attempt < 8; ++attempt) {
    const Mutation& m = table[uniform_int(random, 0, static_cast<int>(table.size()) - 1)];
    if (m.apply(c, random)) return m.name;
  }
  return nudge_point(c, random) ? "nudge-point" : "";
}

FuzzCase cross_over(const FuzzCase& x, const FuzzCase& y, MutationRandom& random) {
  FuzzCase child = x;
  switch (uniform_int(random, 0, 2)) {
    case 0:  // B from y, in y's pose
      child.file.points_b = y.file.points_b;
      child.family_b = y.family_b;
      child.file.pose_b = y.file.pose_b;
      break;
    case 1:  // A from y, x's poses
      child.file.points_a = y.file.points_a;
      child.family_a = y.family_a;
      break;
    default:  // x's hulls in y's poses
      child.file.pose_a = y.file.pose_a;
      child.file.pose_b = y.file.pose_b;
  }
  return child;
}

FuzzCase draw_fuzz_case(uint64_t seed) {
  const GeneratedCase g = any_case()(rc::Random(seed), static_cast<int>(seed % 100)).value();
  FuzzCase c{g.file, family_index(g.hull_a), family_index(g.hull_b)};
  c.file.extensions.clear();
  for (auto* points : {&c.file.points_a, &c.file.points_b})
    if (static_cast<int>(points->size()) > kFuzzMaxPoints) points->resize(kFuzzMaxPoints);
  return c;
}

std::vector<std::pair<std::string, std::vector<uint8_t>>> seed_inputs() {
  const auto& families = hull_family_names();
  std::vector<std::pair<std::string, std::vector<uint8_t>>> inputs;
  std::vector<bool> seen(families.size());
  for (uint64_t seed = 1; inputs.size() < families.size() && seed < 100000; ++seed) {
    const FuzzCase c = draw_fuzz_case(seed);
    if (c.family_a >= families.size() || seen[c.family_a]) continue;
    std::vector<uint8_t> bytes = encode_fuzz_input(c);
    const std::optional<FuzzCase> back = decode_fuzz_input(bytes.data(), bytes.size());
    if (!back || !make_scene(back->file).scene) continue;  // no valid case for this seed
    seen[c.family_a] = true;
    inputs.emplace_back(families[c.family_a], std::move(bytes));
  }
  return inputs;
}

}  // namespace mfz::props

#include "case/scene.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <utility>

#include "geometry/hull_cache.h"
#include "geometry/tolerances.h"

namespace mfz {

double Scene::length_tolerance(double k) const { return k * scale + rounding(); }

double Scene::precision_rounding(double extra_extent) const {
  return tol::kWorldUlps * precision_epsilon * std::max(world_extent + extra_extent, scale);
}

double Scene::rounding(double extra_extent) const {
  return tol::world_rounding(world_extent + extra_extent) + precision_rounding(extra_extent);
}

double Scene::point_tolerance() const {
  const double at_sharpest_corner = rounding() / sharpest_corner;
  const double cap = std::max(tol::kSharpCornerCap * scale, tol::kSharpCornerProfileCap * precision_rounding());
  return length_tolerance(tol::kPoint) + std::min(at_sharpest_corner, cap);
}

namespace {

std::vector<Vec3> posed(const Hull& hull, const Pose& pose) {
  std::vector<Vec3> out;
  out.reserve(static_cast<size_t>(hull.vertex_count()));
  for (int i = 0; i < hull.vertex_count(); ++i) out.push_back(pose.to_world(hull.vertex(i)));
  return out;
}

double largest_coordinate(const std::vector<Vec3>& points) {
  double m = 0;
  for (const Vec3& p : points) m = std::max(m, p.cwiseAbs().maxCoeff());
  return m;
}

}  // namespace

SceneBuild make_scene(const CaseFile& c) {
  // A pose-only change (a fuzzer's mutation, a relation's motion, a
  // shrinker's step) must not rebuild a hull: hulls come from a bounded
  // cache, one per thread.
  HullCache& hulls = thread_hull_cache();
  HullBuild a = hulls.build(c.points_a);
  if (!a.hull) return {std::nullopt, "hull A: " + a.error};
  HullBuild b = hulls.build(c.points_b);
  if (!b.hull) return {std::nullopt, "hull B: " + b.error};
  for (const Pose* pose : {&c.pose_a, &c.pose_b}) {
    if (!pose->position.allFinite() || !pose->orientation.coeffs().allFinite() ||
        pose->orientation.coeffs().cwiseAbs().maxCoeff() == 0)
      return {std::nullopt, "a pose is not finite or its quaternion is zero"};
    if (const double largest = pose->position.cwiseAbs().maxCoeff(); largest > tol::kLargestCoordinate) {
      char why[120];
      std::snprintf(why, sizeof why, "a pose's position has a coordinate of %.3g, past the limit of %g", largest,
                    tol::kLargestCoordinate);
      return {std::nullopt, why};
    }
  }
  Scene scene = posed_scene(std::move(*a.hull), c.pose_a, std::move(*b.hull), c.pose_b);
  // Past this the world frame's rounding (64 ulps of the coordinates) exceeds
  // 1e-6 L, every tolerance is mostly rounding, and a wrong normal would pass.
  if (tol::world_rounding(scene.world_extent) > tol::kFarthestFrame * scene.scale) {
    char why[160];
    std::snprintf(why, sizeof why,
                  "the case lies %.3g L from the origin: past %.3g L the frame's rounding exceeds %g L, and no "
                  "tolerance would mean anything",
                  scene.world_extent / scene.scale, tol::kFarthestFrame / tol::world_rounding(1), tol::kFarthestFrame);
    return {std::nullopt, why};
  }
  for (const auto& [name, hull] : {std::pair{"A", &scene.hull_a}, std::pair{"B", &scene.hull_b}}) {
    if (hull->diameter() < tol::kSmallestHullDiameter) {
      char why[120];
      std::snprintf(why, sizeof why, "hull %s has a diameter of %.3g, below the limit of %g", name, hull->diameter(),
                    tol::kSmallestHullDiameter);
      return {std::nullopt, why};
    }
    if (hull->diameter() < tol::kSmallestHullOverRounding * tol::world_rounding(scene.world_extent)) {
      char why[200];
      std::snprintf(why, sizeof why,
                    "hull %s (diameter %.3g) is smaller than %g times the rounding of world coordinates of %.3g: "
                    "its vertices are not resolved",
                    name, hull->diameter(), tol::kSmallestHullOverRounding, scene.world_extent);
      return {std::nullopt, why};
    }
  }
  return {std::move(scene), {}};
}

namespace {

// Squaring components near 1e154 overflows and near 1e-160 underflows, and
// normalize() then returns garbage: such a quaternion is scaled by its
// largest component first. Ordinary ones are normalised as they always were,
// so every case replays to the same bits.
Quat unit(Quat q) {
  const double largest = q.coeffs().cwiseAbs().maxCoeff();
  if (largest > 1e100 || largest < 1e-100) q.coeffs() /= largest;
  return q.normalized();
}

}  // namespace

Scene posed_scene(Hull a, const Pose& pose_a, Hull b, const Pose& pose_b) {
  Scene scene{std::move(a), std::move(b), pose_a, pose_b, 1, 0, 0, 1, 0, {}, {}};
  scene.pose_a.orientation = unit(scene.pose_a.orientation);
  scene.pose_b.orientation = unit(scene.pose_b.orientation);
  scene.scale = std::max(scene.hull_a.diameter(), scene.hull_b.diameter());
  scene.shortest_edge = std::min(scene.hull_a.shortest_edge(), scene.hull_b.shortest_edge());
  scene.sharpest_corner = std::min(scene.hull_a.sharpest_corner(), scene.hull_b.sharpest_corner());
  scene.world_a = posed(scene.hull_a, scene.pose_a);
  scene.world_b = posed(scene.hull_b, scene.pose_b);
  scene.world_extent = std::max(largest_coordinate(scene.world_a), largest_coordinate(scene.world_b));
  return scene;
}

}  // namespace mfz

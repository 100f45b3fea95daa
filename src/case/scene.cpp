#include "case/scene.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/tolerances.h"

namespace mfz {

double Scene::length_tolerance(double k) const {
  return k * scale + tol::world_rounding(world_extent);
}

namespace {

std::vector<Vec3> posed(const Hull& hull, const Pose& pose) {
  std::vector<Vec3> out;
  for (int i = 0; i < hull.vertex_count(); ++i) out.push_back(pose.to_world(hull.vertex(i)));
  return out;
}

double shortest_edge_of(const Hull& hull) {
  double shortest = std::numeric_limits<double>::infinity();
  for (const HullEdge& e : hull.edges()) shortest = std::min(shortest, (hull.vertex(e.v1) - hull.vertex(e.v0)).norm());
  return shortest;
}

double largest_coordinate(const std::vector<Vec3>& points) {
  double m = 0;
  for (const Vec3& p : points) m = std::max(m, p.cwiseAbs().maxCoeff());
  return m;
}

}  // namespace

SceneBuild make_scene(const CaseFile& c) {
  HullBuild a = build_hull(c.points_a);
  if (!a.hull) return {std::nullopt, "hull A: " + a.error};
  HullBuild b = build_hull(c.points_b);
  if (!b.hull) return {std::nullopt, "hull B: " + b.error};
  for (const Pose* pose : {&c.pose_a, &c.pose_b})
    if (!pose->position.allFinite() || !pose->orientation.coeffs().allFinite() || pose->orientation.norm() == 0)
      return {std::nullopt, "a pose is not finite or its quaternion is zero"};
  return {posed_scene(std::move(*a.hull), c.pose_a, std::move(*b.hull), c.pose_b), {}};
}

Scene posed_scene(Hull a, const Pose& pose_a, Hull b, const Pose& pose_b) {
  Scene scene{std::move(a), std::move(b), pose_a, pose_b, 1, 0, 0, {}, {}};
  scene.pose_a.orientation.normalize();
  scene.pose_b.orientation.normalize();
  scene.scale = std::max(scene.hull_a.diameter(), scene.hull_b.diameter());
  scene.shortest_edge = std::min(shortest_edge_of(scene.hull_a), shortest_edge_of(scene.hull_b));
  scene.world_a = posed(scene.hull_a, scene.pose_a);
  scene.world_b = posed(scene.hull_b, scene.pose_b);
  scene.world_extent = std::max(largest_coordinate(scene.world_a), largest_coordinate(scene.world_b));
  return scene;
}

}  // namespace mfz

#include "bench_families.h"

#include <algorithm>
#include <cmath>
#include <random>

#include "families.h"

namespace mfz::bench {
namespace {

using Random = std::mt19937_64;

double uniform(Random& random, double low, double high) {
  return std::uniform_real_distribution<double>(low, high)(random);
}

Vec3 random_direction(Random& random) {
  std::normal_distribution<double> gauss;
  return Vec3(gauss(random), gauss(random), gauss(random)).normalized();
}

Quat random_rotation(Random& random) {
  return Quat(Eigen::AngleAxisd(uniform(random, 0, M_PI), random_direction(random)));
}

// A turn about z (yaw), then a tilt of `tilt` radians about a horizontal axis.
Quat yaw_and_tilt(Random& random, double tilt) {
  const double heading = uniform(random, 0, 2 * M_PI);
  const Vec3 horizontal(std::cos(heading), std::sin(heading), 0);
  return Quat(Eigen::AngleAxisd(tilt, horizontal)) * Quat(Eigen::AngleAxisd(uniform(random, 0, 2 * M_PI), Vec3::UnitZ()));
}

std::vector<Vec3> sphere_points(int count, double radius, Random& random) {
  std::vector<Vec3> points;
  for (int k = 0; k < count; ++k) points.push_back(radius * random_direction(random));
  return points;
}

std::vector<Vec3> cylinder_points(int sides, double radius, double half_height) {
  std::vector<Vec3> points;
  for (int k = 0; k < sides; ++k) {
    const double angle = 2 * M_PI * k / sides;
    for (double z : {-half_height, half_height})
      points.push_back(Vec3(radius * std::cos(angle), radius * std::sin(angle), z));
  }
  return points;
}

// B's box on A's top face, `tilt` radians off, sunk a little into it.
CaseFile box_on_box(Random& random, double tilt) {
  const Vec3 ha(uniform(random, 0.5, 2), uniform(random, 0.5, 2), uniform(random, 0.2, 1));
  const Vec3 hb(uniform(random, 0.2, 0.8), uniform(random, 0.2, 0.8), uniform(random, 0.2, 0.8));
  CaseFile c;
  c.points_a = props::box_corners(ha.x(), ha.y(), ha.z());
  c.points_b = props::box_corners(hb.x(), hb.y(), hb.z());
  const Quat orientation = yaw_and_tilt(random, tilt);
  // The lowest corner of B, turned, is hb . |column z of R^T|.
  const Mat3 r = orientation.toRotationMatrix();
  const double reach = std::abs(r(2, 0)) * hb.x() + std::abs(r(2, 1)) * hb.y() + std::abs(r(2, 2)) * hb.z();
  const double sunk = uniform(random, 0.001, 0.05) * hb.minCoeff();
  c.pose_b = {Vec3(uniform(random, -0.5, 0.5) * ha.x(), uniform(random, -0.5, 0.5) * ha.y(), ha.z() + reach - sunk),
              orientation};
  return c;
}

// Two clouds on spheres of random radius, B's centre at `apart` of the
// radii's sum away: below 1 they mostly overlap, above 1 never.
CaseFile cloud_pair(Random& random, int points, double apart_low, double apart_high) {
  const double ra = uniform(random, 0.5, 2), rb = uniform(random, 0.5, 2);
  CaseFile c;
  c.points_a = sphere_points(points, ra, random);
  c.points_b = sphere_points(points, rb, random);
  c.pose_a = {Vec3::Zero(), random_rotation(random)};
  c.pose_b = {uniform(random, apart_low, apart_high) * (ra + rb) * random_direction(random), random_rotation(random)};
  return c;
}

// A cylinder standing on another, cap on cap, tilted up to a degree.
CaseFile cylinder_on_cylinder(Random& random) {
  const double ra = uniform(random, 0.5, 1.5), rb = uniform(random, 0.3, 1.2);
  const double ha = uniform(random, 0.2, 1), hb = uniform(random, 0.2, 1);
  CaseFile c;
  c.points_a = cylinder_points(64, ra, ha);
  c.points_b = cylinder_points(64, rb, hb);
  const Quat orientation = yaw_and_tilt(random, uniform(random, 0, M_PI / 180));
  const double sunk = uniform(random, 0.001, 0.05) * hb;
  c.pose_b = {Vec3(uniform(random, -0.3, 0.3) * ra, uniform(random, -0.3, 0.3) * ra, ha + hb - sunk), orientation};
  return c;
}

// Two of one cylinder stacked cap on cap and turned alike, as a column of
// barrels stands: B a little off A's axis, sunk a little into its cap.
// Every rim edge of one meets every rim edge of the other at the caps'
// normal on the Gauss map, and each side edge is parallel to the other's.
CaseFile cylinder_on_its_twin(Random& random) {
  const double radius = uniform(random, 0.3, 1.5), half_height = uniform(random, 0.2, 1);
  CaseFile c;
  c.points_a = c.points_b = cylinder_points(64, radius, half_height);
  const Quat yaw(Eigen::AngleAxisd(uniform(random, 0, 2 * M_PI), Vec3::UnitZ()));
  const double sunk = uniform(random, 0.001, 0.05) * half_height;
  c.pose_a = {Vec3::Zero(), yaw};
  c.pose_b = {Vec3(uniform(random, -0.3, 0.3) * radius, uniform(random, -0.3, 0.3) * radius, 2 * half_height - sunk),
              yaw};
  return c;
}

template <class Draw>
BenchFamily family(const std::string& name, bool boxes, int pairs, unsigned seed, Draw&& draw) {
  Random random(seed);
  BenchFamily f{name, boxes, {}};
  while (pairs > 0 && static_cast<int>(f.scenes.size()) < pairs) {
    SceneBuild built = make_scene(draw(random));
    if (built.scene) f.scenes.push_back(std::move(*built.scene));
  }
  return f;
}

}  // namespace

std::vector<BenchFamily> bench_families(int pairs, bool large,
                                        const std::function<bool(const std::string&)>& wanted) {
  const auto count = [&](const std::string& name) { return !wanted || wanted(name) ? pairs : 0; };
  std::vector<BenchFamily> families;
  families.push_back(family("boxes face to face", true, count("boxes face to face"), 1, [](Random& r) {
    return box_on_box(r, uniform(r, 0, 0.5) * M_PI / 180);
  }));
  families.push_back(family("boxes tilted", true, count("boxes tilted"), 2, [](Random& r) {
    return box_on_box(r, uniform(r, 2, 8) * M_PI / 180);
  }));
  for (int points : {8, 32, 128})
    families.push_back(family(std::to_string(points) + "-point hulls", false,
                              count(std::to_string(points) + "-point hulls"), 3 + points,
                              [points](Random& r) { return cloud_pair(r, points, 0.3, 0.9); }));
  // 512 points: past the 128 whose world vertices a call caches on its
  // stack, and where SAT once measured every edge pair (2.1 s a call).
  if (large)
    families.push_back(family("512-point hulls", false, count("512-point hulls"), 3 + 512,
                              [](Random& r) { return cloud_pair(r, 512, 0.3, 0.9); }));
  families.push_back(family("64-gon cylinders", false,
                            std::max(count("64-gon cylinders"), count("64-gon cylinders triangulated")), 4,
                            cylinder_on_cylinder));
  // The same pairs with every face split into a fan of triangles, as a mesh
  // exported from a modelling tool arrives: the same contacts, from hulls
  // whose caps are 62 triangles each.
  BenchFamily fans{"64-gon cylinders triangulated", false, families.back().scenes};
  for (Scene& s : fans.scenes) s.hull_a = fan_triangulated(s.hull_a), s.hull_b = fan_triangulated(s.hull_b);
  if (count(fans.name) == 0) fans.scenes.clear();
  if (count(families.back().name) == 0) families.back().scenes.clear();
  families.push_back(std::move(fans));
  families.push_back(family("64-gon cylinders stacked alike", false, count("64-gon cylinders stacked alike"), 6,
                            cylinder_on_its_twin));
  families.push_back(family("apart", false, count("apart"), 5, [](Random& r) { return cloud_pair(r, 32, 1.05, 2); }));
  return families;
}

}  // namespace mfz::bench

#pragma once
// Cases the benchmarks share.
#include <random>
#include <vector>

#include "case/case_file.h"
#include "geometry/vec.h"

namespace mfz::bench {

/// `count` points on the unit sphere, from `random`.
inline std::vector<Vec3> sphere_cloud(int count, std::mt19937_64& random) {
  std::normal_distribution<double> gauss;
  std::vector<Vec3> points;
  for (int k = 0; k < count; ++k) points.push_back(Vec3(gauss(random), gauss(random), gauss(random)).normalized());
  return points;
}

/// Two `points`-point sphere clouds, B placed within reach of A and turned:
/// most such pairs overlap, some are apart.
inline CaseFile random_cloud_pair(int points, std::mt19937_64& random) {
  CaseFile c;
  c.points_a = sphere_cloud(points, random);
  c.points_b = sphere_cloud(points, random);
  std::uniform_real_distribution<double> u(-1, 1);
  c.pose_b = {Vec3(u(random), u(random), u(random)), Quat(Eigen::AngleAxisd(3 * u(random), Vec3(1, 2, 3).normalized()))};
  return c;
}

}  // namespace mfz::bench

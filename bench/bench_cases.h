#pragma once
// Cases the benchmarks share.
#include <random>
#include <vector>

#include "geometry/vec.h"

namespace mfz::bench {

/// `count` points on the unit sphere, from `random`.
inline std::vector<Vec3> sphere_cloud(int count, std::mt19937_64& random) {
  std::normal_distribution<double> gauss;
  std::vector<Vec3> points;
  for (int k = 0; k < count; ++k) points.push_back(Vec3(gauss(random), gauss(random), gauss(random)).normalized());
  return points;
}

}  // namespace mfz::bench

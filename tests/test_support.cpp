#include "test_support.h"

#include <filesystem>
#include <random>

#include <unistd.h>

#include "families.h"

namespace mfz::test {

std::vector<Vec3> sphere_points(int count, unsigned seed) {
  std::mt19937 random(seed);
  std::normal_distribution<double> gauss;
  std::vector<Vec3> points;
  for (int k = 0; k < count; ++k) points.push_back(Vec3(gauss(random), gauss(random), gauss(random)).normalized());
  return points;
}

std::vector<Vec3> box_points(double hx, double hy, double hz) { return props::box_corners(hx, hy, hz); }

std::vector<Vec3> tetrahedron_points() { return {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}}; }

Quat about(const Vec3& axis, double angle) { return Quat(Eigen::AngleAxisd(angle, axis.normalized())); }

CaseFile make_case(std::vector<Vec3> a, const Pose& pose_a, std::vector<Vec3> b, const Pose& pose_b) {
  CaseFile c;
  c.points_a = std::move(a);
  c.points_b = std::move(b);
  c.pose_a = pose_a;
  c.pose_b = pose_b;
  return c;
}

CaseRun run_builtin(const CaseFile& c) {
  std::string error;
  auto run = run_case(c, Generator::builtin(), error);
  if (!run) {
    ADD_FAILURE() << "input error: " << error;
    std::abort();
  }
  return std::move(*run);
}

std::string corpus_path(const std::string& name) { return std::string(MANIFUZZ_SOURCE_DIR) + "/corpus/" + name; }

std::string scratch_path(const std::string& name) {
  return (std::filesystem::temp_directory_path() / (name + "-" + std::to_string(getpid()))).string();
}

}  // namespace mfz::test

#include "test_support.h"

#include <cmath>
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

std::vector<Vec3> pyramid_points(int sides, double radius, double apex_z) {
  std::vector<Vec3> points;
  for (int k = 0; k < sides; ++k)
    points.push_back(Vec3(radius * std::cos(2 * M_PI * k / sides), radius * std::sin(2 * M_PI * k / sides), 0));
  points.push_back(Vec3(0, 0, apex_z));
  return points;
}

Quat about(const Vec3& axis, double angle) { return Quat(Eigen::AngleAxisd(angle, axis.normalized())); }

PosedCase::PosedCase(const CaseFile& file)
    : hull_a(build_hull(file.points_a).hull), hull_b(build_hull(file.points_b).hull), pose_a(file.pose_a),
      pose_b(file.pose_b) {
  built = hull_a.has_value() && hull_b.has_value();
  if (!built) return;
  view_a = hull_a->view(), view_b = hull_b->view();
  pose_a.orientation.normalize();
  pose_b.orientation.normalize();
}

void PosedCase::centre_on_a() {
  pose_b.position -= pose_a.position;
  pose_a.position = Vec3::Zero();
}

namespace {

std::vector<Vec3> scaled(std::vector<Vec3> points, double factor) {
  for (Vec3& p : points) p *= factor;
  return points;
}

double unit_draw(std::mt19937& random) { return std::uniform_real_distribution<double>(0, 1)(random); }

Vec3 random_direction(std::mt19937& random) {
  std::normal_distribution<double> gauss;
  const double x = gauss(random), y = gauss(random), z = gauss(random);
  return Vec3(x, y, z).normalized();
}

// Up to 3 rad about any axis: the axis drawn first.
Quat random_turn(std::mt19937& random) {
  const Vec3 axis = random_direction(random);
  return about(axis, 3 * unit_draw(random));
}

}  // namespace

// The members draw from `random` in their order of declaration: B's
// radius, how far apart, A's turn, the direction apart, B's turn.
OverlappingClouds::OverlappingClouds(const std::vector<Vec3>& points_a, int count_b, unsigned seed_b,
                                     std::mt19937& random)
    : radius_b(0.5 + unit_draw(random)),
      hull_a(*build_hull(points_a).hull),
      hull_b(*build_hull(scaled(sphere_points(count_b, seed_b), radius_b)).hull),
      view_a(hull_a.view()),
      view_b(hull_b.view()),
      apart((1 + radius_b) * (0.15 + 0.85 * unit_draw(random))),
      pose_a{Vec3::Zero(), random_turn(random)},
      towards(random_direction(random)),
      pose_b{apart * towards, random_turn(random)} {}

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

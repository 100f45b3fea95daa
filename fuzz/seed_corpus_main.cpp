// Writes fuzz inputs into FOLDER:
//   manifold_fuzzer_seed_corpus FOLDER
//     the seed corpus, one input for each hull family, drawn the way
//     `manifuzz check` draws its cases (props::seed_inputs), as
//     corpus/manifold_fuzzer/ holds it;
//   manifold_fuzzer_seed_corpus --clouds POINTS COUNT FOLDER
//     COUNT pairs of POINTS-point clouds on the unit sphere within reach of
//     each other (fixed seed): the inputs for measuring exec/s.
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <string>

#include "families.h"
#include "fuzz_input.h"
#include "geometric_mutator.h"

namespace {

bool write(const std::string& path, const std::vector<uint8_t>& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  return static_cast<bool>(out);
}

std::vector<mfz::Vec3> sphere_cloud(int count, std::mt19937_64& random) {
  std::normal_distribution<double> gauss;
  std::vector<mfz::Vec3> points;
  for (int k = 0; k < count; ++k) points.push_back(mfz::Vec3(gauss(random), gauss(random), gauss(random)).normalized());
  return points;
}

int write_clouds(int points, int count, const std::string& folder) {
  std::mt19937_64 random(0x5eed);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int k = 0; k < count; ++k) {
    mfz::props::FuzzCase c;
    c.file.points_a = sphere_cloud(points, random);
    c.file.points_b = sphere_cloud(points, random);
    c.file.pose_b = {mfz::Vec3(u(random), u(random), u(random)),
                     mfz::Quat(Eigen::AngleAxisd(3 * u(random), mfz::Vec3(1, 2, 3).normalized()))};
    if (!write(folder + "/cloud-" + std::to_string(k), mfz::props::encode_fuzz_input(c))) return 2;
  }
  std::printf("%d inputs of two %d-point clouds written\n", count, points);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 5 && std::string(argv[1]) == "--clouds")
    return write_clouds(std::atoi(argv[2]), std::atoi(argv[3]), argv[4]);
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s FOLDER | --clouds POINTS COUNT FOLDER\n", argv[0]);
    return 2;
  }
  const auto inputs = mfz::props::seed_inputs();
  for (const auto& [name, bytes] : inputs)
    if (!write(std::string(argv[1]) + "/" + name, bytes)) {
      std::fprintf(stderr, "cannot write into %s\n", argv[1]);
      return 2;
    }
  std::printf("%zu seed inputs written\n", inputs.size());
  return inputs.size() == mfz::props::hull_family_names().size() ? 0 : 1;
}

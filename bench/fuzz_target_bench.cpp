// Executions per second of the manifold fuzzer's target on one core, as
// libFuzzer calls it (decode, the one pipeline with every invariant and
// relation), without libFuzzer's instrumentation or a sanitizer: on 1024
// distinct 8- and 32-point cloud pairs (every hull built), and on 16 point
// sets each in 64 poses (what a pose-only mutation costs: no hull built).
#include <benchmark/benchmark.h>

#include <random>

#include "bench_cases.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv);
extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

namespace mfz {
namespace {

std::vector<std::vector<uint8_t>> inputs(int points, int point_sets, int poses_each) {
  std::mt19937_64 random(0x5eed);
  std::vector<std::vector<uint8_t>> out;
  for (int s = 0; s < point_sets; ++s) {
    const CaseFile shape = bench::random_cloud_pair(points, random);
    for (int p = 0; p < poses_each; ++p) {
      CaseFile c = bench::random_cloud_pair(points, random);
      c.points_a = shape.points_a;
      c.points_b = shape.points_b;
      out.push_back(props::encode_fuzz_input({c, 0, 0}));
    }
  }
  std::shuffle(out.begin(), out.end(), random);
  return out;
}

void run(benchmark::State& state, int point_sets, int poses_each) {
  static const bool initialised = [] {
    int argc = 1;
    char name[] = "fuzz_target_bench";
    char* argv_storage[] = {name, nullptr};
    char** argv = argv_storage;
    return LLVMFuzzerInitialize(&argc, &argv) == 0;
  }();
  if (!initialised) state.SkipWithError("the target did not initialise");
  const auto all = inputs(static_cast<int>(state.range(0)), point_sets, poses_each);
  size_t k = 0;
  for (auto _ : state) {
    const auto& input = all[k++ % all.size()];
    benchmark::DoNotOptimize(LLVMFuzzerTestOneInput(input.data(), input.size()));
  }
  state.SetItemsProcessed(state.iterations());
}

void BM_FuzzExecDistinctHulls(benchmark::State& state) { run(state, 1024, 1); }
BENCHMARK(BM_FuzzExecDistinctHulls)->Arg(8)->Arg(32)->Unit(benchmark::kMicrosecond);

void BM_FuzzExecPoseMutations(benchmark::State& state) { run(state, 16, 64); }
BENCHMARK(BM_FuzzExecPoseMutations)->Arg(8)->Arg(32)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace mfz

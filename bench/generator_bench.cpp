// ns per query of every generator at hand, family by family, in one run: the
// built-in through its plugin (libmanifuzz_clipping.so, the same ABI call any
// harness makes), the peers' plugins built beside it (Bullet's SAT and
// GJK/EPA paths, ODE's convex collider and dBoxBox), and libccd's EPA and MPR
// (one point each). Each family's 1024 pairs are cycled through the timed
// loop, so no one case stays hot in the cache (MANIFUZZ_BENCH_PAIRS cycles
// fewer). After Google Benchmark's own
// report, a table: the median ns per query, contacts per query, and each
// generator's time over the built-in's (scripts/bench_table.sh).
#include <benchmark/benchmark.h>

#include <ccd/ccd.h>

#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <filesystem>
#include <functional>
#include <iostream>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "bench_families.h"
#include "harness/generator.h"

namespace mfz {
namespace {

// A query: one pair, its contact count (or -1 when refused).
using Query = std::function<int(const Scene&)>;

struct Contender {
  std::string name;
  bool boxes_only = false;
  Query query;
};

// --- plugins through the ABI ---

struct AbiPair {
  mfz_hull a, b;
  mfz_pose pose_a, pose_b;
};

Query abi_query(mfz_generate_fn generate) {
  return [generate](const Scene& s) {
    const AbiPair p{s.hull_a.view(), s.hull_b.view(), s.abi_pose_a(), s.abi_pose_b()};
    static mfz_manifold out;
    if (generate(&p.a, &p.pose_a, &p.b, &p.pose_b, &out) != 0) return -1;
    return static_cast<int>(out.contact_count);
  };
}

std::filesystem::path plugin_folder() {
  std::error_code ec;
  return std::filesystem::read_symlink("/proc/self/exe", ec).parent_path() / ".." / "plugins";
}

void add_plugin(std::vector<Contender>& out, std::vector<Generator>& keep, const std::string& name,
                const std::string& file, bool boxes_only) {
  const std::filesystem::path path = plugin_folder() / file;
  if (!std::filesystem::exists(path)) {
    std::fprintf(stderr, "generator_bench: %s not built (%s): left out\n", name.c_str(), path.c_str());
    return;
  }
  std::string error;
  auto generator = Generator::open(path.string(), error);
  if (!generator) {
    std::fprintf(stderr, "generator_bench: %s: %s\n", name.c_str(), error.c_str());
    return;
  }
  keep.push_back(*generator);
  out.push_back({name, boxes_only, abi_query(generator->entry_point())});
}

// --- libccd on the posed vertices ---

struct CcdShape {
  const std::vector<Vec3>* points;
  Vec3 centre;
};

void ccd_support(const void* object, const ccd_vec3_t* dir, ccd_vec3_t* out) {
  const auto& shape = *static_cast<const CcdShape*>(object);
  const Vec3 d(ccdVec3X(dir), ccdVec3Y(dir), ccdVec3Z(dir));
  const Vec3* best = &(*shape.points)[0];
  double best_d = -std::numeric_limits<double>::infinity();
  for (const Vec3& p : *shape.points)
    if (const double v = d.dot(p); v > best_d) best_d = v, best = &p;
  ccdVec3Set(out, best->x(), best->y(), best->z());
}

void ccd_centre(const void* object, ccd_vec3_t* out) {
  const auto& c = static_cast<const CcdShape*>(object)->centre;
  ccdVec3Set(out, c.x(), c.y(), c.z());
}

Vec3 mean(const std::vector<Vec3>& points) {
  Vec3 sum = Vec3::Zero();
  for (const Vec3& p : points) sum += p;
  return sum / static_cast<double>(points.size());
}

Query ccd_query(bool mpr) {
  return [mpr](const Scene& s) {
    ccd_t ccd;
    CCD_INIT(&ccd);
    ccd.support1 = ccd.support2 = ccd_support;
    ccd.center1 = ccd.center2 = ccd_centre;
    ccd.max_iterations = 1000;
    const CcdShape a{&s.world_a, mean(s.world_a)}, b{&s.world_b, mean(s.world_b)};
    ccd_real_t depth;
    ccd_vec3_t direction, position;
    const int status = mpr ? ccdMPRPenetration(&a, &b, &ccd, &depth, &direction, &position)
                           : ccdGJKPenetration(&a, &b, &ccd, &depth, &direction, &position);
    return status == 0 ? 1 : 0;
  };
}

// --- the run and its table ---

struct Cell {
  double ns = 0;
  double contacts = 0;
  bool refused = false;
};
std::map<std::string, std::map<std::string, Cell>> g_table;  // generator -> family -> cell

void time_queries(benchmark::State& state, const std::vector<Scene>& scenes, const Query& query) {
  size_t k = 0;
  long long contacts = 0, refused = 0;
  for (auto _ : state) {
    const int n = query(scenes[k++ % scenes.size()]);
    benchmark::DoNotOptimize(n);
    if (n < 0) ++refused; else contacts += n;
  }
  state.counters["contacts"] = benchmark::Counter(static_cast<double>(contacts), benchmark::Counter::kAvgIterations);
  state.counters["refused"] = benchmark::Counter(static_cast<double>(refused), benchmark::Counter::kAvgIterations);
}

// Keeps each benchmark's median for the table printed at the end.
class TableReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& run : runs) {
      if (run.run_type != Run::RT_Aggregate || run.aggregate_name != "median") continue;
      const std::string name = run.run_name.function_name;  // "family/generator"
      const auto slash = name.rfind('/');
      Cell& cell = g_table[name.substr(slash + 1)][name.substr(0, slash)];
      cell.ns = run.GetAdjustedCPUTime();
      cell.contacts = run.counters.at("contacts");
      cell.refused = run.counters.at("refused") > 0.5;
    }
  }
};

void print_table(const std::vector<bench::BenchFamily>& families, const std::vector<Contender>& contenders) {
  std::printf("\n| median ns per query (contacts; x built-in) |");
  for (const auto& f : families) std::printf(" %s |", f.name.c_str());
  std::printf("\n|---|");
  for (size_t i = 0; i < families.size(); ++i) std::printf("---|");
  std::printf("\n");
  const auto& builtin = g_table["built-in"];
  for (const Contender& c : contenders) {
    std::printf("| %s |", c.name.c_str());
    for (const auto& f : families) {
      const auto& row = g_table[c.name];
      const auto cell = row.find(f.name);
      if (cell == row.end()) {
        std::printf(" – |");
        continue;
      }
      const Cell& x = cell->second;
      const auto base = builtin.find(f.name);
      std::printf(" %.0f (%.1f", x.ns, x.contacts);
      if (c.name != "built-in" && base != builtin.end() && base->second.ns > 0)
        std::printf("; %.2fx", x.ns / base->second.ns);
      std::printf(")%s |", x.refused ? " refused some" : "");
    }
    std::printf("\n");
  }
}

// A family's scenes, built the first time one of its runs starts (set-up,
// outside the timed loop): a run filtered to the boxes does not wait for
// seconds of Qhull on the other families, minutes under valgrind.
const std::vector<Scene>& family_scenes(const std::string& name, int pairs) {
  static std::map<std::string, std::vector<Scene>> built;
  auto found = built.find(name);
  if (found == built.end()) {
    for (bench::BenchFamily& f :
         bench::bench_families(pairs, /*large=*/true, [&name](const std::string& n) { return n == name; }))
      if (f.name == name) found = built.emplace(name, std::move(f.scenes)).first;
  }
  return found->second;
}

}  // namespace
}  // namespace mfz

int main(int argc, char** argv) {
  using namespace mfz;
  benchmark::Initialize(&argc, argv);
  std::vector<Generator> loaded;
  std::vector<Contender> contenders;
  add_plugin(contenders, loaded, "built-in", "libmanifuzz_clipping.so", false);
  // MANIFUZZ_BENCH_PLUGINS="NAME=PATH;NAME=PATH": more generators timed in the
  // same run, beside the built-in (a user's own plugin, or the built-in of
  // another commit: a change is measured against its baseline on one core
  // in one process, not across runs of a noisy machine).
  if (const char* more = std::getenv("MANIFUZZ_BENCH_PLUGINS")) {
    std::stringstream list(more);
    for (std::string item; std::getline(list, item, ';');) {
      const size_t equals = item.find('=');
      if (equals == std::string::npos || equals == 0) {
        std::fprintf(stderr, "generator_bench: MANIFUZZ_BENCH_PLUGINS takes NAME=PATH;...: '%s' left out\n", item.c_str());
        continue;
      }
      add_plugin(contenders, loaded, item.substr(0, equals), item.substr(equals + 1), false);
    }
  }
  add_plugin(contenders, loaded, "Bullet SAT + clip (float)", "libmanifuzz_peer_bullet_sat.so", false);
  add_plugin(contenders, loaded, "Bullet GJK-EPA + clip (float)", "libmanifuzz_peer_bullet.so", false);
  add_plugin(contenders, loaded, "ODE SAT + clip", "libmanifuzz_peer_ode.so", false);
  add_plugin(contenders, loaded, "ODE dBoxBox", "libmanifuzz_peer_ode_box.so", true);
  contenders.push_back({"libccd EPA (1 point)", false, ccd_query(false)});
  contenders.push_back({"libccd MPR (1 point)", false, ccd_query(true)});
  // MANIFUZZ_BENCH_PAIRS=N: N pairs a family cycled instead of 1,024. With
  // 64 the pairs stay in the cache, so the two runs tell how much of a call
  // is waiting on memory (docs/generator.md: a fifth of an 8-point call).
  int pairs = 1024;
  if (const char* given = std::getenv("MANIFUZZ_BENCH_PAIRS")) {
    char* end = nullptr;
    const long n = std::strtol(given, &end, 10);
    if (end == given || *end != '\0' || n < 1 || n > 1024) {
      std::fprintf(stderr, "generator_bench: MANIFUZZ_BENCH_PAIRS takes a count of pairs from 1 to 1024, not '%s'\n", given);
      return 2;
    }
    pairs = static_cast<int>(n);
  }
  // The families' names alone here (no scenes): each is built when its
  // first run starts.
  const std::vector<bench::BenchFamily> families =
      bench::bench_families(pairs, /*large=*/true, [](const std::string&) { return false; });
  for (const auto& family : families)
    for (const Contender& c : contenders) {
      if (c.boxes_only && !family.boxes) continue;
      const std::string name = family.name;
      const Query query = c.query;
      benchmark::RegisterBenchmark((family.name + "/" + c.name).c_str(), [name, pairs, query](benchmark::State& s) {
        time_queries(s, family_scenes(name, pairs), query);
      })
          ->Repetitions(3)
          ->ReportAggregatesOnly(true)
          ->MinTime(0.2);
    }
  TableReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  print_table(families, contenders);
  benchmark::Shutdown();
  return 0;
}

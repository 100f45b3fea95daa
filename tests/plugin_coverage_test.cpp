// A plugin's coverage counters: found in the loaded library, moved by its own
// code when it is called, and carried from its worker to this process.
// The clang build instruments the plugins (MANIFUZZ_PLUGINS_COUNT_COVERAGE);
// the g++ build does not, and there a plugin has no counters to find.
#include "harness/plugin_coverage.h"

#include <dlfcn.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>

#include "case/scene.h"
#include "harness/generator_session.h"
#include "test_support.h"

namespace mfz {
namespace {

const std::string kClippingPlugin = std::string(MANIFUZZ_PLUGIN_DIR) + "/libmanifuzz_clipping.so";

// A box resting on a slab, tilted a little: a call that runs SAT, the clip
// and the depth filter.
Scene resting_box() {
  const CaseFile c = test::make_case(test::box_points(2, 2, 0.5), {}, test::box_points(0.5, 0.5, 0.5),
                                     {Vec3(0.1, 0.2, 0.9), test::about(Vec3(1, 2, 3), 0.1)});
  SceneBuild built = make_scene(c);
  EXPECT_TRUE(built.scene) << built.error;
  return std::move(built.scene.value());
}

size_t set_counters(const CoverageCounters& counters) {
  return static_cast<size_t>(std::count_if(counters.begin, counters.begin + counters.size, [](uint8_t c) { return c; }));
}

TEST(PluginCoverage, HitsTakenFromOneCopyAddUpInAnother) {
  // 43 counters: five words read at once, then three one by one.
  uint8_t worker[43] = {}, here[43] = {};
  worker[0] = 1, worker[9] = 7, worker[39] = 200, worker[41] = 3;
  std::string message;
  take_coverage_hits({worker, sizeof worker}, message);
  EXPECT_EQ(set_counters({worker, sizeof worker}), 0u) << "taken hits are cleared for the next call";
  uint32_t count = 0;
  ASSERT_GE(message.size(), sizeof count);
  std::memcpy(&count, message.data(), sizeof count);
  ASSERT_EQ(count, 4u);
  ASSERT_EQ(message.size(), sizeof count * (1 + count));
  std::vector<uint32_t> hits(count);
  std::memcpy(hits.data(), message.data() + sizeof count, sizeof(uint32_t) * count);
  ASSERT_TRUE(apply_coverage_hits({here, sizeof here}, hits.data(), count));
  ASSERT_TRUE(apply_coverage_hits({here, sizeof here}, hits.data(), count));  // a second call of the same execution
  EXPECT_EQ(here[0], 2);
  EXPECT_EQ(here[9], 14);
  EXPECT_EQ(here[39], 255) << "counts stop at the top rather than wrap to zero";
  EXPECT_EQ(here[41], 6);
  EXPECT_EQ(set_counters({here, sizeof here}), 4u);
  EXPECT_FALSE(apply_coverage_hits({here, 41}, hits.data(), count)) << "a hit past the counters is refused";
}

#ifdef MANIFUZZ_PLUGINS_COUNT_COVERAGE

// The plugin's counters as this process has it loaded (the session loads it
// here to share its coverage).
CoverageCounters counters_loaded_here() {
  void* library = dlopen(kClippingPlugin.c_str(), RTLD_NOW | RTLD_LOCAL | RTLD_NOLOAD);
  if (!library) return {};
  const CoverageCounters counters = coverage_counters_at(dlsym(library, "mfz_generate"));
  dlclose(library);
  return counters;
}


TEST(PluginCoverage, APluginsCallMovesItsOwnCountersNotTheProgramsCopy) {
  std::string error;
  const auto plugin = Generator::open(kClippingPlugin, error);
  ASSERT_TRUE(plugin) << error;
  const CoverageCounters counters = coverage_counters_at(reinterpret_cast<const void*>(plugin->entry_point()));
  ASSERT_GT(counters.size, 1000u) << "the built-in plugin has its generator's counters";
  std::string cleared;
  take_coverage_hits(counters, cleared);
  const Scene scene = resting_box();
  mfz_manifold out;
  const mfz_hull a = scene.hull_a.view(), b = scene.hull_b.view();
  ASSERT_EQ(plugin->generate(a, scene.abi_pose_a(), b, scene.abi_pose_b(), out), 0);
  // This program links the same library and exports its symbols: bound to
  // them, the plugin's calls ran the program's copy, and only its entry
  // point counted (one counter).
  EXPECT_GT(set_counters(counters), 100u);
}

TEST(PluginCoverage, AWorkersCountersReachThisProcessOnlyWhenShared) {
  const Scene scene = resting_box();
  const mfz_hull a = scene.hull_a.view(), b = scene.hull_b.view();
  // Shared first: from then on the plugin stays loaded here, so that the
  // call not shared can be seen to count nothing here.
  for (const bool share : {true, false}) {
    std::string error;
    auto session = open_session(kClippingPlugin, 5, error, share);
    ASSERT_TRUE(session) << error;
    const CoverageCounters here = counters_loaded_here();
    if (here.begin) std::memset(here.begin, 0, here.size);
    mfz_manifold out;
    int32_t status = -1;
    std::string failure;
    ASSERT_EQ(session->generate(a, scene.abi_pose_a(), b, scene.abi_pose_b(), out, status, failure),
              CallOutcome::done)
        << failure;
    EXPECT_EQ(status, 0);
    ASSERT_GT(here.size, 1000u) << "sharing loads the plugin in this process";
    if (share)
      EXPECT_GT(set_counters(here), 100u) << "the worker's call counted here";
    else
      EXPECT_EQ(set_counters(here), 0u) << "a worker not asked to share sends nothing";
  }
}

#else

TEST(PluginCoverage, APluginBuiltWithoutCountersHasNoneAndItsWorkerSendsNone) {
  std::string error;
  const auto plugin = Generator::open(kClippingPlugin, error);
  ASSERT_TRUE(plugin) << error;
  EXPECT_EQ(coverage_counters_at(reinterpret_cast<const void*>(plugin->entry_point())).size, 0u);
  // Asked to share, the worker finds nothing to send, and answers as ever.
  const Scene scene = resting_box();
  auto session = open_session(kClippingPlugin, 5, error, true);
  ASSERT_TRUE(session) << error;
  mfz_manifold out;
  int32_t status = -1;
  std::string failure;
  ASSERT_EQ(session->generate(scene.hull_a.view(), scene.abi_pose_a(), scene.hull_b.view(), scene.abi_pose_b(), out,
                              status, failure),
            CallOutcome::done)
      << failure;
  EXPECT_EQ(status, 0);
  EXPECT_GT(out.contact_count, 0);
}

#endif

}  // namespace
}  // namespace mfz

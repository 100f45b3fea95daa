// manifuzz diff's comparison: each kind of disagreement fires on a
// generator broken that way, names the right side, and a generator against
// itself, or a reducer against the full manifold it reduces, agrees.
#include "differential_run.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "test_support.h"

namespace mfz {
namespace {

using props::DiffSide;

std::unique_ptr<GeneratorSession> mutant(const std::string& name) {
  const std::string path = std::string(MANIFUZZ_PLUGIN_DIR) + "/libmfz_mutant_" + name + ".so";
  if (!std::filesystem::exists(path)) return nullptr;
  std::string error;
  auto session = open_session(path, 5, error);
  EXPECT_TRUE(session) << error;
  return session;
}

CaseFile corpus_case(const std::string& name) {
  const CaseParse parsed = read_case_file(test::corpus_path(name + ".case"));
  EXPECT_TRUE(parsed.value) << parsed.error;
  return parsed.value.value_or(CaseFile{});
}

// The built-in as the first side, `broken` as the second, on `c`.
std::optional<props::Disagreement> against_builtin(const std::string& broken, const CaseFile& c, Profile profile = {}) {
  std::string error;
  auto builtin = open_session("builtin", 5, error);
  auto other = mutant(broken);
  if (!other) return props::Disagreement{"not-built", "", ""};
  DiffSide first{builtin.get(), {}}, second{other.get(), profile};
  bool invalid = false;
  auto d = props::compare_generators(c, first, second, invalid);
  EXPECT_FALSE(invalid);
  return d;
}

#define SKIP_UNLESS_BUILT(d) \
  if ((d) && (d)->kind == "not-built") GTEST_SKIP() << "the mutants are not built in this preset"

TEST(Diff, AGeneratorAgreesWithItself) {
  std::string error;
  auto one = open_session("builtin", 5, error), two = open_session("builtin", 5, error);
  DiffSide first{one.get(), {}}, second{two.get(), {}};
  for (const char* name : {"box_on_box", "box_turned_45_on_box", "edge_crosses_edge", "tetrahedron_tip_in_face"}) {
    bool invalid = false;
    EXPECT_FALSE(props::compare_generators(corpus_case(name), first, second, invalid)) << name;
  }
}

// Each kind fires on a generator broken that way, and the oracles side with
// the built-in.
struct BrokenWay {
  const char* mutant;
  const char* corpus_case;
  const char* kind;
};

class DiffKind : public ::testing::TestWithParam<BrokenWay> {};

TEST_P(DiffKind, FiresOnAGeneratorBrokenThatWayAndSidesWithTheBuiltin) {
  CaseFile c = corpus_case(GetParam().corpus_case);
  // The near-touching mutant calls an overlap of 1e-7 apart.
  if (std::string(GetParam().mutant) == "near_touching") c.pose_b.position.z() = 1 - 1e-7;
  const auto d = against_builtin(GetParam().mutant, c);
  SKIP_UNLESS_BUILT(d);
  ASSERT_TRUE(d);
  EXPECT_EQ(d->kind, GetParam().kind);
  EXPECT_EQ(d->sides_with, "first");
}

INSTANTIATE_TEST_SUITE_P(Diff, DiffKind,
                         ::testing::Values(BrokenWay{"near_touching", "box_on_box", "colliding"},
                                           BrokenWay{"edge_axes_skipped", "edge_crosses_edge", "depth"},
                                           BrokenWay{"normal_sign", "box_on_box", "normal"},
                                           BrokenWay{"deepest_only", "box_turned_45_on_box", "contact-region"}),
                         [](const auto& info) {
                           std::string name = info.param.kind;
                           for (char& ch : name)
                             if (ch == '-') ch = '_';
                           return name;
                         });

// A reducer keeps four of the eight corners: under its max-contacts its
// points need only lie inside the full manifold's.
TEST(Diff, AReducerUnderItsProfileAgreesWithTheFullManifold) {
  Profile four;
  four.max_contacts = 4;
  const auto d = against_builtin("reducing", corpus_case("box_turned_45_on_box"), four);
  SKIP_UNLESS_BUILT(d);
  EXPECT_FALSE(d) << d->kind << ": " << d->detail;
}

}  // namespace
}  // namespace mfz

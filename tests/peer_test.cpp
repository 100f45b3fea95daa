// The peers (Bullet and ODE wrapped as plugins, peers/): that their
// conventions are mapped to the contract's, on the hand-computed cases, and
// that each finding kept in corpus/peers/ still gets the answer its
// `expect GENERATOR OUTCOME` lines record (the engine's current answer; a
// float finding also names the double build, which must fail alike). A peer
// whose library was not found at build time is skipped, and says so.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>

#include "case_property.h"
#include "harness/profile.h"
#include "test_support.h"

namespace mfz {
namespace {

std::string plugin_of(const std::string& generator) {
  std::string file = "libmanifuzz_peer_" + generator + ".so";
  std::replace(file.begin(), file.end(), '-', '_');
  return std::string(MANIFUZZ_PLUGIN_DIR) + "/" + file;
}

// One worker per peer for the whole test: the session of each, opened once.
GeneratorSession* session_of(const std::string& generator) {
  static std::map<std::string, std::unique_ptr<GeneratorSession>> sessions;
  auto& session = sessions[generator];
  if (!session && std::filesystem::exists(plugin_of(generator))) {
    std::string error;
    session = open_session(plugin_of(generator), 10, error);
    EXPECT_TRUE(session) << error;
  }
  return session.get();
}

props::Selection declared(const GeneratorSession& session, std::set<std::string> names = {}) {
  std::string error;
  props::Selection selection;
  selection.names = std::move(names);
  const auto profile = profile_in_force(session.declared_profile(), std::nullopt, error);
  EXPECT_TRUE(profile) << error;
  selection.profile = profile.value_or(Profile{});
  return selection;
}

// The invariants a wrong mapping of conventions breaks: the normal's
// direction and length, the signs of the depths, where the two points of a
// contact lie and how they pair.
const std::set<std::string> kConventionChecks = {"unit-normal", "negative-penetration", "pair-consistency",
                                                 "on-surface", "agrees-with-gjk", "depth-exact"};

class PeerConventions : public ::testing::TestWithParam<std::string> {};

TEST_P(PeerConventions, HandComputedFaceCasesComeOutInTheContractsTerms) {
  GeneratorSession* session = session_of(GetParam());
  if (!session) GTEST_SKIP() << GetParam() << " was not built (its library was not found)";
  for (const char* name : {"box_on_box", "box_turned_45_on_box", "separated", "touching"}) {
    const CaseParse parsed = read_case_file(test::corpus_path(std::string(name) + ".case"));
    ASSERT_TRUE(parsed.value) << parsed.error;
    const props::CaseOutcome o = props::check_case(*parsed.value, *session, declared(*session, kConventionChecks));
    EXPECT_FALSE(o.finding) << GetParam() << " on " << name << ": " << o.finding->name << ": " << o.finding->detail;
  }
}

INSTANTIATE_TEST_SUITE_P(Peers, PeerConventions,
                         ::testing::Values("bullet-sat", "bullet", "bullet-sat-double", "bullet-double", "ode", "ode-box"),
                         [](const auto& info) {
                           std::string name = info.param;
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

// ---- the findings kept, each with the engine's current answer ----

std::vector<std::string> peer_cases() {
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(test::corpus_path("peers")))
    if (entry.path().extension() == ".case") files.push_back(entry.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

class PeerFinding : public ::testing::TestWithParam<std::string> {};

TEST_P(PeerFinding, EachPeerStillAnswersAsRecorded) {
  const CaseParse parsed = read_case_file(GetParam());
  ASSERT_TRUE(parsed.value) << parsed.error;
  int expectations = 0;
  for (const std::string& line : parsed.value->extensions) {
    std::istringstream words(line);
    std::string key, generator, outcome;
    if (!(words >> key >> generator >> outcome) || key != "expect") continue;
    ++expectations;
    GeneratorSession* session = session_of(generator);
    if (!session) {
      std::cout << "skipped: " << generator << " was not built\n";
      continue;
    }
    // The case's own `profile` line is the profile the finding was made under.
    const props::CaseOutcome o = props::check_case(*parsed.value, *session, declared(*session));
    ASSERT_FALSE(o.invalid) << o.invalid_reason;
    EXPECT_EQ(o.finding ? o.finding->name : "pass", outcome) << generator;
  }
  EXPECT_GT(expectations, 0) << "the case has no 'expect GENERATOR OUTCOME' line";
}

INSTANTIATE_TEST_SUITE_P(Corpus, PeerFinding, ::testing::ValuesIn(peer_cases()), [](const auto& info) {
  const std::filesystem::path path(info.param);
  std::string name = path.parent_path().filename().string() + "_" + path.stem().string();
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
});

}  // namespace
}  // namespace mfz

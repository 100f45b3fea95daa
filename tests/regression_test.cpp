// Every case in corpus/regressions is a minimised finding: the built-in
// generator must pass the whole property on it (invariants and relations), and
// the tutorial's unfixed method must answer as the case's `expect-tutorial` line says
// (the finding it shows, or `pass` for a bug a later fix introduced), so each
// case still pins what it was kept for. Regression cases are never deleted.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <memory>
#include <sstream>

#include "case_property.h"
#include "test_support.h"

namespace mfz {
namespace {

// MANIFUZZ_REGRESSIONS_DIR points the test at another folder of cases
// (a promoted case in tests/fuzz_cli_test.sh).
std::string regressions_dir() {
  const char* other = std::getenv("MANIFUZZ_REGRESSIONS_DIR");
  return other && *other ? other : test::corpus_path("regressions");
}

std::vector<std::string> regression_cases() {
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(regressions_dir()))
    if (entry.path().extension() == ".case") files.push_back(entry.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

class RegressionCase : public ::testing::TestWithParam<std::string> {};

std::string expected_tutorial_outcome(const CaseFile& c) {
  for (const std::string& line : c.extensions)
    if (const std::string key = "expect-tutorial "; line.rfind(key, 0) == 0) return line.substr(key.size());
  return {};
}

TEST_P(RegressionCase, BuiltinPassesAndTheTutorialMethodAnswersAsRecorded) {
  const CaseParse parsed = read_case_file(GetParam());
  ASSERT_TRUE(parsed.value) << parsed.error;
  std::string load_error;
  const auto builtin = open_session("builtin", 5, load_error);
  const props::CaseOutcome fixed = props::check_case(*parsed.value, *builtin, {{}, props::Level::strict});
  ASSERT_FALSE(fixed.invalid) << fixed.invalid_reason;
  EXPECT_FALSE(fixed.finding) << fixed.finding->name << ": " << fixed.finding->detail;
  std::string error;
  const auto tutorial_session = open_session(std::string(MANIFUZZ_PLUGIN_DIR) + "/libmanifuzz_tutorial.so", 5, error);
  ASSERT_TRUE(tutorial_session) << error;
  const props::CaseOutcome unfixed = props::check_case(*parsed.value, *tutorial_session, {{}, props::Level::strict});
  const std::string expected = expected_tutorial_outcome(*parsed.value);
  ASSERT_FALSE(expected.empty()) << "the case has no 'expect-tutorial' line";
  EXPECT_EQ(unfixed.finding ? unfixed.finding->name : "pass", expected);
}

INSTANTIATE_TEST_SUITE_P(Corpus, RegressionCase, ::testing::ValuesIn(regression_cases()),
                         [](const auto& info) {
                           std::string name = std::filesystem::path(info.param).stem().string();
                           for (char& c : name)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return name;
                         });

TEST(RegressionCorpus, HoldsTheFindings) { EXPECT_GE(regression_cases().size(), 4u); }

// corpus/open: findings not fixed yet (FINDINGS.md, "Open"). Each still
// fails as its `expect-builtin` line says; when a fix makes one pass, this
// test fails until the case moves to corpus/regressions with an
// `expect-tutorial` line. The folder may hold none (F31 left it so).
std::vector<std::string> open_cases() {
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(test::corpus_path("open")))
    if (entry.path().extension() == ".case") files.push_back(entry.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

// A harness finding still open names the correct variant it fires on
// (`expect-variant <variant> <check>`, a plugin of tests/mutants): the
// harness must still flag it as recorded until the check is fixed.
TEST(OpenFindings, EachStillFailsAsRecorded) {
  std::string error;
  const auto builtin = open_session("builtin", 5, error);
  for (const std::string& file : open_cases()) {
    const CaseParse parsed = read_case_file(file);
    ASSERT_TRUE(parsed.value) << parsed.error;
    std::string expected, variant;
    for (const std::string& line : parsed.value->extensions) {
      if (line.rfind("expect-builtin ", 0) == 0) expected = line.substr(15);
      if (line.rfind("expect-variant ", 0) == 0) {
        std::istringstream words(line.substr(15));
        words >> variant >> expected;
      }
    }
    ASSERT_FALSE(expected.empty()) << file << " has no 'expect-builtin' or 'expect-variant' line";
    std::unique_ptr<GeneratorSession> variant_session;
    if (!variant.empty()) {
      const std::string plugin = std::string(MANIFUZZ_PLUGIN_DIR) + "/libmfz_mutant_" + variant + ".so";
      if (!std::filesystem::exists(plugin)) continue;  // a build without the variants (sanitize)
      variant_session = open_session(plugin, 5, error);
      ASSERT_TRUE(variant_session) << error;
    }
    const props::CaseOutcome o = props::check_case(*parsed.value, variant_session ? *variant_session : *builtin);
    EXPECT_EQ(o.finding ? o.finding->name : "pass", expected) << file;
  }
}

}  // namespace
}  // namespace mfz

// manifuzz fuzz --generator G [--seconds T] [--jobs J] [--corpus DIR] [--out DIR] [--strict]
// libFuzzer's manifold_fuzzer in fork mode on J cores (props/fuzz_campaign.h).
// The fuzzer program comes with the clang build (beside this manifuzz) or
// is named by MANIFUZZ_FUZZER.
#include <cstdlib>
#include <iostream>
#include <thread>

#include "cli/arguments.h"
#include "cli/program_files.h"
#include "harness/junit_report.h"
#include "fuzz_campaign.h"

namespace mfz::cli {
namespace {

constexpr const char* kUsage =
    "usage: manifuzz fuzz --generator G [--seconds T] [--jobs J] [--corpus DIR] [--out DIR] [--strict] [--profile P]";

int fail(const std::string& why) {
  std::cerr << "manifuzz fuzz: " << why << "\n";
  return kExitInputError;
}

std::string fuzzer_program() {
  if (const char* named = std::getenv("MANIFUZZ_FUZZER"); named && *named) return named;
  return beside_this_program({"../fuzz/manifold_fuzzer", "manifold_fuzzer", "../lib/manifuzz/manifold_fuzzer"});
}

}  // namespace

int fuzz_command(const std::vector<std::string>& words) {
  std::string error;
  const auto args = parse_arguments(
      words, {"--generator", "--seconds", "--jobs", "--corpus", "--out", "--call-timeout", "--minimise-seconds", "--profile", "--junit", "--confirm-with"},
      {"--strict", "--quiet"}, error);
  if (!args) return fail(error + " (" + kUsage + ")");
  if (!args->positional.empty()) return fail("unexpected argument " + mfz::quoted(args->positional[0]) + " (" + kUsage + ")");
  props::FuzzOptions options;
  options.generator = resolve_generator(args->get("--generator", "builtin"));
  options.corpus_dir = args->get("--corpus", options.corpus_dir);
  options.out_dir = args->get("--out", options.out_dir);
  if (options.corpus_dir.empty()) return fail("--corpus needs a folder name");
  if (args->options.count("--seconds")) {
    options.seconds = parse_seconds(args->get("--seconds", ""));
    if (!options.seconds || *options.seconds < 1) return fail("--seconds takes a number >= 1");
  }
  if (args->options.count("--minimise-seconds")) {
    const auto seconds = parse_seconds(args->get("--minimise-seconds", ""));
    if (!seconds) return fail("--minimise-seconds takes a number >= 0");
    options.minimise_seconds = *seconds;
  }
  const long long cores = std::max(1u, std::thread::hardware_concurrency());
  const auto jobs = parse_count(args->get("--jobs", "1"), 1, 4 * cores);
  if (!jobs) return fail("--jobs takes a whole number from 1 to " + std::to_string(4 * cores));
  options.jobs = static_cast<int>(*jobs);
  const auto timeout = call_timeout(*args, error);
  if (!timeout) return fail(error);
  options.call_timeout = *timeout;
  if (args->has("--strict")) options.level = props::Level::strict;
  if (args->has("--quiet")) options.progress_every = 0;
  options.profile_override = profile_override(*args);
  if (args->options.count("--confirm-with")) options.confirm_with = resolve_generator(args->get("--confirm-with", ""));
  options.fuzzer = fuzzer_program();
  if (options.fuzzer.empty())
    return fail("no manifold_fuzzer beside this manifuzz: fuzzing needs the clang build (cmake --preset clang; "
                "then build/clang/src/manifuzz fuzz), or MANIFUZZ_FUZZER naming the program");
  const std::string junit = args->get("--junit", "");
  if (args->options.count("--junit") && !junit_writable(junit, error)) return fail(error);
  const auto result = props::run_fuzz(options, std::cerr, std::cout, error);
  if (!result) return fail(error);
  if (!junit.empty()) {
    // One test case for the campaign, and one per distinct finding.
    const std::string classname = "manifuzz.fuzz." + args->get("--generator", "builtin");
    std::vector<JunitCase> cases = {{classname, "campaign", result->seconds}};
    if (!result->findings.empty()) cases[0].failure_message = std::to_string(result->findings.size()) + " findings";
    for (const props::FuzzFinding& f : result->findings)
      cases.push_back({classname, f.name + " (" + f.kind + ")", f.after_seconds, false, f.name + " after " +
                       std::to_string(static_cast<long long>(f.after_seconds)) + " s", f.case_path});
    if (!write_junit(junit, "manifuzz fuzz", cases, result->seconds, error)) return fail(error);
  }
  if (!result->findings.empty()) return kExitViolation;
  return result->interrupted ? kExitInterrupted : kExitClean;
}

}  // namespace mfz::cli

// manifuzz check --generator G [--cases N] [--seed S] [--seconds T] [--out DIR]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <random>

#include "check_driver.h"
#include "cli/arguments.h"

namespace mfz::cli {

/// Without --cases or --seconds the check runs this many cases: the main job's budget.
constexpr long long kDefaultCases = 20000;


int check_command(const std::vector<std::string>& words) {
  std::string error;
  const auto args = parse_arguments(
      words, {"--generator", "--cases", "--seed", "--seconds", "--out", "--call-timeout", "--only"}, {"--quiet", "--strict"}, error);
  const auto usage = [](const std::string& why) {
    std::cerr << "manifuzz check: " << why
              << " (usage: manifuzz check --generator G [--cases N] [--seed S] [--seconds T] [--out DIR] [--strict])\n";
    return kExitInputError;
  };
  if (!args) return usage(error);
  if (!args->positional.empty()) return usage("unexpected argument '" + args->positional[0] + "'");
  props::CheckOptions options;
  options.generator = args->get("--generator", "builtin");
  options.out_dir = args->get("--out", "failures");
  if (args->options.count("--cases")) {
    options.cases = parse_count(args->get("--cases", ""), 1, 1LL << 50);
    if (!options.cases) return usage("--cases takes a whole number >= 1");
  }
  if (args->options.count("--seconds")) {
    options.seconds = parse_seconds(args->get("--seconds", ""));
    if (!options.seconds) return usage("--seconds takes a number >= 0");
  }
  if (!options.cases && !options.seconds) options.cases = kDefaultCases;
  if (args->options.count("--seed")) {
    const auto seed = parse_count(args->get("--seed", ""), 0, (1LL << 62));
    if (!seed) return usage("--seed takes a whole number >= 0");
    options.seed = static_cast<uint64_t>(*seed);
  } else {
    options.seed = std::random_device{}() % 1000000000;
  }
  if (const auto timeout = call_timeout(*args, error)) options.call_timeout = *timeout;
  else return usage(error);
  if (args->options.count("--only")) {
    // A misspelt name would check nothing and pass: refuse it.
    const std::string only = args->get("--only", "");
    const auto& invariants = invariant_names();
    const auto& relations = props::relation_names();
    if (std::find(invariants.begin(), invariants.end(), only) == invariants.end() &&
        std::find(relations.begin(), relations.end(), only) == relations.end())
      return usage("--only takes an invariant or relation name, not '" + only + "'");
    options.selection.names.insert(only);
  }
  if (args->has("--quiet")) options.progress_every = 0;
  if (args->has("--strict")) options.selection.level = props::Level::strict;
  const auto result = props::run_check(options, std::cerr, error);
  if (!result) {
    std::cerr << "manifuzz check: " << error << "\n";
    return kExitInputError;
  }
  if (!result->finding) return result->interrupted ? kExitInterrupted : kExitClean;
  std::cerr << "minimised case (" << result->shrink_steps << " shrink steps):\n" << result->minimised_text;
  std::printf("VIOLATION %s %s\n", result->finding->name.c_str(), result->case_path.c_str());
  return kExitViolation;
}

}  // namespace mfz::cli

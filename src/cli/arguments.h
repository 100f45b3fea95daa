#pragma once
/// \file
/// The command line's small argument parser: `--name value`, `--flag`, and
/// positional words, with a one-line error for anything else.
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "case_property.h"

namespace mfz::cli {

/// Exit statuses of the contract.
inline constexpr int kExitClean = 0;
inline constexpr int kExitViolation = 1;
inline constexpr int kExitInputError = 2;
/// Stopped by Ctrl-C or SIGTERM before the budget, nothing found: the
/// shell's convention (128 + SIGINT), so a script never reads it as a pass.
inline constexpr int kExitInterrupted = 130;

struct Arguments {
  std::map<std::string, std::string> options;  ///< "--seed" -> "7"
  std::set<std::string> flags;                 ///< "--json"
  std::vector<std::string> positional;

  std::string get(const std::string& name, const std::string& fallback) const;
  bool has(const std::string& flag) const { return flags.count(flag) > 0; }
};

/// Parses `words`; options in `valued` take a value, those in `switches` none.
/// On error: nullopt and a one-line reason.
std::optional<Arguments> parse_arguments(const std::vector<std::string>& words, const std::set<std::string>& valued,
                                         const std::set<std::string>& switches, std::string& error);

/// A whole number in [low, high], or nullopt.
std::optional<long long> parse_count(const std::string& text, long long low, long long high);
/// The per-call limit for a plugin: --call-timeout if given, else 5 s;
/// nullopt and a one-line `error` for a value below kShortestCallTimeout.
std::optional<double> call_timeout(const Arguments& args, std::string& error);
/// The shortest per-call limit --call-timeout accepts (seconds): below it a
/// correct generator's ordinary call (a 64-gon, a loaded machine) reads as a hang.
inline constexpr double kShortestCallTimeout = 0.05;

/// Sets the selection's profile: the generator's declaration, with the keys
/// of --profile replacing its own (and then no case file's `profile` line
/// replaces it). false and a one-line `error` when either cannot be read.
bool apply_profile(const Arguments& args, const GeneratorSession& session, props::Selection& selection,
                   std::string& error);
/// --profile's text, when given.
std::optional<std::string> profile_override(const Arguments& args);

/// A run's budget and stream: --cases N, --seconds T (without either,
/// `default_cases`), --seed S (without it, one of the run's own choosing).
struct RunBudget {
  std::optional<long long> cases;
  std::optional<double> seconds;
  uint64_t seed = 0;
};
/// nullopt and a one-line `error` for a value out of range.
std::optional<RunBudget> run_budget(const Arguments& args, long long default_cases, std::string& error);

/// Whether `path` can be written (--junit is tried before a run, so that a
/// report is never lost to it after the run); false and a one-line `error`.
bool junit_writable(const std::string& path, std::string& error);

/// A finite number >= 0, or nullopt.
std::optional<double> parse_seconds(const std::string& text);

int replay_command(const std::vector<std::string>& words);
int explain_command(const std::vector<std::string>& words);
int check_command(const std::vector<std::string>& words);
int promote_command(const std::vector<std::string>& words);
int fuzz_command(const std::vector<std::string>& words);
int diff_command(const std::vector<std::string>& words);
int render_command(const std::vector<std::string>& words);

}  // namespace mfz::cli

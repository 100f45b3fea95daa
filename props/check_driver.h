#pragma once
/// \file
/// `manifuzz check`: draws cases from the families, runs the case property
/// against a generator, shrinks the first finding to a small case, writes it,
/// and keeps statistics of what the run covered.
#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "case_property.h"
#include "harness/run_statistics.h"

namespace mfz::props {

struct CheckOptions {
  std::string generator = "builtin";
  std::optional<long long> cases;    ///< stop after this many valid cases
  std::optional<double> seconds;     ///< or after this long
  uint64_t seed = 0;
  std::string out_dir = "failures";  ///< where minimised cases are written
  double call_timeout = 5;           ///< per generator call, seconds (plugins)
  double progress_every = 5;         ///< seconds between progress lines; 0: none
  Selection selection;
  /// --profile: keys that replace the generator's declared profile.
  std::optional<std::string> profile_override;
  /// --family: the hull families drawn (empty: every family).
  std::vector<std::string> hull_families;
  /// --confirm-with: the same logic in double (a float peer's double build).
  /// A finding it does not make too is rounding, not logic: counted, logged,
  /// and the run goes on.
  std::optional<std::string> confirm_with;
};

/// What a run found. `finding` is empty when nothing was.
struct CheckResult {
  long long cases = 0, invalid = 0, oracle_disagreements = 0;
  /// Findings the --confirm-with generator did not make: rounding only.
  long long rounding_only = 0;
  double seconds = 0;
  std::optional<Finding> finding;
  long long found_at_case = -1;
  std::string case_path;     ///< the minimised case file
  std::string minimised_text;
  int shrink_steps = 0;
  bool interrupted = false;  ///< stopped by SIGINT or SIGTERM
  /// What the run covered: counts per category, each check's margins, and
  /// the cases over time (the summary and --report).
  RunStatistics statistics;
};

/// Runs the check; progress and statistics go to `log`. Returns nullopt and a
/// one-line `error` when the generator cannot be loaded or the out folder
/// cannot be written.
std::optional<CheckResult> run_check(const CheckOptions& options, std::ostream& log, std::string& error);

}  // namespace mfz::props

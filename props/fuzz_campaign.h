#pragma once
/// \file
/// `manifuzz fuzz`: a campaign of libFuzzer in fork mode on J cores, driven
/// from outside. libFuzzer finds; the campaign keeps the user's corpus whole
/// (new inputs are copied in through a temporary name, and only once their
/// bytes match their name), reports progress, and turns each distinct
/// finding into a minimised case file while the fuzzer goes on.
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "case_property.h"
#include "fuzz_input.h"
#include "harness/run_statistics.h"

namespace mfz::props {

struct FuzzOptions {
  std::string generator = "builtin";
  std::string fuzzer;                ///< the manifold_fuzzer program
  std::optional<double> seconds;     ///< of the whole run, minimising included; none: until Ctrl-C
  int jobs = 1;
  /// --max-points: the most points either hull of an input has (4 to
  /// kFuzzMaxPoints), libFuzzer's -max_len. Hulls of at most 8 points run
  /// about three times as many executions a second as the inputs of 30 to
  /// 64 points a campaign grows towards, and reached F62 and a hull
  /// builder's overflow within 30 s each, which campaigns of the full size
  /// had not (stop 68).
  int max_points = kFuzzMaxPoints;
  /// --max-points A..B: a campaign that grows its hulls, in phases of equal
  /// time on the one corpus, at most A points, then twice as many, up to
  /// max_points (B); 0 for one phase at max_points. Needs `seconds`.
  int least_points = 0;
  std::string corpus_dir = "fuzz-corpus";
  std::string out_dir = "failures";
  double call_timeout = 5;
  double progress_every = 5;         ///< seconds between progress lines
  double minimise_seconds = 30;      ///< per distinct finding (libFuzzer's, then the case shrinker)
  Level level = Level::contract;
  /// --profile: keys that replace the generator's declared profile. The
  /// profile in force goes to the fuzzer whole, as MANIFUZZ_PROFILE.
  std::optional<std::string> profile_override;
  Profile profile = {};  ///< the profile in force, set by run_fuzz
  /// --confirm-with: the same logic in double; a finding it does not make
  /// too is rounding, counted and not written.
  std::optional<std::string> confirm_with;
};

/// One distinct finding: a check and the kind of case it failed on.
struct FuzzFinding {
  std::string name;       ///< the check, or crash, hang, out-of-memory
  std::string kind;       ///< the contact kind (face-face, edge-edge, ...), or the artefact's kind
  std::string case_path;  ///< the minimised case file
  int artefacts = 0;      ///< how many of libFuzzer's artefacts showed it
  double after_seconds = 0;
  double error = 0, tolerance = 0;
};

struct FuzzResult {
  long long execs = 0;
  int coverage = 0, features = 0;
  int corpus_inputs = 0, corpus_added = 0;
  double seconds = 0;
  std::vector<FuzzFinding> findings;
  long long rounding_only = 0;  ///< distinct findings --confirm-with did not make
  bool interrupted = false;
  /// Executions and coverage over time (about a sample a second).
  RunStatistics statistics;
};

/// Runs the campaign; progress and the summary go to `log`, one
/// `VIOLATION <name> <file>` line per distinct finding to `findings_out` as
/// it is written. nullopt and a one-line `error` when it cannot start.
std::optional<FuzzResult> run_fuzz(const FuzzOptions& options, std::ostream& log, std::ostream& findings_out,
                                   std::string& error);

}  // namespace mfz::props

#pragma once
/// \file
/// `manifuzz diff`: the same cases to two generators, and where their
/// answers differ by more than both profiles allow: whether they collide,
/// the depth, the normal, the contact region (the contacts' hulls on the
/// contact plane). For each disagreement, which of the two the oracles side
/// with; for each kind, the first case minimised; and a summary table.
#include <cstdint>
#include <iosfwd>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "case/case_file.h"
#include "harness/generator_session.h"
#include "harness/profile.h"
#include "harness/run_statistics.h"

namespace mfz::props {

/// One generator of the pair, with the profile it is held to.
struct DiffSide {
  GeneratorSession* session = nullptr;
  Profile profile;
};

/// Where the two answers differ on one case. `kind` is colliding, depth,
/// normal or contact-region (or crash, hang, refused for a generator that
/// gave no answer); `sides_with` is first, second, both or neither: whose
/// answer the oracles confirm.
struct Disagreement {
  std::string kind;
  std::string detail;
  std::string sides_with;
};

/// The four kinds, in the order they are looked for (a case reports the first).
const std::vector<std::string>& disagreement_kinds();

/// Compares the two answers on `c`. nullopt when they agree within both
/// profiles; a disagreement whose `sides_with` is both when they differ
/// where the oracles confirm each (a tie, which a run does not count); `invalid` is set (and nullopt returned) for a case that is no
/// valid input, or that one of the profiles does not resolve.
/// With `statistics`, the case's contact kind and both answers' margins
/// (each check under "first: " and "second: ") are counted there.
std::optional<Disagreement> compare_generators(const CaseFile& c, DiffSide& first, DiffSide& second, bool& invalid,
                                               RunStatistics* statistics = nullptr);

struct DiffOptions {
  std::string generator, against;
  std::optional<long long> cases;
  std::optional<double> seconds;
  uint64_t seed = 0;
  std::string out_dir = "failures";
  double call_timeout = 5;
  double progress_every = 5;
  std::vector<std::string> hull_families;
  /// --profile and --against-profile: keys over each generator's declared profile.
  std::optional<std::string> profile_override, against_profile_override;
};

/// What one kind of disagreement amounted to over the run.
struct KindTally {
  long long cases = 0;
  std::map<std::string, long long> sides_with;  ///< first, second, both, neither
  std::string example_path;                     ///< the minimised case file
  std::string example_detail;
};

struct DiffResult {
  std::string first_name, second_name;
  Profile first_profile, second_profile;
  long long cases = 0, invalid = 0, agreeing = 0;
  /// Answers that differ where the oracles confirm both (a tie): not disagreements.
  long long ties = 0;
  double seconds = 0;
  std::map<std::string, KindTally> kinds;
  bool interrupted = false;
  /// Families, placements and outcomes counted, and cases over time.
  RunStatistics statistics;
};

/// Runs the differential campaign. nullopt and a one-line `error` when a
/// generator cannot be loaded or the out folder cannot be written.
std::optional<DiffResult> run_diff(const DiffOptions& options, std::ostream& log, std::string& error);

/// The summary table of a run.
void print_diff_summary(const DiffResult& result, std::ostream& out);

}  // namespace mfz::props

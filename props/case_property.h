#pragma once
/// \file
/// The one pipeline every case goes through, whichever command asks (`check`,
/// `replay`, `explain`, the regression test, the properties): call the
/// generator (a plugin in its worker, with the call limit), consult the
/// oracles, check every invariant, then the metamorphic relations, or only
/// the one a relation finding's case file names, with its recorded
/// parameters, so that the finding replays exactly.
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "case/case_file.h"
#include "case/scene.h"
#include "harness/generator_session.h"
#include "harness/invariants.h"

namespace mfz::props {

/// What went wrong: an invariant's or relation's name, or crash, hang,
/// refused; and one line of detail.
struct Finding {
  std::string name;
  std::string detail;
  /// For a relation finding: the case file line that reproduces it
  /// (`relation NAME numbers...`); empty otherwise.
  std::string relation_line = {};
  /// A failed check's error and tolerance (x L); 0 where none is measured.
  double error = 0, tolerance = 0;
};

/// What a run covered, for the statistics.
struct CaseTags {
  std::string contact_kind;  ///< separated, face-face, edge-face, vertex-face, edge-edge, no-contacts
  int contact_count = 0;
  bool touching = false;
  bool tie = false;
  double depth_over_l = 0;  ///< the exact depth in units of L (negative: the gap)
};

/// What a case covered: its contact kind (from the oracles and the
/// manifold), whether it touches or ties, its exact depth.
CaseTags tags_of(const Scene& s, const OracleAnswers& o, const mfz_manifold& m);

/// How much a relation asks (docs/contract.md, "Ties"): `contract` compares
/// what the geometry determines; `strict` asks for one canonical answer even
/// in a tie, and adds the triangulated-faces relation.
enum class Level { contract, strict };

/// The name a relation's run reports when SIGINT or SIGTERM cut it short;
/// check_case turns it into `interrupted`, never a finding.
inline constexpr const char* kInterrupted = "interrupted";

/// A relation's transformed run (the swapped, moved, scaled or renumbered
/// case and the generator's answer to it), for a picture of its finding.
struct TransformedRun {
  std::string relation;
  Scene scene;
  std::optional<mfz_manifold> manifold;  ///< empty: the call crashed, hung or refused
};

struct CaseOutcome {
  bool invalid = false;  ///< not a valid input (degenerate hull): discarded, not a finding
  bool interrupted = false;  ///< SIGINT or SIGTERM cut the case short: no verdict
  std::string invalid_reason;
  std::optional<Finding> finding;
  CaseTags tags;
  /// The original call, when it returned: the manifold and its verdict.
  std::optional<mfz_manifold> manifold;
  std::optional<Verdict> verdict;
  double scale = 0;  ///< L
  Profile profile;   ///< the profile in force (the selection's, or the case file's line)
  /// A relation finding's transformed run, when Selection::keep_transformed_run.
  std::optional<TransformedRun> transformed;
};

/// Which checks count (empty: all invariants and relations), and how strictly.
struct Selection {
  std::set<std::string> names;
  Level level = Level::contract;
  /// What the generator declares (or --profile says): every check relaxes
  /// what it names, and only that.
  Profile profile = {};
  /// The profile came from --profile: a case file's `profile` line does not
  /// replace it.
  bool profile_from_command_line = false;
  /// Keep a relation finding's transformed run in the outcome (pictures);
  /// off in the runs, where it would copy hulls on every relation.
  bool keep_transformed_run = false;
  /// Describe every passing check in the outcome's verdict (replay prints
  /// them); off in the runs, which read a failure's detail only.
  bool pass_details = false;
  bool wants(const std::string& name) const { return names.empty() || names.count(name) > 0; }
};

/// The metamorphic relations' names.
const std::vector<std::string>& relation_names();

/// The one pipeline. A case file's `level strict` line raises the level; its
/// `relation` line restricts the relations to that one, with its parameters;
/// its `profile` line (the profile a finding was made under) replaces the
/// selection's, unless that came from --profile.
CaseOutcome check_case(const CaseFile& c, GeneratorSession& generator, const Selection& selection = {});

/// The extension lines that make a finding replay: the relation line, and
/// `level strict` when the finding was made at the strict level, and the
/// `profile` line of the profile in force, if any.
std::vector<std::string> replay_lines(const Finding& f, const Selection& selection);

}  // namespace mfz::props

#pragma once
/// \file
/// The contract's invariants, each a named check that measures its error and
/// compares it with its tolerance. Errors and tolerances are reported in units
/// of L (unit-normal: dimensionless), so a margin reads the same at any scale.
#include <optional>
#include <string>
#include <vector>

#include "manifuzz/abi.h"
#include "oracles/oracle_answers.h"
#include "case/scene.h"
#include "harness/profile.h"

namespace mfz {

enum class CheckStatus { pass, fail, skipped, oracle_disagreement };
const char* status_name(CheckStatus status);

struct InvariantCheck {
  std::string name;  ///< the contract's name, e.g. "depth-exact"
  CheckStatus status = CheckStatus::pass;
  double error = 0;      ///< measured, in units of L
  double tolerance = 0;  ///< in units of L
  std::string detail;    ///< one line: what was measured, or why skipped
  /// The part of `tolerance` the generator's profile added (x L; 0 without
  /// one). A check leaves it negative for the default: the precision's
  /// rounding, which every length tolerance holds once.
  double profile_share = -1;
};

/// Apart in truth, but by no more than the profile's margin (x L): a margin
/// engine may report the case colliding, with the gap as its penetration.
bool separated_within_margin(const Scene& scene, const OracleAnswers& oracles, const Profile& profile);

/// The contact a check's detail names ("... (contact 3)"), or -1: the point a
/// picture of the finding circles.
int contact_named_in(const std::string& detail);

/// The invariant names, in the contract's order.
const std::vector<std::string>& invariant_names();

struct Verdict {
  int32_t generator_status = 0;  ///< non-zero: the generator refused
  std::vector<InvariantCheck> checks;
  bool refused() const { return generator_status != 0; }
  /// The first failed check, or nullptr.
  const InvariantCheck* first_violation() const;
  bool has_oracle_disagreement() const;
};

/// Checks `manifold` (what the generator returned with `status`) against
/// every invariant, relaxed as `profile` says (its precision must already be
/// in `scene`). A refusal is reported by `refused()`, and its checks are
/// skipped. A passing check describes itself only when its detail is
/// `written` (explain and replay print every check; the property suite
/// reads a failure's detail only).
enum class PassDetails { written, left_out };
Verdict check_manifold(const Scene& scene, const OracleAnswers& oracles, int32_t status, const mfz_manifold& manifold,
                       const Profile& profile = {}, PassDetails pass_details = PassDetails::written);

/// The invariants a relation's transformed run must pass as well: every check
/// that needs no oracle of its own, against the original case's oracles (a
/// motion, a renumbering or a swap keeps the exact depth; a scale multiplies
/// it by `depth_factor`). Returns the first check it fails, in the
/// contract's order, or nothing: a relation reports that one only, so the
/// checks after it are not run and the passing ones are not kept (a kept
/// verdict named each of its checks, five of them on the heap, on each of a
/// case's five or six transformed runs).
std::optional<InvariantCheck> check_transformed_manifold(const Scene& scene, const OracleAnswers& original,
                                                         double depth_factor, const mfz_manifold& m,
                                                         const Profile& profile = {});

}  // namespace mfz

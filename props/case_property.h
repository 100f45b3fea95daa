#pragma once
/// \file
/// The property every case must satisfy: the generator's manifold passes every
/// invariant, and every metamorphic relation holds. One function, called by
/// the RapidCheck properties, by `manifuzz check` and by the fuzz target.
#include <optional>
#include <set>
#include <string>

#include "case/case_file.h"
#include "harness/generator_session.h"
#include "harness/invariants.h"

namespace mfz::props {

/// What went wrong: an invariant's or relation's name, or crash, hang,
/// refused; and one line of detail.
struct Finding {
  std::string name;
  std::string detail;
};

/// What a run covered, for the statistics.
struct CaseTags {
  std::string contact_kind;  ///< separated, face-face, edge-face, vertex-face, edge-edge, no-contacts
  int contact_count = 0;
  bool touching = false;
  bool tie = false;
};

struct CaseOutcome {
  bool invalid = false;  ///< not a valid input (degenerate hull): discarded, not a finding
  std::string invalid_reason;
  std::optional<Finding> finding;
  CaseTags tags;
};

/// Which checks count; empty means all invariants and all relations.
struct Selection {
  std::set<std::string> names;
  bool wants(const std::string& name) const { return names.empty() || names.count(name) > 0; }
};

/// The metamorphic relations' names.
const std::vector<std::string>& relation_names();

CaseOutcome check_case(const CaseFile& c, GeneratorSession& generator, const Selection& selection = {});

}  // namespace mfz::props

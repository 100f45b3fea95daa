#pragma once
/// \file
/// One case through one generator: build the scene, call the generator through
/// the ABI, consult the oracles, check every invariant.
#include <optional>
#include <string>

#include "harness/generator.h"
#include "harness/invariants.h"

namespace mfz {

struct CaseRun {
  Scene scene;
  mfz_manifold manifold;
  OracleAnswers oracles;
  Verdict verdict;
};

/// nullopt and a one-line reason when the case is not a valid input
/// (a degenerate hull, a non-finite pose).
std::optional<CaseRun> run_case(const CaseFile& c, const Generator& generator, std::string& error);

}  // namespace mfz

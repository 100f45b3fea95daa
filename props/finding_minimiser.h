#pragma once
/// \file
/// Minimising a finding's case file, for every command that has one (`check`
/// after RapidCheck's shrink tree, `fuzz` after libFuzzer's minimiser,
/// `promote`): the case shrinker's steps, each kept only when the same check
/// still fails by a margin of the same order.
#include <functional>

#include "case_property.h"

namespace mfz::props {

/// True when `candidate` shows the same failure as `original`: the same
/// check, failing by at least a tenth of the original's error (when it has
/// one), so that shrinking never trades a large error for a rounding-sized one.
bool same_failure(const Finding& original, const Finding& candidate);

struct Minimised {
  CaseFile file;
  Finding finding;  ///< as the smallest case fails
  int steps = 0;
};

/// Shrinks `failing`, which fails with `original`, for at most `seconds`, or
/// until `stop()` says so.
Minimised minimise_finding(const CaseFile& failing, const Finding& original, GeneratorSession& generator,
                           const Selection& selection, double seconds, const std::function<bool()>& stop = {});

}  // namespace mfz::props

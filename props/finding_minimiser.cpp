#include "finding_minimiser.h"

#include "case_shrinker.h"

namespace mfz::props {
namespace {

/// Shrinking keeps a candidate whose error is at least this fraction of the
/// original's (the same order of magnitude).
constexpr double kSameOrder = 0.1;

}  // namespace

// A shrink that turned a 1.77 L error into a rounding-sized one had found a
// different, lesser failure: the minimised case must fail by the same order.
bool same_failure(const Finding& original, const Finding& candidate) {
  if (candidate.name != original.name) return false;
  return !(original.error > 0) || candidate.error >= kSameOrder * original.error;
}

Minimised minimise_finding(const CaseFile& failing, const Finding& original, GeneratorSession& generator,
                           const Selection& selection, double seconds, const std::function<bool()>& stop) {
  Minimised out{failing, original, 0};
  out.steps = shrink_case_file(
      out.file,
      [&](const CaseFile& candidate) {
        if (stop && stop()) return false;
        const CaseOutcome o = check_case(candidate, generator, selection);
        if (o.invalid || !o.finding || !same_failure(original, *o.finding)) return false;
        out.finding = *o.finding;
        return true;
      },
      seconds);
  return out;
}

}  // namespace mfz::props

#pragma once
/// \file
/// The one place that asks every oracle about a case: the brute-force SAT's
/// ranked axes, the exact depth, libccd's GJK and EPA, and what follows from
/// them (touching, tied axes). The invariants compare a manifold with these
/// answers; none of them uses the generator under test.
#include <vector>

#include "case/scene.h"
#include "oracles/brute_force_sat.h"
#include "oracles/exact_depth.h"
#include "oracles/libccd_oracle.h"

namespace mfz {

/// Everything the checks compare a manifold against, computed once per case.
struct OracleAnswers {
  ExactDepth exact;
  std::vector<RankedAxis> sat_axes;  ///< brute-force SAT, best first
  LibccdAnswer ccd;
  bool touching = false;  ///< |exact depth or gap| within tol::kTouching
  bool axis_tie = false;  ///< two distinct minimal axes (tolerances.h kTie)
};

OracleAnswers consult_oracles(const Scene& scene);

}  // namespace mfz

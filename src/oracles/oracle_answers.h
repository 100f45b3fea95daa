#pragma once
/// \file
/// The one place that asks every oracle about a case: the brute-force SAT's
/// ranked axes, the exact depth, libccd's GJK and EPA, and what follows from
/// them (touching, tied axes). The invariants compare a manifold with these
/// answers; none of them uses the generator under test.
#include <cmath>
#include <vector>

#include "case/scene.h"
#include "oracles/brute_force_sat.h"
#include "oracles/exact_depth.h"
#include "oracles/libccd_oracle.h"
#include "oracles/ties.h"

namespace mfz {

/// Everything the checks compare a manifold against, computed once per case.
struct OracleAnswers {
  ExactDepth exact;
  std::vector<RankedAxis> sat_axes;  ///< brute-force SAT, best first
  /// least_reverse_overlap(sat_axes) (brute_force_sat.h); NaN until
  /// consult_oracles finds it, which no check takes for a bound.
  double least_reverse_overlap = NAN;
  LibccdAnswer ccd;
  bool touching = false;  ///< |exact depth or gap| within tol::kTouching
  bool axis_tie = false;  ///< two distinct minimal axes (tolerances.h kTie)
  /// The contract's ties, classified (ties.h).
  Ties ties;
  /// A face axis is among the minimal candidates along the best direction:
  /// the hulls first touch at a face, and the contact region is well defined.
  bool face_contact = false;
};

OracleAnswers consult_oracles(const Scene& scene);

}  // namespace mfz

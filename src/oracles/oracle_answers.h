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

/// The least axis's own edges, where it is an edge pair: the frame's
/// rounding turns their cross product by that rounding over the shorter
/// edge and the sine of their angle, and so moves a contact on them and the
/// overlap along the axis (invariants.h, depth-exact; the relations).
struct LeastEdgePair {
  bool present = false;
  /// A face axis lies along it too: the direction is the face's, known to
  /// the rounding of its own plane, and the depth has no room.
  bool along_a_face = false;
  double sine = 0;          ///< of the angle between the two edges
  double shorter_edge = 0;  ///< the shorter one's length
  /// sine x shorter edge / L: the same in every frame a relation makes.
  double conditioning = INFINITY;
  /// How far the overlap along the axis may move with the frame's `rounding`:
  /// the axis turns by rounding / (shorter edge x sine), and the overlap by
  /// that turn times the hulls' reach along it, 2 L at most.
  double depth_room(double rounding) const { return present && !along_a_face ? 2 * rounding / conditioning : 0; }
};

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
  LeastEdgePair least_edge_pair;
  /// A face axis is among the minimal candidates along the best direction:
  /// the hulls first touch at a face, and the contact region is well defined.
  bool face_contact = false;
};

OracleAnswers consult_oracles(const Scene& scene);

}  // namespace mfz

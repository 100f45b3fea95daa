#pragma once
/// \file
/// The exact oracle of depth-exact and agrees-with-gjk: inside, the least
/// overlap over every candidate axis (brute_force_sat.h says why that is the
/// distance from the origin to the boundary of A - B); outside, the hulls'
/// own distance (hull_gap.h). Neither uses the generator's SAT.
#include <vector>

#include "oracles/brute_force_sat.h"
#include "case/scene.h"

namespace mfz {

/// The exact answer for the hulls as posed.
struct ExactDepth {
  bool colliding = false;  ///< origin inside A - B (on the boundary counts)
  /// Penetration depth when colliding, else minus the gap (distance between hulls).
  double signed_depth = 0;
  /// Colliding: the axis of least overlap, the direction to move B.
  /// Separated: the direction from the nearest point of A to the nearest of B.
  Vec3 normal = Vec3::UnitZ();
};

/// `ranked` is rank_sat_axes(scene).
ExactDepth exact_depth(const Scene& scene, const std::vector<RankedAxis>& ranked);

}  // namespace mfz

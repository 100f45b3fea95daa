#pragma once
/// \file
/// The exact oracle: the Minkowski difference A - B (the hull of every vertex
/// difference a - b), built with Qhull. The origin is inside it exactly when
/// the hulls overlap; its distance to the boundary is the exact penetration
/// depth (or the gap). Independent of any separating-axis code.
#include <optional>
#include <string>
#include <vector>

#include "vec.h"

namespace mfz {

struct MinkowskiFacet {
  Vec3 normal;  ///< outward unit
  double offset = 0;  ///< normal . x = offset on the facet
};

/// The exact answer for the hulls as posed.
struct ExactDepth {
  bool colliding = false;  ///< origin inside A - B (on the boundary counts)
  /// Penetration depth when colliding, else minus the gap (distance between hulls).
  double signed_depth = 0;
  /// Colliding: outward normal of the nearest facet, the direction to move B.
  /// Separated (from `exact_depth`): the direction from the nearest point of
  /// A to the nearest of B.
  Vec3 normal = Vec3::UnitZ();
};

class MinkowskiDifference {
 public:
  /// Hull of { a - b } (merged facets: only their planes are used); nullopt
  /// and a reason if Qhull fails.
  static std::optional<MinkowskiDifference> build(const std::vector<Vec3>& world_a, const std::vector<Vec3>& world_b,
                                                  std::string& error);
  /// How deep a point lies inside A - B: min over facets of offset - normal . t
  /// (positive inside, negative outside; outside it is a lower bound on the
  /// distance). Moving B by t leaves the hulls overlapping iff t is inside.
  double depth_of(const Vec3& t) const;
  /// Inside, the exact depth at the origin. Outside, colliding is false and
  /// signed_depth is minus the largest plane distance, a lower bound on the
  /// gap: `exact_depth` takes the gap itself from hull_gap.h.
  ExactDepth at_origin() const;
  const std::vector<MinkowskiFacet>& facets() const { return facets_; }

 private:
  std::vector<MinkowskiFacet> facets_;
};

}  // namespace mfz

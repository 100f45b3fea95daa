#pragma once
/// \file
/// The Minkowski difference A - B as the contract describes it: the hull of
/// every vertex difference a - b, built with Qhull. The origin is inside it
/// exactly when the hulls overlap; its distance to the boundary is the exact
/// penetration depth. Independent of any separating-axis code, and slow (a
/// hull of V_A x V_B points): the property suite takes the same number from
/// exact_depth.h, and a property checks the two agree; `explain` shows both.
#include <optional>
#include <string>
#include <vector>

#include "oracles/exact_depth.h"
#include "geometry/vec.h"

namespace mfz {

struct MinkowskiFacet {
  Vec3 normal;  ///< outward unit
  double offset = 0;  ///< normal . x = offset on the facet
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
  /// gap (hull_gap.h measures the gap itself).
  ExactDepth at_origin() const;
  const std::vector<MinkowskiFacet>& facets() const { return facets_; }

 private:
  std::vector<MinkowskiFacet> facets_;
};

}  // namespace mfz

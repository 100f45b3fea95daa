#pragma once
/// \file
/// A case made ready to check: both hulls built, poses normalised, the scale
/// L and the world-frame resolution M that every tolerance is relative to.
#include <optional>
#include <string>
#include <vector>

#include "case/case_file.h"
#include "geometry/hull.h"

namespace mfz {

struct Scene {
  Hull hull_a, hull_b;
  Pose pose_a, pose_b;  ///< orientations unit length
  double scale = 1;     ///< L: the larger hull diameter
  double world_extent = 0;  ///< M: the largest absolute world coordinate of a vertex
  double shortest_edge = 0;  ///< of either hull: directions taken from edges resolve to eps M / this
  double sharpest_corner = 1;  ///< sine of the smallest angle at a face corner of either hull
  /// The unit roundoff a generator profile declares (precision=float:
  /// 2^-23), or 0: the contract's double, already in the world's rounding.
  double precision_epsilon = 0;
  std::vector<Vec3> world_a, world_b;  ///< posed vertices

  /// A length tolerance: k * L plus the rounding (below).
  double length_tolerance(double k) const;
  /// The world frame's resolution (tolerances.h) at coordinates up to M +
  /// `extra_extent`, plus what the profile's precision adds.
  double rounding(double extra_extent = 0) const;
  /// What the profile's precision adds to every length tolerance: 64 of its
  /// ulps of the larger of M and L (a float engine rounds its own frame).
  double precision_rounding(double extra_extent = 0) const;
  /// The tolerance of a contact point's place: kPoint L, the world frame's
  /// resolution, and that resolution magnified at the sharpest face corner
  /// (tolerances.h, kSharpCornerCap).
  double point_tolerance() const;
  mfz_pose abi_pose_a() const { return pose_a.to_abi(); }
  mfz_pose abi_pose_b() const { return pose_b.to_abi(); }
};

struct SceneBuild {
  std::optional<Scene> scene;
  std::string error;  ///< one line, naming the hull at fault
};

/// Builds both hulls from the case's points and poses them; a degenerate
/// hull or a non-finite pose is an error.
SceneBuild make_scene(const CaseFile& c);

/// A scene of hulls already built (a relation's transformed case).
Scene posed_scene(Hull a, const Pose& pose_a, Hull b, const Pose& pose_b);

}  // namespace mfz

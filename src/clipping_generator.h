#pragma once
/// \file
/// The built-in contact-manifold generator: the seed's clipping method
/// (shared/seed/000_17999a06bffaa920.txt), with the project's conventions.
#include <string>
#include <vector>

#include "manifuzz/abi.h"
#include "sat.h"

namespace mfz {

/// What the generator did, step by step, for `manifuzz explain`. Filled only
/// when a trace is asked for; the hot path passes nullptr and allocates nothing.
struct ClipTrace {
  SatResult sat;
  int face_a = -1, face_b = -1;  ///< significant faces
  int support_a = -1, support_b = -1;  ///< the vertices they were chosen from
  bool flipped = false;          ///< true: B's face is the reference face
  struct Step {
    std::string what;
    std::vector<Vec3> polygon;
  };
  std::vector<Step> steps;       ///< the incident polygon after each clip
};

/// Fills `out` for hulls a and b at their poses (orientations unit length).
/// Returns 0, or 1 when it refuses: a face too large for its fixed buffers.
int32_t generate_clipping_manifold(const mfz_hull& a, const mfz_pose& pose_a, const mfz_hull& b,
                                   const mfz_pose& pose_b, mfz_manifold& out, ClipTrace* trace = nullptr);

/// The face of `hull` the seed calls significant for `direction`: of the faces
/// that contain the vertex furthest along `direction`, the one whose normal is
/// most parallel to it (first of equals). Sets `support` to that vertex.
int significant_face(const PosedHull& hull, const Vec3& direction, int& support);

}  // namespace mfz

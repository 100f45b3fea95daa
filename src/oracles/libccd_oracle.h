#pragma once
/// \file
/// libccd (GJK, EPA, MPR) as a second opinion. Per docs/contract.md it is called on
/// the case rescaled to L = 1 (its tolerances are absolute), with bounded
/// iterations and a bounded number of support points (EPA may otherwise
/// never end); its EPA depth is a lower bound, not the truth.
#include <vector>

#include "case/scene.h"

namespace mfz {

struct LibccdAnswer {
  bool gjk_intersecting = false;
  bool epa_ok = false;     ///< ccdGJKPenetration returned 0 and a direction, within the budget
  double epa_depth = 0;    ///< in the case's units
  Vec3 epa_direction = Vec3::UnitZ();  ///< unit; moving B along it separates
  bool mpr_ok = false;
  double mpr_depth = 0;
  Vec3 mpr_direction = Vec3::UnitZ();
};

/// GJK and EPA, and MPR when `with_mpr` (only `explain` shows MPR; no
/// invariant reads it).
LibccdAnswer ask_libccd(const Scene& scene, bool with_mpr = false);

/// GJK's verdict on the scene with B moved by `translation` (world units).
bool libccd_intersecting(const Scene& scene, const Vec3& translation);

}  // namespace mfz

#pragma once
// Single precision at the generator's boundary: the poses it reads and every
// number it writes are rounded to float, as an engine that keeps its
// transforms and results in float does. Errors are a few float ulps of the
// coordinates; the logic is the built-in's, in double.
#include "manifuzz/abi.h"

namespace mutant {

inline double to_float(double x) { return static_cast<float>(x); }
inline void round_to_float(mfz_vec3& v) { v = {to_float(v.x), to_float(v.y), to_float(v.z)}; }

inline void round_pose(mfz_pose& p) {
  round_to_float(p.position);
  p.orientation = {to_float(p.orientation.w), to_float(p.orientation.x), to_float(p.orientation.y),
                   to_float(p.orientation.z)};
}

inline void round_manifold(mfz_manifold& m) {
  round_to_float(m.normal);
  m.penetration = to_float(m.penetration);
  for (int i = 0; i < m.contact_count; ++i) {
    round_to_float(m.contacts[i].point_on_a);
    round_to_float(m.contacts[i].point_on_b);
    m.contacts[i].penetration = to_float(m.contacts[i].penetration);
  }
}

}  // namespace mutant

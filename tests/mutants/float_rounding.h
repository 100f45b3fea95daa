#pragma once
// Single precision at the generator's boundary: the poses it reads and every
// number it writes are rounded to float, as an engine that keeps its
// transforms and results in float does. Errors are a few float ulps of the
// coordinates; the logic is the built-in's, in double.
#include <cmath>

#include "manifuzz/abi.h"

namespace mutant {

inline double to_float(double x) { return static_cast<float>(x); }
inline void round_to_float(mfz_vec3& v) { v = {to_float(v.x), to_float(v.y), to_float(v.z)}; }

// The orientation is stored as four floats and read as the rotation they
// stand for, normalised. Rounded but not normalised it hands the generator
// a rotation matrix sheared by 1e-7, which the clipping of two 0.99-deep
// concentric cubes with faces 1e-3 apart magnified 500 times: 7e-5 L off
// the surface in a rigid-motion run, a false alarm at seeds 301 and 302
// (30,000 cases each pass once normalised).
inline void round_pose(mfz_pose& p) {
  round_to_float(p.position);
  mfz_quat q = {to_float(p.orientation.w), to_float(p.orientation.x), to_float(p.orientation.y),
                to_float(p.orientation.z)};
  const double n = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
  p.orientation = {q.w / n, q.x / n, q.y / n, q.z / n};
}

// An engine in float keeps a contact only while its depth, in float, is
// below zero: a depth under float's smallest (1.4e-45) is zero there, and
// the contact is dropped, as the clip's own filter drops a point on the
// reference plane. Rounded after the filter instead, such a depth became
// -0, which the contract's p_i < 0 refuses: a corner of denormal
// coordinates at the origin gave a contact 1.8e-312 deep, a false alarm of
// the vertex-order relation (stop 55, `manifuzz fuzz` on the variant, 52 s;
// corpus/variants/float-variant-a-depth-below-float-s-smallest-kept-as-minus-zero.case).
inline void round_manifold(mfz_manifold& m) {
  round_to_float(m.normal);
  m.penetration = to_float(m.penetration);
  int kept = 0;
  for (int i = 0; i < m.contact_count; ++i) {
    mfz_contact c = m.contacts[i];
    round_to_float(c.point_on_a);
    round_to_float(c.point_on_b);
    c.penetration = to_float(c.penetration);
    if (m.colliding == 1 && !(c.penetration < 0) && m.contacts[i].penetration < 0) continue;
    m.contacts[kept++] = c;
  }
  m.contact_count = kept;
}

}  // namespace mutant

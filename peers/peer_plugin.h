#pragma once
/// \file
/// What every peer plugin shares: the scale L of a case (the larger hull
/// diameter, as the contract defines it) and the exported ABI entry points.
/// A peer uses the public ABI only, like a user's plugin: nothing of the
/// harness's library is linked in.
#include <algorithm>
#include <cmath>
#include <string>

#include "manifuzz/abi.h"

#define MFZ_PEER_EXPORT extern "C" __attribute__((visibility("default")))

namespace peer {

/// A hull's diameter: the longest distance between two of its vertices.
inline double diameter(const mfz_hull& h) {
  double longest = 0;
  for (int i = 0; i < h.vertex_count; ++i)
    for (int j = i + 1; j < h.vertex_count; ++j) {
      const double dx = h.vertices[i].x - h.vertices[j].x, dy = h.vertices[i].y - h.vertices[j].y,
                   dz = h.vertices[i].z - h.vertices[j].z;
      longest = std::max(longest, dx * dx + dy * dy + dz * dz);
    }
  return std::sqrt(longest);
}

/// The contract's L: the larger of the two diameters.
inline double case_scale(const mfz_hull& a, const mfz_hull& b) { return std::max(diameter(a), diameter(b)); }

/// An empty, not-colliding manifold (every field set).
inline void clear(mfz_manifold& out) {
  out.colliding = 0;
  out.normal = {0, 0, 1};
  out.penetration = 0;
  out.contact_count = 0;
}

}  // namespace peer

#include "geometry/parallelepiped.h"

#include <cmath>

namespace mfz {

namespace {

Vec3 local_edge(const PosedHull& hull, const TopologyEdge& edge) {
  return hull.local_vertex(edge.v1) - hull.local_vertex(edge.v0);
}

}  // namespace

bool is_parallelepiped(const PosedHull& hull) {
  const HullTopology* topology = hull.vertex_count() == 8 ? hull.topology() : nullptr;
  if (!topology || !topology->has_cube_loops()) return false;
  Vec3 direction[3];
  for (int z = 0; z < 3; ++z) {
    direction[z] = local_edge(hull, topology->edge(topology->zone_edge(z, 0)));
    const double length2 = direction[z].squaredNorm();
    for (int k = 1; k < 4; ++k) {
      const Vec3 other = local_edge(hull, topology->edge(topology->zone_edge(z, k)));
      // Squared, to spare three square roots: |d x o|^2 <= s^2 |d|^2 |o|^2.
      const double bound = tol::kZoneParallelSine * tol::kZoneParallelSine * length2 * other.squaredNorm();
      if (!(direction[z].cross(other).squaredNorm() <= bound)) return false;
    }
  }
  const double volume = std::abs(direction[0].dot(direction[1].cross(direction[2])));
  return volume >= tol::kZoneSpan * direction[0].norm() * direction[1].norm() * direction[2].norm();
}

}  // namespace mfz

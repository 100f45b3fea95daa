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
      // Squared, to spare the square roots: |d x o|^2 <= s^2 |d|^2 |o|^2.
      const double bound = tol::kZoneParallelSine * tol::kZoneParallelSine * length2 * other.squaredNorm();
      if (!(direction[z].cross(other).squaredNorm() <= bound)) return false;
    }
  }
  // The same squared: volume^2 >= span^2 |d0|^2 |d1|^2 |d2|^2, with a
  // product that neither vanishes nor overflows (a hull 1e200 across takes
  // the general path).
  const double volume = direction[0].dot(direction[1].cross(direction[2]));
  const double needed = tol::kZoneSpan * tol::kZoneSpan * direction[0].squaredNorm() * direction[1].squaredNorm() *
                        direction[2].squaredNorm();
  return needed > 0 && std::isfinite(needed) && volume * volume >= needed;
}

int supporting_zone_edge(const PosedHull& hull, int zone, const Vec3& direction) {
  const HullTopology& topology = *hull.topology();
  int best = topology.zone_edge(zone, 0);
  double best_d = direction.dot(hull.world_vertex(topology.edge(best).v0));
  for (int k = 1; k < 4; ++k) {
    const int e = topology.zone_edge(zone, k);
    const double d = direction.dot(hull.world_vertex(topology.edge(e).v0));
    if (d > best_d) best = e, best_d = d;
  }
  return best;
}

}  // namespace mfz

#include "geometry/parallelepiped.h"

#include <cmath>

namespace mfz {

namespace {

// A zone's edges as plain doubles, one array per coordinate.
struct ZoneEdges {
  double x[4], y[4], z[4];
};

// Edge k of zone z as v1 - v0 in the hull's own frame.
ZoneEdges zone_edges(const mfz_hull& hull, const HullTopology& topology, int zone) {
  ZoneEdges e;
  for (int k = 0; k < 4; ++k) {
    const TopologyEdge& edge = topology.edge(topology.zone_edge(zone, k));
    const mfz_vec3 &from = hull.vertices[edge.v0], &to = hull.vertices[edge.v1];
    e.x[k] = to.x - from.x, e.y[k] = to.y - from.y, e.z[k] = to.z - from.z;
  }
  return e;
}

double squared_norm(double x, double y, double z) { return (x * x + y * y) + z * z; }

}  // namespace

// In plain doubles, in the order Eigen's cross, dot and squaredNorm take
// them, so the same bits as through Vec3: through Vec3 the twelve edges'
// tests were 600 instructions a hull, 6% of a box pair's call.
bool is_parallelepiped(const PosedHull& hull) {
  const HullTopology* topology = hull.vertex_count() == 8 ? hull.topology() : nullptr;
  if (!topology || !topology->has_cube_loops()) return false;
  constexpr double parallel2 = tol::kZoneParallelSine * tol::kZoneParallelSine;
  double dx[3], dy[3], dz[3], length2[3];
  for (int zone = 0; zone < 3; ++zone) {
    const ZoneEdges e = zone_edges(hull.abi_hull(), *topology, zone);
    dx[zone] = e.x[0], dy[zone] = e.y[0], dz[zone] = e.z[0];
    length2[zone] = squared_norm(e.x[0], e.y[0], e.z[0]);
    for (int k = 1; k < 4; ++k) {
      // Squared, to spare the square roots: |d x o|^2 <= s^2 |d|^2 |o|^2.
      const double bound = parallel2 * length2[zone] * squared_norm(e.x[k], e.y[k], e.z[k]);
      const double cx = e.y[0] * e.z[k] - e.z[0] * e.y[k];
      const double cy = e.z[0] * e.x[k] - e.x[0] * e.z[k];
      const double cz = e.x[0] * e.y[k] - e.y[0] * e.x[k];
      if (!(squared_norm(cx, cy, cz) <= bound)) return false;
    }
  }
  // The same squared: volume^2 >= span^2 |d0|^2 |d1|^2 |d2|^2, with a
  // product that neither vanishes nor overflows (a hull 1e200 across takes
  // the general path).
  const double cx = dy[1] * dz[2] - dz[1] * dy[2];
  const double cy = dz[1] * dx[2] - dx[1] * dz[2];
  const double cz = dx[1] * dy[2] - dy[1] * dx[2];
  const double volume = (dx[0] * cx + dy[0] * cy) + dz[0] * cz;
  const double needed = tol::kZoneSpan * tol::kZoneSpan * length2[0] * length2[1] * length2[2];
  return needed > 0 && std::isfinite(needed) && volume * volume >= needed;
}

}  // namespace mfz

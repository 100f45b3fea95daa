#include "generator/supporting_edges.h"

#include <algorithm>
#include <cmath>

#include "geometry/tolerances.h"

namespace mfz {

SupportingEdges::SupportingEdges(const PosedHull& hull, const Vec3& direction) : hull_(hull), direction_(direction) {
  double best = -std::numeric_limits<double>::infinity(), lowest = std::numeric_limits<double>::infinity();
  double extent = 0;
  for (int i = 0; i < hull.vertex_count(); ++i) {
    const Vec3 p = hull.world_vertex(i);
    const double height = direction.dot(p);
    if (i < kKeptHeights) heights_[i] = height;
    lowest = std::min(lowest, height);
    extent = std::max(extent, p.cwiseAbs().maxCoeff());
  }
  // F22: a diagonal between two triangles of one face would add a contact
  // that the face untriangulated does not have.
  each_edge([&](int, int, int, double reach, const auto& is_flat) {
    if (reach > best && !is_flat()) best = reach;
    return true;
  });
  threshold_ = best - (tol::kTie * std::max(best - lowest, hull.span()) +
                       tol::world_rounding(std::max(std::abs(best), extent)));
}

int SupportingEdges::first() const {
  int found = -1;
  each_edge([&](int edge, int, int, double reach, const auto& is_flat) {
    if (reach >= threshold_ && !is_flat()) found = edge;
    return found < 0;
  });
  return found;
}

}  // namespace mfz

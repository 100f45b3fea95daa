#include "geometry/simplicial_facets.h"

#include <algorithm>
#include <cmath>

namespace mfz {

std::optional<std::vector<QhullFacet>> simplicial_facets(const std::vector<Vec3>& points) {
  const int n = static_cast<int>(points.size());
  if (n < 4 || n > kSimplicialMaxPoints) return std::nullopt;
  double diameter = 0;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) diameter = std::max(diameter, (points[i] - points[j]).squaredNorm());
  diameter = std::sqrt(diameter);
  std::vector<QhullFacet> facets;
  facets.reserve(static_cast<size_t>(2 * n - 4));
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      for (int k = j + 1; k < n; ++k) {
        const Vec3 normal = (points[j] - points[i]).cross(points[k] - points[i]);
        const double twice_area = normal.norm();
        // Three points nearly on a line span no plane worth trusting; if
        // they bound the hull, the facets found will not close and Qhull
        // takes over.
        if (!(twice_area > kNearPlane * diameter * diameter)) continue;
        const double near = kNearPlane * diameter * twice_area;  // a distance of kNearPlane x diameter
        int above = 0, below = 0, on = 0;
        for (int l = 0; l < n; ++l) {
          if (l == i || l == j || l == k) continue;
          const double height = normal.dot(points[l] - points[i]);
          above += height > near;
          below += height < -near;
          on += std::abs(height) <= near;
        }
        if (above > 0 && below > 0) continue;
        if (on > 0) return std::nullopt;  // four points on a supporting plane: Qhull merges or keeps its way
        const bool outward = above == 0;
        QhullFacet facet;
        facet.normal = (outward ? normal : Vec3(-normal)) / twice_area;
        facet.offset = facet.normal.dot(points[i]);
        facet.point_ids = outward ? std::vector<int>{i, j, k} : std::vector<int>{i, k, j};
        facets.push_back(std::move(facet));
      }
  return facets;
}

}  // namespace mfz

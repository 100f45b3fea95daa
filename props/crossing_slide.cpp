#include "crossing_slide.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/closest_point.h"

namespace mfz::props {
namespace {

struct Segment {
  Vec3 from, to;
};

// The edges of a posed hull that pass within `on_edge` of `point`.
std::vector<Segment> edges_through(const Hull& hull, const std::vector<Vec3>& world, const Vec3& point, double on_edge) {
  std::vector<Segment> out;
  for (const HullEdge& e : hull.edges()) {
    const Vec3& from = world[e.v0];
    const Vec3& to = world[e.v1];
    if ((point - closest_on_segment(point, from, to)).norm() <= on_edge) out.push_back({from, to});
  }
  return out;
}

// The slides of an incident point along each incident edge it lies on,
// against each side plane through a reference edge its partner lies on.
void add_slides(bool incident_is_a, const std::vector<Segment>& incident_edges,
                const std::vector<Segment>& reference_edges, const Vec3& on_incident, const Vec3& n, double rounding,
                double worth, std::vector<CrossingSlide>& out) {
  for (const Segment& e : incident_edges) {
    const double length = (e.to - e.from).norm();
    if (!(length > 0)) continue;
    const Vec3 along = (e.to - e.from) / length;
    const double at = (on_incident - e.from).dot(along);
    for (const Segment& r : reference_edges) {
      const Vec3 side = (r.to - r.from).cross(n);
      if (!(side.norm() > 0)) continue;
      const double sine = std::abs(along.dot(side.normalized()));
      const double reach = sine > 0 ? rounding / sine : std::numeric_limits<double>::infinity();
      if (!(reach > worth)) continue;
      out.push_back({incident_is_a, along, along - along.dot(n) * n, std::max(-reach, -at),
                     std::min(reach, length - at)});
    }
  }
}

}  // namespace

std::vector<CrossingSlide> crossing_slides(const Scene& scene, const Vec3& normal, const Vec3& on_a, const Vec3& on_b,
                                           double on_edge, double rounding, double worth) {
  std::vector<CrossingSlide> out;
  const double length = normal.norm();
  if (!(length > 0) || !std::isfinite(length)) return out;
  const Vec3 n = normal / length;
  const std::vector<Segment> edges_a = edges_through(scene.hull_a, scene.world_a, on_a, on_edge);
  const std::vector<Segment> edges_b = edges_through(scene.hull_b, scene.world_b, on_b, on_edge);
  add_slides(false, edges_b, edges_a, on_b, n, rounding, worth, out);
  add_slides(true, edges_a, edges_b, on_a, n, rounding, worth, out);
  return out;
}

}  // namespace mfz::props

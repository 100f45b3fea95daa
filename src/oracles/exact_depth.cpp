#include "oracles/exact_depth.h"

#include "oracles/hull_gap.h"

namespace mfz {

ExactDepth exact_depth(const Scene& scene, const std::vector<RankedAxis>& ranked) {
  ExactDepth answer;
  if (ranked.empty()) return answer;
  if (ranked[0].overlap >= 0) {
    answer.colliding = true;
    answer.signed_depth = ranked[0].overlap;
    answer.normal = ranked[0].normal;
    return answer;
  }
  const HullGap gap = hull_gap(scene);
  answer.signed_depth = -gap.distance;
  answer.normal = gap.distance > 0 ? Vec3((gap.on_b - gap.on_a) / gap.distance) : Vec3(-ranked[0].normal);
  return answer;
}

}  // namespace mfz

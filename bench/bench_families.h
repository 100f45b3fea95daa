#pragma once
// The families the generator benchmark times every generator on: 1024 pairs
// each, from fixed seeds, hulls built (Qhull) and posed before any timing.
#include <functional>
#include <string>
#include <vector>

#include "case/scene.h"

namespace mfz::bench {

struct BenchFamily {
  std::string name;            ///< a column of the table
  bool boxes = false;          ///< only box pairs: dBoxBox takes them
  std::vector<Scene> scenes;
};

/// Boxes resting face to face (a small tilt, any yaw), boxes tilted a few
/// degrees, random hulls of 8, 32 and 128 points on spheres of random
/// radius overlapping, with `large` 512 points too, 64-gon cylinders cap to
/// cap, the same cylinders with their faces triangulated
/// (fan_triangulated), and 32-point hulls apart (the early-out); `pairs`
/// each. The 512-point family is timed (generator_bench) but not
/// fingerprinted: a generator that measures every edge pair there (the
/// tutorial, or the built-in before stop 52) takes seconds a call.
/// A family whose name `wanted` turns down comes back with no scenes: a
/// run filtered to the boxes starts at once instead of after seconds of
/// Qhull (minutes under valgrind).
std::vector<BenchFamily> bench_families(int pairs = 1024, bool large = false,
                                        const std::function<bool(const std::string&)>& wanted = {});

}  // namespace mfz::bench

#pragma once
/// \file
/// Hulls built once per distinct point set. The fuzzer's mutations, the
/// relations and the shrinker move poses far more often than points, and a
/// hull built again is work thrown away (Qhull's 18 us per call where it
/// still builds). The cache is bounded (the least recently used hull goes
/// first), so a run of hours holds at most `capacity` hulls.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "geometry/hull.h"

namespace mfz {

class HullCache {
 public:
  explicit HullCache(size_t capacity = 64) : capacity_(capacity) {}
  /// `build_hull(points)`, from the cache when these exact points (bit for
  /// bit, in this order) were built before. Valid until the next call.
  const HullBuild& build(const std::vector<Vec3>& points);
  long long hits() const { return hits_; }
  long long misses() const { return misses_; }
  size_t size() const { return entries_.size(); }

 private:
  struct Entry {
    size_t key = 0;
    std::vector<Vec3> points;
    HullBuild built;
    uint64_t last_use = 0;
  };
  size_t capacity_;
  std::vector<Entry> entries_;
  uint64_t clock_ = 0;
  long long hits_ = 0, misses_ = 0;
};

/// This thread's cache, shared by every layer that builds hulls from a
/// case's points (the scene, the families), so that a case drawn and then
/// checked builds each hull once.
HullCache& thread_hull_cache();

}  // namespace mfz

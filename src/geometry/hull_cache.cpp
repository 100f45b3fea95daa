#include "geometry/hull_cache.h"

#include <algorithm>
#include <cstring>
#include <functional>
#include <string_view>

namespace mfz {
namespace {

size_t key_of(const std::vector<Vec3>& points) {
  const std::string_view bytes(reinterpret_cast<const char*>(points.data()), points.size() * sizeof(Vec3));
  return std::hash<std::string_view>{}(bytes);
}

// Bitwise, not ==: -0.0 and 0.0 give the same hull but a NaN never equals
// itself, and a cache must not tell them apart differently from the hash.
// An empty vector's data() may be null, which memcmp must not be given
// (case_file_fuzzer under UBSan, a case file with no points).
bool same_points(const std::vector<Vec3>& x, const std::vector<Vec3>& y) {
  if (x.size() != y.size()) return false;
  return x.empty() || std::memcmp(x.data(), y.data(), x.size() * sizeof(Vec3)) == 0;
}

}  // namespace

const HullBuild& HullCache::build(const std::vector<Vec3>& points) {
  const size_t key = key_of(points);
  ++clock_;
  for (Entry& e : entries_)
    if (e.key == key && same_points(e.points, points)) {
      e.last_use = clock_;
      ++hits_;
      return e.built;
    }
  ++misses_;
  Entry fresh{key, points, build_hull(points), clock_};
  if (entries_.size() < capacity_) {
    entries_.push_back(std::move(fresh));
    return entries_.back().built;
  }
  auto oldest = std::min_element(entries_.begin(), entries_.end(),
                                 [](const Entry& a, const Entry& b) { return a.last_use < b.last_use; });
  *oldest = std::move(fresh);
  return oldest->built;
}

HullCache& thread_hull_cache() {
  static thread_local HullCache cache;
  return cache;
}

}  // namespace mfz

#pragma once
/// \file
/// What every peer plugin shares: the scale L of a case (the larger hull
/// diameter, as the contract defines it), the exported ABI entry points, and
/// a store of each hull's engine-side form.
/// A peer uses the public ABI only, like a user's plugin: nothing of the
/// harness's library is linked in.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "manifuzz/abi.h"

#define MFZ_PEER_EXPORT extern "C" __attribute__((visibility("default")))

namespace peer {

/// A hull's diameter: the longest distance between two of its vertices.
inline double diameter(const mfz_hull& h) {
  double longest = 0;
  for (int i = 0; i < h.vertex_count; ++i)
    for (int j = i + 1; j < h.vertex_count; ++j) {
      const double dx = h.vertices[i].x - h.vertices[j].x, dy = h.vertices[i].y - h.vertices[j].y,
                   dz = h.vertices[i].z - h.vertices[j].z;
      longest = std::max(longest, dx * dx + dy * dy + dz * dz);
    }
  return std::sqrt(longest);
}

/// The contract's L: the larger of the two diameters.
inline double case_scale(const mfz_hull& a, const mfz_hull& b) { return std::max(diameter(a), diameter(b)); }

/// An empty, not-colliding manifold (every field set).
inline void clear(mfz_manifold& out) {
  out.colliding = 0;
  out.normal = {0, 0, 1};
  out.penetration = 0;
  out.contact_count = 0;
}

/// An engine builds its form of a shape once (Bullet's btConvexPolyhedron
/// and btConvexHullShape, ODE's convex geom) and collides it many times; a
/// peer that built it on every call would be timed on the conversion, not
/// on its collision. So each thread keeps the forms of the hulls it has
/// seen, keyed by their whole content (compared in full on a hit, never by
/// address), up to kCapacity hulls, then starts again. The capacity holds
/// every hull of a bench run (seven families of 2,048 hulls): at 4,096 the
/// table started again during the 128-point family, and Bullet's GJK/EPA
/// was timed there at 737,596 ns per query, rebuilding its polyhedra,
/// where alone it takes 31,000. A call begins with `begin_call()`, so that
/// starting again never pulls a form from under the call that holds it.
template <class Prepared>
class PreparedHulls {
 public:
  static constexpr size_t kCapacity = 16384;

  /// Room for the call's two hulls.
  void begin_call() {
    if (count_ + 2 > kCapacity) {
      table_.clear();
      count_ = 0;
    }
  }

  /// The form of `hull`, made by `make(hull, prepared)` on first sight.
  template <class Make>
  Prepared& get(const mfz_hull& hull, Make&& make) {
    const Parts parts = parts_of(hull);
    size_t key = hull.vertex_count * 31u + hull.face_count;
    for (const std::string_view part : parts) key = key * 1000003u ^ std::hash<std::string_view>{}(part);
    auto& bucket = table_[key];
    for (const auto& entry : bucket)
      if (entry->same(parts)) return entry->prepared;
    auto entry = std::make_unique<Entry>();
    for (int i = 0; i < 4; ++i) entry->bytes[i].assign(parts[i]);
    make(hull, entry->prepared);
    ++count_;
    table_[key].push_back(std::move(entry));
    return table_[key].back()->prepared;
  }

 private:
  using Parts = std::array<std::string_view, 4>;
  static Parts parts_of(const mfz_hull& h) {
    const auto bytes = [](const void* p, size_t n) { return std::string_view(static_cast<const char*>(p), n); };
    const int steps = h.face_offsets[h.face_count];
    return {bytes(h.vertices, sizeof(mfz_vec3) * h.vertex_count),
            bytes(h.face_normals, sizeof(mfz_vec3) * h.face_count),
            bytes(h.face_offsets, sizeof(int32_t) * (h.face_count + 1)),
            bytes(h.face_vertices, sizeof(int32_t) * steps)};
  }
  struct Entry {
    std::string bytes[4];
    Prepared prepared;
    bool same(const Parts& parts) const {
      for (int i = 0; i < 4; ++i)
        if (bytes[i] != parts[i]) return false;
      return true;
    }
  };
  std::unordered_map<size_t, std::vector<std::unique_ptr<Entry>>> table_;
  size_t count_ = 0;
};

}  // namespace peer

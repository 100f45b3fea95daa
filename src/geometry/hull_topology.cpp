#include "geometry/hull_topology.h"

#include <algorithm>
#include <cstring>

namespace mfz {

namespace {

bool loops_fit(const mfz_hull& hull) {
  if (hull.vertex_count < 4 || hull.vertex_count > kTopologyMaxVertices) return false;
  if (hull.face_count < 4 || hull.face_count > kTopologyMaxFaces) return false;
  if (hull.face_offsets[0] != 0) return false;
  for (int f = 0; f < hull.face_count; ++f)
    if (hull.face_offsets[f + 1] - hull.face_offsets[f] < 3) return false;
  const int steps = hull.face_offsets[hull.face_count];
  if (steps > kTopologyMaxSteps) return false;
  for (int i = 0; i < steps; ++i)
    if (hull.face_vertices[i] < 0 || hull.face_vertices[i] >= hull.vertex_count) return false;
  return true;
}

}  // namespace

bool HullTopology::same_loops(const mfz_hull& hull) const {
  if (hull.vertex_count != vertex_count_ || hull.face_count != face_count_) return false;
  const size_t offsets = sizeof(int32_t) * (face_count_ + 1);
  if (std::memcmp(offsets_, hull.face_offsets, offsets) != 0) return false;
  return std::memcmp(loops_, hull.face_vertices, sizeof(int32_t) * step_count_) == 0;
}

bool HullTopology::build(const mfz_hull& hull) {
  vertex_count_ = -1;  // unusable until complete
  if (!loops_fit(hull)) return false;
  const int faces = hull.face_count, steps = hull.face_offsets[faces], vertices = hull.vertex_count;
  std::memcpy(offsets_, hull.face_offsets, sizeof(int32_t) * (faces + 1));
  std::memcpy(loops_, hull.face_vertices, sizeof(int32_t) * steps);
  // Steps bucketed by their first vertex (a counting sort, linear): the
  // twin of v0 -> v1 is the step in v1's bucket that ends at v0.
  int step_end[kTopologyMaxSteps], step_face[kTopologyMaxSteps];
  int bucket_offsets[kTopologyMaxVertices + 1] = {};
  for (int f = 0; f < faces; ++f) {
    const int begin = offsets_[f], end = offsets_[f + 1];
    for (int i = begin; i < end; ++i) {
      step_end[i] = loops_[i + 1 < end ? i + 1 : begin];
      step_face[i] = f;
      if (step_end[i] == loops_[i]) return false;
      ++bucket_offsets[loops_[i] + 1];
    }
  }
  for (int v = 0; v < vertices; ++v) bucket_offsets[v + 1] += bucket_offsets[v];
  int bucket_end[kTopologyMaxSteps], bucket_face[kTopologyMaxSteps];
  int fill[kTopologyMaxVertices];
  std::copy(bucket_offsets, bucket_offsets + vertices, fill);
  for (int i = 0; i < steps; ++i) {
    const int at = fill[loops_[i]]++;
    bucket_end[at] = step_end[i], bucket_face[at] = step_face[i];
  }
  for (int i = 0; i < steps; ++i) {
    const int v0 = loops_[i], v1 = step_end[i];
    int twins = 0;
    int face = -1;
    for (int j = bucket_offsets[v1]; j < bucket_offsets[v1 + 1]; ++j) {
      const bool twin = bucket_end[j] == v0;  // branchless: which one matches is data
      face = twin ? bucket_face[j] : face;
      twins += twin;
    }
    across_[i] = face;
    if (twins != 1) return false;  // open, or an edge in more than two faces
  }
  // Edges in SAT's order, and each vertex's neighbours.
  int degree[kTopologyMaxVertices + 1] = {};
  edge_count_ = 0;
  for (int f = 0; f < faces; ++f) {
    const int begin = offsets_[f], n = offsets_[f + 1] - begin;
    for (int k = 0; k < n; ++k) {
      const int v0 = loops_[begin + k], v1 = loops_[begin + (k + 1) % n];
      if (v0 > v1) continue;
      edges_[edge_count_++] = {v0, v1, f, across_[begin + k]};
      ++degree[v0], ++degree[v1];
    }
  }
  neighbour_offsets_[0] = 0;
  for (int v = 0; v < vertices; ++v) neighbour_offsets_[v + 1] = neighbour_offsets_[v] + degree[v];
  int filled[kTopologyMaxVertices] = {};
  for (int e = 0; e < edge_count_; ++e) {
    const TopologyEdge& edge = edges_[e];
    neighbours_[neighbour_offsets_[edge.v0] + filled[edge.v0]++] = edge.v1;
    neighbours_[neighbour_offsets_[edge.v1] + filled[edge.v1]++] = edge.v0;
  }
  for (int v = 0; v < vertices; ++v)
    if (degree[v] < 3) return false;  // a vertex in no corner of the polyhedron
  vertex_count_ = vertices, face_count_ = faces, step_count_ = steps;
  return true;
}

// The least recently used slot gives way.
class TopologyCache {
 public:
  const HullTopology* find(const mfz_hull& hull) {
    ++clock_;
    for (int s = 0; s < kTopologySlots; ++s)
      if (slots_[s].same_loops(hull)) {
        last_use_[s] = clock_;
        return &slots_[s];
      }
    const int victim = static_cast<int>(std::min_element(last_use_, last_use_ + kTopologySlots) - last_use_);
    last_use_[victim] = clock_;
    return slots_[victim].build(hull) ? &slots_[victim] : nullptr;
  }

 private:
  HullTopology slots_[kTopologySlots];
  unsigned long long last_use_[kTopologySlots] = {};
  unsigned long long clock_ = 0;
};

const HullTopology* topology_of(const mfz_hull& hull) {
  static thread_local TopologyCache cache;
  return cache.find(hull);
}

}  // namespace mfz

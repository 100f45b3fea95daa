#include "geometry/hull_topology.h"

#include <algorithm>
#include <cstring>
#include <memory>

// The hash compiled in from the header: no library to link or ship.
#define XXH_INLINE_ALL
#include <xxhash.h>

namespace mfz {

namespace {

// The loops' counts are in range: the hash may read them.
bool counts_fit(const mfz_hull& hull) {
  if (hull.vertex_count < 4 || hull.vertex_count > kTopologyMaxVertices) return false;
  if (hull.face_count < 4 || hull.face_count > kTopologyMaxFaces) return false;
  const int steps = hull.face_offsets[hull.face_count];
  return hull.face_offsets[0] == 0 && steps >= 3 * hull.face_count && steps <= kTopologyMaxSteps;
}

// Every loop has three steps or more and names vertices of the hull.
bool loops_fit(const mfz_hull& hull) {
  for (int f = 0; f < hull.face_count; ++f)
    if (hull.face_offsets[f + 1] - hull.face_offsets[f] < 3) return false;
  const int steps = hull.face_offsets[hull.face_count];
  for (int i = 0; i < steps; ++i)
    if (hull.face_vertices[i] < 0 || hull.face_vertices[i] >= hull.vertex_count) return false;
  return true;
}

// XXH3 over the counts, the offsets and the loops, each array at once. The
// FNV-1a it replaces took a word at a time, each step waiting on the
// last's multiply: on pairs cycled through the benchmark (no pair met
// twice in a row) hashing the loops was a tenth of a 32-point call.
uint64_t loops_hash(const mfz_hull& hull) {
  const int32_t counts[2] = {hull.vertex_count, hull.face_count};
  uint64_t h = XXH3_64bits(counts, sizeof counts);
  h = XXH3_64bits_withSeed(hull.face_offsets, sizeof(int32_t) * (hull.face_count + 1), h);
  return XXH3_64bits_withSeed(hull.face_vertices, sizeof(int32_t) * hull.face_offsets[hull.face_count], h);
}

// The words a topology takes after its header: offsets and loops, the face
// across each step, the edges (four words each), neighbour offsets and
// neighbours (two per edge). A closed polyhedron has an edge per two steps.
size_t words_for(int vertices, int faces, int steps) {
  const int edges = steps / 2;
  return static_cast<size_t>((faces + 1) + steps + steps + 4 * edges + (vertices + 1) + 2 * edges);
}

constexpr size_t kAlignment = 16;
size_t aligned(size_t bytes) { return (bytes + kAlignment - 1) / kAlignment * kAlignment; }
constexpr size_t kLargestEntry =
    (sizeof(HullTopology) + sizeof(int32_t) * (kTopologyMaxFaces + 1 + 2 * kTopologyMaxSteps + 4 * kTopologyMaxEdges +
                                               kTopologyMaxVertices + 1 + 2 * kTopologyMaxEdges) +
     kAlignment - 1) / kAlignment * kAlignment;
static_assert(kTopologyStoreBytes >= 64 * kLargestEntry, "the ring must hold many of the largest topologies");

// What a build works in besides the ring: the steps bucketed by their first
// vertex, and counts per vertex. Sized for the largest hull, 114 KB, so
// kept with the store, reserved with it, not on the call's stack.
struct BuildScratch {
  int step_end[kTopologyMaxSteps], step_face[kTopologyMaxSteps];
  int bucket_end[kTopologyMaxSteps], bucket_face[kTopologyMaxSteps];
  int bucket_offsets[kTopologyMaxVertices + 1], fill[kTopologyMaxVertices];
  int degree[kTopologyMaxVertices + 1], filled[kTopologyMaxVertices];
};

// Zones of a cube's loops: an edge's zone holds the edge opposite it in
// each of its two faces, and theirs in turn. Twelve edges in three zones of
// four, or the loops are not a cube's and `zones` starts with -1.
void find_cube_zones(int faces, const int32_t* offsets, const int32_t* loops, const TopologyEdge* edges,
                     int edge_count, int32_t (&zones)[3][4]) {
  zones[0][0] = -1;
  if (faces != 6 || edge_count != 12 || offsets[faces] != 24) return;
  // The edge of each loop step, by its two ends.
  int step_edge[24];
  for (int i = 0; i < 24; ++i) {
    const int f = i / 4;
    if (offsets[f] != 4 * f) return;
    const int v0 = loops[i], v1 = loops[4 * f + (i + 1) % 4];
    step_edge[i] = -1;
    for (int e = 0; e < edge_count; ++e)
      if ((edges[e].v0 == v0 && edges[e].v1 == v1) || (edges[e].v0 == v1 && edges[e].v1 == v0)) step_edge[i] = e;
  }
  int zone_of[12];
  std::fill(zone_of, zone_of + 12, -1);
  for (int z = 0; z < 3; ++z) {
    const int first = static_cast<int>(std::find(zone_of, zone_of + 12, -1) - zone_of);
    if (first == 12) return;
    int queue[12], queued = 0;
    zone_of[first] = z, queue[queued++] = first;
    for (int at = 0; at < queued; ++at)
      for (int i = 0; i < 24; ++i) {
        if (step_edge[i] != queue[at]) continue;
        const int opposite = step_edge[4 * (i / 4) + (i + 2) % 4];
        if (opposite < 0 || zone_of[opposite] >= 0) continue;
        if (queued == 4) return;
        zone_of[opposite] = z, queue[queued++] = opposite;
      }
    if (queued != 4) return;
  }
  int filled[3] = {};
  for (int e = 0; e < 12; ++e) zones[zone_of[e]][filled[zone_of[e]]++] = e;
}

}  // namespace

// The ring: topologies are written one after another at the head; when the
// next does not fit before the end, the head goes back to the start and a
// new lap begins. An entry is alive while the head has not passed over it:
// written this lap, or last lap at or past the head. The index is a set-
// associative table of hashes (kWays entries a set; the stalest gives way).
class TopologyStore {
 public:
  uint64_t hashed() const { return hashed_; }

  const HullTopology* find(const mfz_hull& hull) {
    if (!counts_fit(hull)) return nullptr;
    if (!arena_) reserve();
    // First the entries last found for loops at this address, then the
    // last two hulls, both without hashing: a caller keeps a shape's loops
    // where they are from call to call, a call's pair comes again (the
    // relations, the shrinker), and every box has the same loops. The
    // address is only where to look: the loops are compared in full.
    AddressSlot* by_address = tables_->by_address[address_set(hull)];
    for (int w = 0; w < kAddressWays; ++w) {
      const AddressSlot& slot = by_address[w];
      if (slot.loops == hull.face_vertices && slot.entry && alive(*slot.entry) && same_loops(at(*slot.entry), hull))
        return hit(*slot.entry);
    }
    for (Entry* e : recent_)
      if (e && alive(*e) && same_loops(at(*e), hull)) return hit(at_address(by_address, hull, *e));
    const uint64_t hash = loops_hash(hull);
    ++hashed_;
    Entry* set = tables_->index + (hash % kSets) * kWays;
    for (int w = 0; w < kWays; ++w) {
      Entry& e = set[w];
      if (e.hash == hash && alive(e) && same_loops(at(e), hull)) return hit(at_address(by_address, hull, e));
    }
    if (!loops_fit(hull)) return nullptr;
    Entry& victim = *std::min_element(set, set + kWays, [this](const Entry& x, const Entry& y) { return age(x) > age(y); });
    const HullTopology* built = build(hull, hash, victim);
    if (built) remember(at_address(by_address, hull, victim));
    return built;
  }

 private:
  struct Entry {
    uint64_t hash = 0;
    uint64_t offset = 0;
    uint64_t lap = 0;  ///< 0: empty
  };
  static constexpr size_t kSets = 8192;
  static constexpr int kWays = 4;
  // Where loops lay when their entry was last found: two ways a set, the
  // latest first. Twice as many sets as the benchmark's hulls a family
  // (2,048, each pair with its own copies), so that a cycle through them
  // finds each where it lies; with one way, two of sixteen hulls' addresses
  // met in one slot and were hashed on every lookup.
  struct AddressSlot {
    const int32_t* loops = nullptr;  ///< null: empty
    Entry* entry = nullptr;
  };
  static constexpr int kAddressBits = 12;
  static constexpr int kAddressWays = 2;

  // Fibonacci hashing: the product's top bits mix every bit of the address.
  static size_t address_set(const mfz_hull& hull) {
    const uint64_t address = reinterpret_cast<uintptr_t>(hull.face_vertices);
    return static_cast<size_t>((address * 0x9E3779B97F4A7C15ull) >> (64 - kAddressBits));
  }

  // `e` is where the loops at hull.face_vertices were found: the latest of
  // the set, the other way the one before (unless that was this address).
  static Entry& at_address(AddressSlot* set, const mfz_hull& hull, Entry& e) {
    if (set[0].loops != hull.face_vertices) set[1] = set[0];
    set[0] = {hull.face_vertices, &e};
    return e;
  }

  const HullTopology* hit(Entry& e) {
    if (near_head(e)) move_to_head(e);
    remember(e);
    return at(e);
  }
  void remember(Entry& e) {
    if (recent_[0] != &e) recent_[1] = recent_[0], recent_[0] = &e;
  }

  void reserve() {
    arena_.reset(new std::byte[kTopologyStoreBytes]);  // not value-initialised: pages touched as used
    tables_.reset(new Tables());  // every entry and every slot empty
    scratch_.reset(new BuildScratch);
  }
  HullTopology* at(const Entry& e) const { return reinterpret_cast<HullTopology*>(arena_.get() + e.offset); }
  bool alive(const Entry& e) const { return e.lap == lap_ || (e.lap + 1 == lap_ && e.offset >= head_); }
  // How far ahead of the head an entry lies along the ring (the next bytes
  // written are nearest); a dead entry is at distance 0.
  size_t distance_ahead(const Entry& e) const {
    if (!alive(e)) return 0;
    return e.lap == lap_ ? kTopologyStoreBytes - head_ + e.offset : e.offset - head_;
  }
  // Older entries are nearer the head; empty and dead ones are oldest.
  size_t age(const Entry& e) const { return kTopologyStoreBytes - distance_ahead(e); }
  // An entry the next lookups could overwrite while the caller still holds
  // it: two more entries of the largest size, and the end of a lap skipped.
  bool near_head(const Entry& e) const { return distance_ahead(e) < 4 * kLargestEntry; }

  static bool same_loops(const HullTopology* t, const mfz_hull& hull) {
    if (hull.vertex_count != t->vertex_count_ || hull.face_count != t->face_count_) return false;
    if (std::memcmp(t->words(), hull.face_offsets, sizeof(int32_t) * (t->face_count_ + 1)) != 0) return false;
    return std::memcmp(t->words() + t->loops_at_, hull.face_vertices, sizeof(int32_t) * t->step_count_) == 0;
  }

  // The head, with room for `bytes` before the end of the ring.
  std::byte* claim(size_t bytes) {
    if (head_ + bytes > kTopologyStoreBytes) head_ = 0, ++lap_;
    std::byte* at = arena_.get() + head_;
    head_ += bytes;
    return at;
  }

  void move_to_head(Entry& e) {
    const HullTopology* from = at(e);
    const size_t bytes = aligned(sizeof(HullTopology) + sizeof(int32_t) * from->size_words_);
    // The source may lie where the head is about to go: memmove.
    const uint64_t old_offset = e.offset;
    std::byte* to = claim(bytes);
    std::memmove(to, arena_.get() + old_offset, bytes);
    e.offset = static_cast<uint64_t>(to - arena_.get());
    e.lap = lap_;
  }

  const HullTopology* build(const mfz_hull& hull, uint64_t hash, Entry& entry);

  std::unique_ptr<std::byte[]> arena_;
  // The index and the slots by address, one allocation (the thread's first
  // calls allocate seven times in all, BuiltinGenerator.AllocatesNothingPerCall).
  struct Tables {
    Entry index[kSets * kWays];
    AddressSlot by_address[size_t{1} << kAddressBits][kAddressWays];
  };
  std::unique_ptr<Tables> tables_;
  std::unique_ptr<BuildScratch> scratch_;
  Entry* recent_[2] = {nullptr, nullptr};  ///< the entries last returned, newest first
  size_t head_ = 0;
  uint64_t lap_ = 1;
  uint64_t serials_ = 0;  ///< the last serial a built topology took
  uint64_t hashed_ = 0;   ///< lookups that hashed the loops (topology_lookups_hashed)
};

// The topology is written straight into the ring at the head. Should the
// loops not close, the head stays past what was written, so that no entry
// still counts as alive where the failed build wrote.
const HullTopology* TopologyStore::build(const mfz_hull& hull, uint64_t hash, Entry& entry) {
  const int faces = hull.face_count, steps = hull.face_offsets[faces], vertices = hull.vertex_count;
  if (steps % 2 != 0) return nullptr;  // a closed polyhedron has two steps per edge
  const size_t bytes = aligned(sizeof(HullTopology) + sizeof(int32_t) * words_for(vertices, faces, steps));
  HullTopology* t = reinterpret_cast<HullTopology*>(claim(bytes));
  entry = {};
  t->vertex_count_ = vertices, t->face_count_ = faces, t->step_count_ = steps, t->edge_count_ = steps / 2;
  t->serial_ = ++serials_;
  t->loops_at_ = faces + 1;
  t->across_at_ = t->loops_at_ + steps;
  t->edges_at_ = t->across_at_ + steps;
  t->neighbour_offsets_at_ = t->edges_at_ + 4 * t->edge_count_;
  t->neighbours_at_ = t->neighbour_offsets_at_ + vertices + 1;
  t->size_words_ = t->neighbours_at_ + 2 * t->edge_count_;
  int32_t* words = reinterpret_cast<int32_t*>(t + 1);
  int32_t* offsets = words;
  int32_t* loops = words + t->loops_at_;
  int32_t* across = words + t->across_at_;
  TopologyEdge* edges = reinterpret_cast<TopologyEdge*>(words + t->edges_at_);
  int32_t* neighbour_offsets = words + t->neighbour_offsets_at_;
  int32_t* neighbours = words + t->neighbours_at_;
  std::memcpy(offsets, hull.face_offsets, sizeof(int32_t) * (faces + 1));
  std::memcpy(loops, hull.face_vertices, sizeof(int32_t) * steps);
  // Steps bucketed by their first vertex (a counting sort, linear): the
  // twin of v0 -> v1 is the step in v1's bucket that ends at v0.
  BuildScratch& s = *scratch_;
  int* step_end = s.step_end;
  int* step_face = s.step_face;
  int* bucket_offsets = s.bucket_offsets;
  std::fill(bucket_offsets, bucket_offsets + vertices + 1, 0);
  for (int f = 0; f < faces; ++f) {
    const int begin = offsets[f], end = offsets[f + 1];
    for (int i = begin; i < end; ++i) {
      step_end[i] = loops[i + 1 < end ? i + 1 : begin];
      step_face[i] = f;
      if (step_end[i] == loops[i]) return nullptr;
      ++bucket_offsets[loops[i] + 1];
    }
  }
  for (int v = 0; v < vertices; ++v) bucket_offsets[v + 1] += bucket_offsets[v];
  int* bucket_end = s.bucket_end;
  int* bucket_face = s.bucket_face;
  int* fill = s.fill;
  std::copy(bucket_offsets, bucket_offsets + vertices, fill);
  for (int i = 0; i < steps; ++i) {
    const int at = fill[loops[i]]++;
    bucket_end[at] = step_end[i], bucket_face[at] = step_face[i];
  }
  for (int i = 0; i < steps; ++i) {
    const int v0 = loops[i], v1 = step_end[i];
    int twins = 0;
    int face = -1;
    for (int j = bucket_offsets[v1]; j < bucket_offsets[v1 + 1]; ++j) {
      const bool twin = bucket_end[j] == v0;  // branchless: which one matches is data
      face = twin ? bucket_face[j] : face;
      twins += twin;
    }
    across[i] = face;
    if (twins != 1) return nullptr;  // open, or an edge in more than two faces
  }
  // Edges in SAT's order, and each vertex's neighbours.
  int* degree = s.degree;
  std::fill(degree, degree + vertices + 1, 0);
  int edge_count = 0;
  for (int f = 0; f < faces; ++f) {
    const int begin = offsets[f], n = offsets[f + 1] - begin;
    for (int k = 0; k < n; ++k) {
      const int v0 = loops[begin + k], v1 = loops[begin + (k + 1) % n];
      if (v0 > v1) continue;
      if (edge_count == t->edge_count_) return nullptr;
      edges[edge_count++] = {v0, v1, f, across[begin + k]};
      ++degree[v0], ++degree[v1];
    }
  }
  if (edge_count != t->edge_count_) return nullptr;
  neighbour_offsets[0] = 0;
  for (int v = 0; v < vertices; ++v) neighbour_offsets[v + 1] = neighbour_offsets[v] + degree[v];
  int* filled = s.filled;
  std::fill(filled, filled + vertices, 0);
  for (int e = 0; e < edge_count; ++e) {
    const TopologyEdge& edge = edges[e];
    neighbours[neighbour_offsets[edge.v0] + filled[edge.v0]++] = edge.v1;
    neighbours[neighbour_offsets[edge.v1] + filled[edge.v1]++] = edge.v0;
  }
  for (int v = 0; v < vertices; ++v)
    if (degree[v] < 3) return nullptr;  // a vertex in no corner of the polyhedron
  find_cube_zones(faces, offsets, loops, edges, edge_count, t->cube_zones_);
  entry = {hash, static_cast<uint64_t>(reinterpret_cast<std::byte*>(t) - arena_.get()), lap_};
  return t;
}

namespace {

TopologyStore& thread_store() {
  static thread_local TopologyStore store;
  return store;
}

}  // namespace

const HullTopology* topology_of(const mfz_hull& hull) { return thread_store().find(hull); }

uint64_t topology_lookups_hashed() { return thread_store().hashed(); }

}  // namespace mfz

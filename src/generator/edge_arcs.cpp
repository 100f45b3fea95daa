#include "generator/edge_arcs.h"

#include <algorithm>
#include <cstdint>
#include <limits>

#include "geometry/vector_lanes.h"

namespace mfz {

namespace {

// A loop step v0 -> v1 with v0 > v1: the twin side of the edge {v1, v0}.
struct TwinStep {
  long long key;  // smaller vertex * V + larger vertex
  int face;
};

long long edge_key(int low, int high, int vertex_count) {
  return static_cast<long long>(low) * vertex_count + high;
}

// Zeros past the last arc, up to the next whole four (ArcColumns).
void pad_to_lanes(ArcColumns& c, int count) {
  for (int i = count; i < lanes_of(count); ++i) {
    c.face_x[i] = c.face_y[i] = c.face_z[i] = 0;
    c.twin_x[i] = c.twin_y[i] = c.twin_z[i] = 0;
    c.across_x[i] = c.across_y[i] = c.across_z[i] = 0;
    c.v0_x[i] = c.v0_y[i] = c.v0_z[i] = 0;
  }
}

// Whether any of the first `count` arcs' circle normals is short enough
// for is_flat_arc to ask further: the least square in vector lanes, apart
// from the loop that writes the columns (folded into it, the test cost
// 128-point pairs 2.8% more instructions; apart and in plain lanes, 0.9%).
MFZ_VECTOR_LANES bool any_flat_circle(const ArcColumns& c, int count) {
  double least = std::numeric_limits<double>::infinity();
#pragma omp simd reduction(min : least)
  for (int i = 0; i < count; ++i) {
    const double x = c.across_x[i], y = c.across_y[i], z = c.across_z[i];
    const double square = (x * x + y * y) + z * z;
    least = square < least ? square : least;
  }
  return least <= kFlatArcRoom;
}

// write_columns' loop in vector lanes, from the turned normals (x y z of
// each face in turn) and the cached world vertices: the same values, and
// the same products for `across` as Vec3::cross, so the same bits. Arc by
// arc through Vec3s a column's arc took about 65 instructions, 26 here
// (g++ loads the gathered values one by one into the lanes): 32-point
// calls take 4.6% fewer instructions, 128-point calls 6% (stop 64).
MFZ_VECTOR_LANES void gather_columns(const ArcIndices* at, int count, const double* normals, const double* xs,
                                     const double* ys, const double* zs, ArcColumns& c) {
#pragma omp simd
  for (int i = 0; i < count; ++i) {
    const int face = 3 * at[i].face, twin = 3 * at[i].twin;
    const double px = normals[face], py = normals[face + 1], pz = normals[face + 2];
    const double qx = normals[twin], qy = normals[twin + 1], qz = normals[twin + 2];
    const int v = at[i].v0;
    c.face_x[i] = px, c.face_y[i] = py, c.face_z[i] = pz;
    c.twin_x[i] = qx, c.twin_y[i] = qy, c.twin_z[i] = qz;
    c.across_x[i] = qy * pz - qz * py, c.across_y[i] = qz * px - qx * pz, c.across_z[i] = qx * py - qy * px;
    c.v0_x[i] = xs[v], c.v0_y[i] = ys[v], c.v0_z[i] = zs[v];
  }
}

// write_edge_vectors' loop in vector lanes, from the cached world vertices:
// the same differences of the same values as world_vertex's.
MFZ_VECTOR_LANES void gather_edge_vectors(const ArcIndices* at, int count, const double* xs, const double* ys,
                                          const double* zs, EdgeVectors& e) {
#pragma omp simd
  for (int i = 0; i < count; ++i) {
    const int v0 = at[i].v0, v1 = at[i].v1;
    e.x[i] = xs[v1] - xs[v0], e.y[i] = ys[v1] - ys[v0], e.z[i] = zs[v1] - zs[v0];
  }
}

}  // namespace

void EdgeArcs::build(const PosedHull& hull) {
  count_ = 0;
  complete_ = false;
  if (hull.vertex_count() > kTopologyMaxVertices) return;
  if (!storage_) storage_ = std::make_unique<Storage>();
  ArcIndices* indices = storage_->indices;
  // The twins are known already for a hull whose topology is kept.
  if (const HullTopology* topology = hull.topology()) {
    count_ = topology->edge_count();
    for (int e = 0; e < count_; ++e) {
      const TopologyEdge& edge = topology->edge(e);
      indices[e] = {edge.v0, edge.v1, edge.face, edge.twin};
    }
  } else {
    for (int f = 0; f < hull.face_count(); ++f) {
      const int n = hull.face_size(f);
      for (int k = 0; k < n; ++k) {
        const int v0 = hull.face_vertex(f, k), v1 = hull.face_vertex(f, (k + 1) % n);
        if (v0 >= v1) continue;
        if (count_ == kMaxArcs) return;
        indices[count_++] = {v0, v1, f, -1};
      }
    }
    if (!pair_twins(hull)) return;
  }
  write_columns(hull);
  complete_ = true;
}

// Each arc's ends, circle and first vertex, in one loop over its indices.
// Each face's normal turned once, not once for each of its edges' ends: a
// face has three or more edges, each edge two faces. Written through a
// member function per arc and another for its twin, an arc took 88
// instructions (a 128-point call builds 756).
void EdgeArcs::write_columns(const PosedHull& hull) {
  hull.turn_face_normals();
  ArcColumns& c = storage_->columns;
  const double* normals = hull.turned_face_normals();
  if (normals && hull.has_world_columns()) {
    gather_columns(storage_->indices, count_, normals, hull.world_xs(), hull.world_ys(), hull.world_zs(), c);
  } else {
    write_columns_one_by_one(hull, c);
  }
  may_have_flat_ = any_flat_circle(c, count_);
  pad_to_lanes(c, count_);
}

void EdgeArcs::write_columns_one_by_one(const PosedHull& hull, ArcColumns& c) {
  for (int i = 0; i < count_; ++i) {
    const ArcIndices& at = storage_->indices[i];
    const Vec3 n_face = hull.world_face_normal(at.face), n_twin = hull.world_face_normal(at.twin);
    const Vec3 v = hull.world_vertex(at.v0), across = n_twin.cross(n_face);
    c.face_x[i] = n_face.x(), c.face_y[i] = n_face.y(), c.face_z[i] = n_face.z();
    c.twin_x[i] = n_twin.x(), c.twin_y[i] = n_twin.y(), c.twin_z[i] = n_twin.z();
    c.across_x[i] = across.x(), c.across_y[i] = across.y(), c.across_z[i] = across.z();
    c.v0_x[i] = v.x(), c.v0_y[i] = v.y(), c.v0_z[i] = v.z();
  }
}

void EdgeArcs::write_edge_vectors(const PosedHull& hull) {
  EdgeVectors& e = storage_->edges;
  if (hull.has_world_columns()) {
    gather_edge_vectors(storage_->indices, count_, hull.world_xs(), hull.world_ys(), hull.world_zs(), e);
    return;
  }
  for (int i = 0; i < count_; ++i) {
    const ArcIndices& at = storage_->indices[i];
    const Vec3 edge = hull.world_vertex(at.v1) - hull.world_vertex(at.v0);
    e.x[i] = edge.x(), e.y[i] = edge.y(), e.z[i] = edge.z();
  }
}

// With A's arc a -> b and B's negated c -> d: c . across_a times
// d . across_a (the ends of B's arc either side of A's circle), then
// a . across_b times b . across_b (A's either side of B's), then
// c . across_a times b . across_b (one crossing, not its antipode). Each is
// kept below the slack; the greatest of the three stands for them, so that
// the lanes hold doubles only.
namespace {

// Whether each of B's arcs (columns `k`) may cross A's arc: the greatest
// of the three products below `limit`, 1 or 0 in a word as wide as the
// lanes' doubles. Built for AVX2 and for any x86-64; file-local, as
// vector_lanes.h asks.
// Whole fours: with a scalar tail after the lanes, an 8-point hull's 18
// arcs took 280 instructions a row. The `count` arcs from `begin`, arc
// begin + j's flag in flags[j].
MFZ_VECTOR_LANES void crossing_flags(const ArcColumns& k, int begin, int count, const EdgeArc& arc_a, double limit,
                                     int64_t* flags) {
  const int lanes = lanes_of(count);
  if (lanes % kArcLanes != 0) __builtin_unreachable();
  const double ax = arc_a.across.x(), ay = arc_a.across.y(), az = arc_a.across.z();
  const double px = arc_a.n_face.x(), py = arc_a.n_face.y(), pz = arc_a.n_face.z();
  const double qx = arc_a.n_twin.x(), qy = arc_a.n_twin.y(), qz = arc_a.n_twin.z();
  const double *fx = k.face_x + begin, *fy = k.face_y + begin, *fz = k.face_z + begin;
  const double *tx = k.twin_x + begin, *ty = k.twin_y + begin, *tz = k.twin_z + begin;
  const double *cx = k.across_x + begin, *cy = k.across_y + begin, *cz = k.across_z + begin;
#pragma omp simd
  for (int j = 0; j < lanes; ++j) {
    const double c = fx[j] * ax + fy[j] * ay + fz[j] * az;
    const double d = tx[j] * ax + ty[j] * ay + tz[j] * az;
    const double a = cx[j] * px + cy[j] * py + cz[j] * pz;
    const double b = cx[j] * qx + cy[j] * qy + cz[j] * qz;
    flags[j] = std::max(std::max(c * d, a * b), c * b) < limit;
  }
}

// The flags of crossing_flags, gathered into indices, for the `arcs` arcs
// from `begin` (a whole four): of B's own arcs (`index` null), or of those
// keep_arcs kept (`index` from `begin`). At most kStretch arcs, so that
// the flags stay a kilobyte on the stack whatever the hull's size.
constexpr int kStretch = 128;
[[gnu::always_inline]] inline int gather_stretch(const ArcColumns& columns, int begin, int arcs, const int* index,
                                                 const EdgeArc& arc_a, int* out) {
  // The ends are unit vectors and so is |across| at most: each dot product
  // is within a few ulps of the test's own, and so is their product.
  constexpr double kLaneRounding = 1e-13;
  int64_t flags[kStretch + kArcLanes];
  crossing_flags(columns, begin, arcs, arc_a, tol::kGaussArcSlack + kLaneRounding, flags);
  std::fill(flags + arcs, flags + arcs + kArcLanes, 0);  // the padding's lanes too
  // Four arcs at a time: a row crosses a few of B's arcs, so most fours
  // have none. Taking every arc in turn, without a branch, was half the
  // test's time on 32-point hulls.
  int found = 0;
  for (int block = 0; block < arcs; block += 4) {
    if ((flags[block] | flags[block + 1] | flags[block + 2] | flags[block + 3]) == 0) continue;
    for (int j = block; j < block + 4; ++j)
      out[found] = index ? index[j] : begin + j, found += static_cast<int>(flags[j]);
  }
  return found;
}

// gather_stretch over all `count` arcs. Hulls of up to 44 vertices have
// at most kStretch arcs and take one stretch, in the code they took before
// larger hulls had arcs (a loop over stretches cost 8-point hulls 2.8%
// more instructions).
int gather_crossing(const ArcColumns& columns, int count, const int* index, const EdgeArc& arc_a, int* out) {
  if (count <= kStretch) return gather_stretch(columns, 0, count, index, arc_a, out);
  int found = 0;
  for (int begin = 0; begin < count; begin += kStretch)
    found += gather_stretch(columns, begin, std::min(kStretch, count - begin), index ? index + begin : nullptr, arc_a,
                            out + found);
  return found;
}

}  // namespace

int EdgeArcs::crossing(const EdgeArc& arc_a, int* out) const {
  return gather_crossing(storage_->columns, count_, nullptr, arc_a, out);
}

int crossing_among(const ArcColumns& kept, int count, const int* index, const EdgeArc& arc_a, int* out) {
  return gather_crossing(kept, count, index, arc_a, out);
}

int keep_arcs(const ArcColumns& all, int count, const bool* left_out, ArcColumns& kept, int* index) {
  int n = 0;
  for (int j = 0; j < count; ++j) {
    if (left_out[j]) continue;
    kept.face_x[n] = all.face_x[j], kept.face_y[n] = all.face_y[j], kept.face_z[n] = all.face_z[j];
    kept.twin_x[n] = all.twin_x[j], kept.twin_y[n] = all.twin_y[j], kept.twin_z[n] = all.twin_z[j];
    kept.across_x[n] = all.across_x[j], kept.across_y[n] = all.across_y[j], kept.across_z[n] = all.across_z[j];
    kept.v0_x[n] = all.v0_x[j], kept.v0_y[n] = all.v0_y[j], kept.v0_z[n] = all.v0_z[j];
    index[n++] = j;
  }
  pad_to_lanes(kept, n);
  return n;
}

// Sorting the twin steps pairs every edge with its other face in E log E.
bool EdgeArcs::pair_twins(const PosedHull& hull) {
  // Only hulls without a topology come here (malformed loops, or more
  // vertices than a topology takes): the steps of a 128-point hull fit.
  constexpr int kTwinSteps = 3 * kCachedVertices;
  TwinStep twins[kTwinSteps];
  int twin_count = 0;
  const int vertices = hull.vertex_count();
  for (int f = 0; f < hull.face_count(); ++f) {
    const int n = hull.face_size(f);
    for (int k = 0; k < n; ++k) {
      const int v0 = hull.face_vertex(f, k), v1 = hull.face_vertex(f, (k + 1) % n);
      if (v0 <= v1) continue;
      if (twin_count == kTwinSteps) return false;
      twins[twin_count++] = {edge_key(v1, v0, vertices), f};
    }
  }
  if (twin_count != count_) return false;
  std::sort(twins, twins + twin_count, [](const TwinStep& x, const TwinStep& y) { return x.key < y.key; });
  for (int i = 0; i < count_; ++i) {
    const long long key = edge_key(storage_->indices[i].v0, storage_->indices[i].v1, vertices);
    const TwinStep* found = std::lower_bound(twins, twins + twin_count, key,
                                             [](const TwinStep& t, long long k) { return t.key < k; });
    if (found == twins + twin_count || found->key != key) return false;
    storage_->indices[i].twin = found->face;
  }
  return true;
}

}  // namespace mfz

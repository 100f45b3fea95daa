// Bullet 3.24 as a manifuzz generator, in two of its paths:
//
//   bullet-sat  btPolyhedralContactClipping::findSeparatingAxis gives the
//               normal (SAT over face normals and edge pairs), then
//               clipHullAgainstHull clips B's incident face against A's
//               reference face (what btConvexConvexAlgorithm does with
//               btDispatcherInfo::m_enableSatConvex).
//   bullet      Bullet's default: btGjkPairDetector with
//               btGjkEpaPenetrationDepthSolver on the shapes with their
//               collision margin gives the normal and depth (margins taken
//               off again), then the same clipHullAgainstHull.
//
// Both feed their points through btPersistentManifold as btManifoldResult
// does (a point within the breaking threshold of a cached one replaces it;
// a fifth point evicts one, keeping the deepest and the largest area), so
// what the harness sees is what a Bullet user's solver sees.
//
// Built twice from this file: against Debian's libbullet (float) and
// libbullet-float64 (BT_USE_DOUBLE_PRECISION), so that every finding in the
// float build can be replayed against the same logic in double.
//
// Conventions mapped to the contract's (docs/peers.md):
//   - Bullet's normal is on B, pointing from B towards A: n = -normalOnB.
//   - Bullet's point is on B; the point on A is pointOnB + normalOnB * depth.
//   - Bullet's depth is signed, negative when overlapping: p_i = depth.
//   - The collision margin (Bullet's default 0.04 for a shape of unit size)
//     is 0.04 L; the breaking threshold is Bullet's relative one, 0.02 of the
//     shape's angular motion disc (at most 0.019 L for a shape about the
//     middle of its bounding box, as each hull is handed over): contacts up
//     to it before touching are reported, hence the profile's margin=0.02.
#include <BulletCollision/CollisionShapes/btConvexHullShape.h>
#include <BulletCollision/CollisionShapes/btConvexPolyhedron.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpaPenetrationDepthSolver.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkPairDetector.h>
#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>
#include <BulletCollision/NarrowPhaseCollision/btPolyhedralContactClipping.h>
#include <BulletCollision/NarrowPhaseCollision/btVoronoiSimplexSolver.h>

#include "../peer_plugin.h"

#ifndef BULLET_PEER_SAT
#error "define BULLET_PEER_SAT to 1 (bullet-sat) or 0 (bullet)"
#endif

namespace {

#ifdef BT_USE_DOUBLE_PRECISION
constexpr const char* kSuffix = "-double";
constexpr const char* kProfile = "max-contacts=4 margin=0.02";
#else
constexpr const char* kSuffix = "";
constexpr const char* kProfile = "precision=float max-contacts=4 margin=0.02";
#endif

/// Bullet's default collision margin (CONVEX_DISTANCE_MARGIN), for a shape
/// of unit size.
constexpr double kMarginPerL = 0.04;
/// gContactBreakingThreshold: the relative breaking threshold's factor.
constexpr double kBreakingFactor = 0.02;

btVector3 to_bt(const mfz_vec3& v) { return btVector3(btScalar(v.x), btScalar(v.y), btScalar(v.z)); }
mfz_vec3 from_bt(const btVector3& v) { return {double(v.x()), double(v.y()), double(v.z())}; }

btTransform to_bt(const mfz_pose& p) {
  const btQuaternion q(btScalar(p.orientation.x), btScalar(p.orientation.y), btScalar(p.orientation.z),
                       btScalar(p.orientation.w));
  return btTransform(q, to_bt(p.position));
}

/// The middle of a hull's bounding box: Bullet's shapes are built about it
/// (a Bullet user centres a shape; the breaking threshold, 0.02 of the
/// bounding sphere about the local origin, assumes it).
mfz_vec3 box_centre(const mfz_hull& h) {
  mfz_vec3 low = h.vertices[0], high = h.vertices[0];
  for (int i = 1; i < h.vertex_count; ++i) {
    const mfz_vec3& v = h.vertices[i];
    low = {std::min(low.x, v.x), std::min(low.y, v.y), std::min(low.z, v.z)};
    high = {std::max(high.x, v.x), std::max(high.y, v.y), std::max(high.z, v.z)};
  }
  return {0.5 * (low.x + high.x), 0.5 * (low.y + high.y), 0.5 * (low.z + high.z)};
}

/// The pose of a hull moved to be about `centre`: world = R (local' + c) + p.
btTransform centred_pose(const mfz_pose& p, const mfz_vec3& centre) {
  btTransform t = to_bt(p);
  t.setOrigin(t(to_bt(centre)));
  return t;
}

/// The harness's hull as Bullet's polyhedron, about `centre`: its vertices
/// and faces, each face's plane as Bullet stores it (n . x + d = 0);
/// initialize() finds the unique edge directions and the inner sphere and
/// box Bullet tests against.
void fill_polyhedron(const mfz_hull& h, const mfz_vec3& centre, btConvexPolyhedron& poly) {
  poly.m_vertices.resize(0);
  poly.m_faces.resize(0);
  poly.m_uniqueEdges.resize(0);
  for (int i = 0; i < h.vertex_count; ++i) {
    const mfz_vec3& v = h.vertices[i];
    poly.m_vertices.push_back(to_bt(mfz_vec3{v.x - centre.x, v.y - centre.y, v.z - centre.z}));
  }
  for (int f = 0; f < h.face_count; ++f) {
    btFace face;
    for (int k = h.face_offsets[f]; k < h.face_offsets[f + 1]; ++k) face.m_indices.push_back(h.face_vertices[k]);
    const btVector3 n = to_bt(h.face_normals[f]);
    const btVector3 on_face = poly.m_vertices[face.m_indices[0]];
    face.m_plane[0] = n.x();
    face.m_plane[1] = n.y();
    face.m_plane[2] = n.z();
    face.m_plane[3] = -n.dot(on_face);
    poly.m_faces.push_back(face);
  }
  poly.initialize();
}

/// btManifoldResult's addContactPoint, without the collision objects: the
/// breaking-threshold cut, then the persistent manifold's cache.
class ManifoldResult final : public btDiscreteCollisionDetectorInterface::Result {
 public:
  ManifoldResult(const btTransform& a, const btTransform& b, btScalar threshold)
      : a_(a), b_(b), manifold_(nullptr, nullptr, 0, threshold, threshold) {}
  void setShapeIdentifiersA(int, int) override {}
  void setShapeIdentifiersB(int, int) override {}
  void addContactPoint(const btVector3& normal_on_b, const btVector3& point_on_b, btScalar depth) override {
    if (depth > manifold_.getContactBreakingThreshold()) return;
    const btVector3 point_on_a = point_on_b + normal_on_b * depth;
    btManifoldPoint point(a_.invXform(point_on_a), b_.invXform(point_on_b), normal_on_b, depth);
    point.m_positionWorldOnA = point_on_a;
    point.m_positionWorldOnB = point_on_b;
    const int cached = manifold_.getCacheEntry(point);
    if (cached >= 0) manifold_.replaceContactPoint(point, cached);
    else manifold_.addManifoldPoint(point);
  }
  btPersistentManifold& manifold() { return manifold_; }

 private:
  btTransform a_, b_;
  btPersistentManifold manifold_;
};

/// GJK's answer with the margins taken off, as btConvexConvexAlgorithm's
/// btWithoutMarginResult keeps it.
class WithoutMarginResult final : public btDiscreteCollisionDetectorInterface::Result {
 public:
  explicit WithoutMarginResult(btScalar margins) : margins_(margins) {}
  void setShapeIdentifiersA(int, int) override {}
  void setShapeIdentifiersB(int, int) override {}
  void addContactPoint(const btVector3& normal_on_b, const btVector3&, btScalar depth) override {
    normal_on_b_ = normal_on_b;
    distance_ = depth + margins_;
    found_ = distance_ < 0;
  }
  bool found_ = false;
  btVector3 normal_on_b_{0, 0, 1};
  btScalar distance_ = 0;

 private:
  btScalar margins_;
};

/// Bullet's relative breaking threshold: 0.02 of the smaller angular motion
/// disc (the bounding sphere about the local origin, margin included).
btScalar breaking_threshold(const btConvexHullShape& a, const btConvexHullShape& b) {
  return btMin(a.getContactBreakingThreshold(btScalar(kBreakingFactor)),
               b.getContactBreakingThreshold(btScalar(kBreakingFactor)));
}

void write_manifold(btPersistentManifold& manifold, bool colliding, const btVector3& normal_on_b, btScalar depth,
                    mfz_manifold& out) {
  peer::clear(out);
  if (!colliding) return;
  out.colliding = 1;
  out.normal = from_bt(-normal_on_b);
  double deepest = 0;
  for (int i = 0; i < manifold.getNumContacts(); ++i) {
    const btManifoldPoint& p = manifold.getContactPoint(i);
    mfz_contact& c = out.contacts[out.contact_count++];
    c.point_on_a = from_bt(p.m_positionWorldOnA);
    c.point_on_b = from_bt(p.m_positionWorldOnB);
    c.penetration = double(p.getDistance());
    deepest = std::min(deepest, c.penetration);
  }
  // The SAT path has no depth of its own: Bullet's user reads the deepest point.
  out.penetration = BULLET_PEER_SAT ? deepest : std::min(0.0, double(depth));
}

}  // namespace

MFZ_PEER_EXPORT int32_t mfz_abi_version(void) { return MFZ_ABI_VERSION; }

MFZ_PEER_EXPORT const char* mfz_generator_name(void) {
  static const std::string name = std::string(BULLET_PEER_SAT ? "bullet-sat" : "bullet") + kSuffix;
  return name.c_str();
}

MFZ_PEER_EXPORT const char* mfz_generator_profile(void) { return kProfile; }

/// A hull as Bullet holds a shape: its polyhedron and its hull shape about
/// the bounding box's centre, and its diameter; built once per hull.
struct BulletHull {
  mfz_vec3 centre{};
  double diameter = 0;
  btConvexPolyhedron poly;
  std::unique_ptr<btConvexHullShape> shape;
  btScalar margin = -1;  ///< the margin its bounding box was last made with
};

void make_bullet_hull(const mfz_hull& h, BulletHull& out) {
  out.centre = box_centre(h);
  out.diameter = peer::diameter(h);
  fill_polyhedron(h, out.centre, out.poly);
  out.shape = std::make_unique<btConvexHullShape>(&out.poly.m_vertices[0].x(), out.poly.m_vertices.size(),
                                                  sizeof(btVector3));
}

/// The case's margin on a kept shape. setMargin leaves the cached bounding
/// box (made with the default 0.04) as it was: the breaking threshold is
/// read from it, so it is made again when the margin changes.
btConvexHullShape& with_margin(BulletHull& hull, btScalar margin) {
  if (hull.margin != margin) {
    hull.shape->setMargin(margin);
    hull.shape->recalcLocalAabb();
    hull.margin = margin;
  }
  return *hull.shape;
}

MFZ_PEER_EXPORT int32_t mfz_generate(const mfz_hull* a, const mfz_pose* pose_a, const mfz_hull* b,
                                     const mfz_pose* pose_b, mfz_manifold* out) {
  static thread_local peer::PreparedHulls<BulletHull> kept;
  kept.begin_call();
  BulletHull& hull_a = kept.get(*a, make_bullet_hull);
  BulletHull& hull_b = kept.get(*b, make_bullet_hull);
  const btTransform ta = centred_pose(*pose_a, hull_a.centre), tb = centred_pose(*pose_b, hull_b.centre);
  const btScalar margin = btScalar(kMarginPerL * std::max(hull_a.diameter, hull_b.diameter));
  const btConvexPolyhedron &poly_a = hull_a.poly, &poly_b = hull_b.poly;
  btConvexHullShape& shape_a = with_margin(hull_a, margin);
  btConvexHullShape& shape_b = with_margin(hull_b, margin);
  const btScalar threshold = breaking_threshold(shape_a, shape_b);

  btVector3 normal_on_b(0, 0, 1);
  btScalar min_distance = btScalar(-1e30);
  bool colliding = false;
  ManifoldResult result(ta, tb, threshold);
  if (BULLET_PEER_SAT) {
    // Given the manifold, as btConvexConvexAlgorithm gives it: on an edge
    // axis findSeparatingAxis adds the edges' closest points there itself.
    colliding = btPolyhedralContactClipping::findSeparatingAxis(poly_a, poly_b, ta, tb, normal_on_b, result);
  } else {
    btVoronoiSimplexSolver simplex;
    btGjkEpaPenetrationDepthSolver epa;
    btGjkPairDetector gjk(&shape_a, &shape_b, &simplex, &epa);
    btGjkPairDetector::ClosestPointInput input;
    input.m_transformA = ta;
    input.m_transformB = tb;
    const btScalar reach = 2 * margin + threshold;
    input.m_maximumDistanceSquared = reach * reach;
    WithoutMarginResult without_margin(2 * margin);
    gjk.getClosestPoints(input, without_margin, nullptr);
    colliding = without_margin.found_;
    normal_on_b = without_margin.normal_on_b_;
    min_distance = without_margin.distance_;
  }
  if (colliding) {
    btVertexArray clipped_1, clipped_2;
    btPolyhedralContactClipping::clipHullAgainstHull(normal_on_b, poly_a, poly_b, ta, tb, min_distance - threshold,
                                                    threshold, clipped_1, clipped_2, result);
    result.manifold().refreshContactPoints(ta, tb);
  }
  write_manifold(result.manifold(), colliding, normal_on_b, min_distance, *out);
  return 0;
}

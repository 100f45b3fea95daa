#include "geometry/hull.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "test_support.h"

namespace mfz {
namespace {

using test::box_points;

TEST(HullBuilding, CubeHasEightVerticesAndSixSquareFaces) {
  const HullBuild built = build_hull(box_points(1, 1, 1));
  ASSERT_TRUE(built.hull) << built.error;
  const Hull& h = *built.hull;
  EXPECT_EQ(h.vertex_count(), 8);
  EXPECT_EQ(h.face_count(), 6);
  EXPECT_EQ(h.edge_count(), 12);
  for (int f = 0; f < h.face_count(); ++f) {
    EXPECT_EQ(h.face_size(f), 4);
    EXPECT_NEAR(h.face_normal(f).cwiseAbs().maxCoeff(), 1.0, 1e-15);
    EXPECT_NEAR(h.face_offset(f), 1.0, 1e-15);
  }
  EXPECT_NEAR(h.diameter(), 2 * std::sqrt(3.0), 1e-15);
  EXPECT_EQ(validate_hull(h), "");
}

TEST(HullBuilding, FaceLoopsRunCounterClockwiseSeenFromOutside) {
  const Hull h = *build_hull(box_points(1, 2, 3)).hull;
  for (int f = 0; f < h.face_count(); ++f) {
    const Vec3 a = h.vertex(h.face_vertex(f, 0)), b = h.vertex(h.face_vertex(f, 1)), c = h.vertex(h.face_vertex(f, 2));
    EXPECT_GT((b - a).cross(c - b).dot(h.face_normal(f)), 0) << "face " << f;
  }
}

TEST(HullBuilding, EveryEdgeHasALeftAndARightFace) {
  const Hull h = *build_hull(box_points(1, 1, 1)).hull;
  for (const HullEdge& e : h.edges()) {
    EXPECT_GE(e.face_left, 0);
    EXPECT_GE(e.face_right, 0);
    EXPECT_NE(e.face_left, e.face_right);
  }
}

TEST(HullBuilding, TetrahedronHasFourTriangles) {
  const HullBuild built = build_hull(test::tetrahedron_points());
  ASSERT_TRUE(built.hull) << built.error;
  EXPECT_EQ(built.hull->vertex_count(), 4);
  EXPECT_EQ(built.hull->face_count(), 4);
  for (int f = 0; f < 4; ++f) EXPECT_EQ(built.hull->face_size(f), 3);
}

TEST(HullBuilding, DuplicateAndInteriorPointsAreDropped) {
  std::vector<Vec3> points = box_points(1, 1, 1);
  points.push_back(points[0]);
  points.push_back(points[3]);
  points.emplace_back(0.1, 0.2, -0.3);  // interior
  const HullBuild built = build_hull(points);
  ASSERT_TRUE(built.hull) << built.error;
  EXPECT_EQ(built.hull->vertex_count(), 8);
  EXPECT_EQ(built.hull->face_count(), 6);
}

TEST(HullBuilding, PointsOnEdgesAndFacesAreNotVertices) {
  std::vector<Vec3> points = box_points(1, 1, 1);
  points.emplace_back(0, 1, 1);  // middle of an edge
  points.emplace_back(0, 0, 1);  // centre of a face
  points.emplace_back(1, 0.25, -0.5);  // inside a face
  const HullBuild built = build_hull(points);
  ASSERT_TRUE(built.hull) << built.error;
  EXPECT_EQ(built.hull->vertex_count(), 8);
  EXPECT_EQ(built.hull->face_count(), 6);
  EXPECT_EQ(validate_hull(*built.hull), "");
}

TEST(HullBuilding, CoplanarTrianglesMergeIntoOneFace) {
  // An octagonal prism: the caps arrive from Qhull as fans of triangles.
  std::vector<Vec3> points;
  for (int k = 0; k < 8; ++k) {
    const double t = k * M_PI / 4;
    points.emplace_back(std::cos(t), std::sin(t), -0.5);
    points.emplace_back(std::cos(t), std::sin(t), 0.5);
  }
  const HullBuild built = build_hull(points);
  ASSERT_TRUE(built.hull) << built.error;
  EXPECT_EQ(built.hull->face_count(), 10);
  int caps = 0;
  for (int f = 0; f < built.hull->face_count(); ++f) caps += built.hull->face_size(f) == 8;
  EXPECT_EQ(caps, 2);
}

TEST(HullBuilding, FewerThanFourPointsIsAnError) {
  const HullBuild built = build_hull({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
  EXPECT_FALSE(built.hull);
  EXPECT_NE(built.error.find("fewer than four"), std::string::npos) << built.error;
}

TEST(HullBuilding, NanOrInfIsAnError) {
  std::vector<Vec3> points = box_points(1, 1, 1);
  points[2].y() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(build_hull(points).hull);
  points[2].y() = std::numeric_limits<double>::infinity();
  const HullBuild built = build_hull(points);
  EXPECT_FALSE(built.hull);
  EXPECT_NE(built.error.find("NaN"), std::string::npos) << built.error;
}

// O20: a tetrahedron 3e78 long is past what a generator's squared cross
// products of edges can hold; 1e30 is the limit, and a hull at it builds.
TEST(HullBuilding, ACoordinatePastTheLimitIsAnErrorAndOneAtItBuilds) {
  std::vector<Vec3> points = box_points(1, 1, 1);
  for (Vec3& p : points) p *= 1e30;
  EXPECT_TRUE(build_hull(points).hull);
  points[5].z() = -3e30;
  const HullBuild built = build_hull(points);
  EXPECT_FALSE(built.hull);
  EXPECT_NE(built.error.find("coordinate of 3e+30 is past the limit"), std::string::npos) << built.error;
}

TEST(HullBuilding, CoplanarCloudIsAnError) {
  const HullBuild built = build_hull({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0.5, 0.5, 0}});
  EXPECT_FALSE(built.hull);
  EXPECT_NE(built.error.find("plane"), std::string::npos) << built.error;
}

TEST(HullBuilding, CloudThinnerThanTheFlatnessToleranceIsAnError) {
  EXPECT_FALSE(build_hull({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 1e-12}}).hull);
  EXPECT_TRUE(build_hull({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 1e-6}}).hull);
}

TEST(HullBuilding, CollinearAndCoincidentPointsAreErrors) {
  EXPECT_FALSE(build_hull({{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}}).hull);
  EXPECT_FALSE(build_hull({{1, 2, 3}, {1, 2, 3}, {1, 2, 3}, {1, 2, 3}}).hull);
}

// A cloud 1e-129 across, which Qhull closes with facets whose corners are
// all dropped as not extreme, one face left with none: an error, named,
// and nothing read past the loops. Taking each face's plane offset from its
// first corner, stop 67's hull read a corner the empty face does not have
// (a heap overflow under ASan; a SEGV in the fuzzer, manifold_fuzzer from
// an empty corpus at -max_len=500).
TEST(HullBuilding, ACloudWhoseFacesLoseEveryCornerIsAnErrorNotARead) {
  const HullBuild built = build_hull({{-3.0648456941657976e-289, 1.8018255209656384e-129, 1.801936811432483e-129},
                                      {-3.064529257580044e-289, 1.8018255209656384e-129, 1.8018255910480497e-129},
                                      {-3.0648456941657985e-289, 1.8018255209656384e-129, 1.8018255910480497e-129},
                                      {1.8019367571256548e-129, 1.8019367571256548e-129, 1.8019367571256548e-129},
                                      {1.8018255367412212e-129, 1.8019367571256548e-129, 1.8018255367412212e-129},
                                      {1.8018255367412212e-129, 1.8018255367412212e-129, 1.8019367571256548e-129},
                                      {1.2671712263056725e-143, 1.8018255209656345e-129, 1.8018255910480375e-129}});
  EXPECT_FALSE(built.hull);
  EXPECT_EQ(built.error, "invalid hull: fewer than four vertices or faces");
}

// Each edge's left face holds the step v0 -> v1, its right face v1 -> v0.
void expect_edges_match_loops(const Hull& h) {
  const auto holds_step = [&](int f, int from, int to) {
    for (int k = 0; k < h.face_size(f); ++k)
      if (h.face_vertex(f, k) == from && h.face_vertex(f, (k + 1) % h.face_size(f)) == to) return true;
    return false;
  };
  for (const HullEdge& e : h.edges()) {
    EXPECT_TRUE(holds_step(e.face_left, e.v0, e.v1));
    EXPECT_TRUE(holds_step(e.face_right, e.v1, e.v0));
  }
}

TEST(HullRenumbering, IsTheSamePolyhedronWithEveryIndexMoved) {
  const Hull h = *build_hull(test::tetrahedron_points()).hull;
  const Hull r = h.renumbered();
  EXPECT_EQ(validate_hull(r), "");
  expect_edges_match_loops(r);
  ASSERT_EQ(r.vertex_count(), h.vertex_count());
  ASSERT_EQ(r.face_count(), h.face_count());
  const int last = h.vertex_count() - 1;
  for (int i = 0; i <= last; ++i) EXPECT_EQ(r.vertex(i), h.vertex(last - i));
  for (int f = 0; f < h.face_count(); ++f) {
    const int g = h.face_count() - 1 - f;
    EXPECT_EQ(r.face_normal(g), h.face_normal(f));
    EXPECT_EQ(r.face_vertex(g, 0), last - h.face_vertex(f, 1)) << "each loop starts one vertex later";
  }
  EXPECT_EQ(r.diameter(), h.diameter());
}

TEST(HullScaling, ScalesVerticesAndDiameterAndKeepsTheFaces) {
  const Hull h = *build_hull(box_points(1, 2, 3)).hull;
  const Hull s = h.scaled(2);
  EXPECT_EQ(validate_hull(s), "");
  expect_edges_match_loops(s);
  for (int i = 0; i < h.vertex_count(); ++i) EXPECT_EQ(s.vertex(i), 2 * h.vertex(i));
  EXPECT_EQ(s.diameter(), 2 * h.diameter());
  EXPECT_NEAR(s.face_offset(0), 2 * h.face_offset(0), 1e-15);
}

TEST(HullMeasures, ShortestEdgeAndSharpestCornerOfABox) {
  const Hull h = *build_hull(box_points(1, 2, 3)).hull;
  EXPECT_EQ(h.shortest_edge(), 2);  // box_points gives half-extents
  EXPECT_EQ(h.sharpest_corner(), 1);  // every corner square
  const Hull s = h.scaled(0.5);
  EXPECT_EQ(s.shortest_edge(), 1) << "a scaled hull measures its own shape";
  EXPECT_EQ(h.renumbered().shortest_edge(), 2);
}

// The same hull assembled again from its vertices, loops and normals: its
// measures taken afresh.
Hull measured_again(const Hull& h) {
  std::vector<Vec3> vertices, normals;
  std::vector<std::vector<int>> loops(static_cast<size_t>(h.face_count()));
  for (int i = 0; i < h.vertex_count(); ++i) vertices.push_back(h.vertex(i));
  for (int f = 0; f < h.face_count(); ++f) {
    normals.push_back(h.face_normal(f));
    for (int k = 0; k < h.face_size(f); ++k) loops[f].push_back(h.face_vertex(f, k));
  }
  return Hull::from_faces(vertices, loops, normals);
}

// Renumbering copies the measures rather than taking them again: they must
// be what taking them again gives, to the bit.
TEST(HullMeasures, ARenumberedHullKeepsTheMeasuresItWouldTakeAgain) {
  for (unsigned seed = 1; seed <= 20; ++seed) {
    const Hull r = build_hull(test::sphere_points(6 + static_cast<int>(seed), seed)).hull->renumbered();
    const Hull again = measured_again(r);
    EXPECT_EQ(r.shortest_edge(), again.shortest_edge()) << "seed " << seed;
    EXPECT_EQ(r.sharpest_corner(), again.sharpest_corner()) << "seed " << seed;
    EXPECT_EQ(r.diameter(), again.diameter()) << "seed " << seed;
  }
}

// Scaling by a power of two copies the measures, scaled, rather than taking
// them again; by any other factor it takes them again, and so it does where
// the squared lengths would leave the normal doubles (2^-530: subnormal;
// 2^515: past the largest), which round apart from the copied measures.
TEST(HullMeasures, AScaledHullHasTheMeasuresItWouldTakeAgain) {
  for (unsigned seed = 1; seed <= 20; ++seed)
    for (const double s : {2.0, 0.5, 0x1p40, 0x1p-30, 3.0, 0.1, 0x1p-530, 0x1p515}) {
      const Hull scaled = build_hull(test::sphere_points(6 + static_cast<int>(seed), seed)).hull->scaled(s);
      const Hull again = measured_again(scaled);
      EXPECT_EQ(scaled.shortest_edge(), again.shortest_edge()) << "seed " << seed << ", scale " << s;
      EXPECT_EQ(scaled.sharpest_corner(), again.sharpest_corner()) << "seed " << seed << ", scale " << s;
    }
}

// Each face's plane offset is taken once, as the hull is made: its normal
// dotted with its loop's first vertex. A renumbered hull's loops start one
// vertex later and a scaled hull's vertices move, so each takes its own,
// and they are those of the same hull made again, to the bit.
TEST(HullMeasures, FaceOffsetsAreThePlanesThroughEachLoopsFirstVertex) {
  for (unsigned seed = 1; seed <= 20; ++seed) {
    const Hull h = *build_hull(test::sphere_points(6 + static_cast<int>(seed), seed)).hull;
    for (const Hull& made : {h, h.renumbered(), h.scaled(2), h.scaled(0.1), fan_triangulated(h)}) {
      const Hull again = measured_again(made);
      ASSERT_EQ(made.face_count(), again.face_count());
      for (int f = 0; f < made.face_count(); ++f) {
        EXPECT_EQ(made.face_offset(f), made.face_normal(f).dot(made.vertex(made.face_vertex(f, 0))))
            << "seed " << seed << ", face " << f;
        EXPECT_EQ(made.face_offset(f), again.face_offset(f)) << "seed " << seed << ", face " << f;
        EXPECT_EQ(made.face_offsets()[f], made.face_offset(f));
      }
    }
  }
}

TEST(HullMeasures, TheSharpestCornerIsTheSineOfTheSmallestFaceAngle) {
  // A wedge whose slanted faces meet the base at corners of 0.1 rad.
  const double t = std::tan(0.1);
  const Hull h = *build_hull({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0, 0, t}, {0, 1, t}}).hull;
  EXPECT_NEAR(h.sharpest_corner(), std::sin(0.1), 1e-12);
}

TEST(HullCopies, ShareTheShapeAndAHullMovedFromKeepsIt) {
  Hull h = *build_hull(box_points(1, 1, 1)).hull;
  const Hull copy = h;
  EXPECT_EQ(copy.view().vertices, h.view().vertices) << "a copy shares the arrays";
  const Hull moved = std::move(h);
  EXPECT_EQ(h.vertex_count(), 8);  // NOLINT(bugprone-use-after-move): the point of the test
  EXPECT_EQ(moved.vertex_count(), 8);
  EXPECT_EQ(h.scaled(2).view().vertices == h.view().vertices, false) << "scaling copies the arrays";
}

TEST(HullValidation, RejectsAFlippedFaceLoop) {
  // A tetrahedron with one face's loop reversed: that edge pair no longer matches.
  const std::vector<Vec3> v = test::tetrahedron_points();
  const Hull good = *build_hull(v).hull;
  std::vector<std::vector<int>> loops;
  std::vector<Vec3> normals;
  for (int f = 0; f < good.face_count(); ++f) {
    loops.push_back({good.face_vertex(f, 0), good.face_vertex(f, 1), good.face_vertex(f, 2)});
    normals.push_back(good.face_normal(f));
  }
  std::swap(loops[0][1], loops[0][2]);
  std::vector<Vec3> vertices;
  for (int i = 0; i < good.vertex_count(); ++i) vertices.push_back(good.vertex(i));
  const std::string why = validate_hull(Hull::from_faces(vertices, loops, normals));
  EXPECT_NE(why.find("is not shared by exactly two faces"), std::string::npos) << why;
}

TEST(HullValidation, RejectsAnOpenHullByItsUnsharedEdges) {
  // A box with its last face left out: no step repeats, but the rim's steps
  // have no reverse.
  const Hull good = *build_hull(box_points(1, 1, 1)).hull;
  std::vector<std::vector<int>> loops;
  std::vector<Vec3> normals;
  for (int f = 0; f + 1 < good.face_count(); ++f) {
    loops.emplace_back();
    for (int k = 0; k < good.face_size(f); ++k) loops.back().push_back(good.face_vertex(f, k));
    normals.push_back(good.face_normal(f));
  }
  std::vector<Vec3> vertices;
  for (int i = 0; i < good.vertex_count(); ++i) vertices.push_back(good.vertex(i));
  const std::string why = validate_hull(Hull::from_faces(vertices, loops, normals));
  EXPECT_NE(why.find("is not shared by exactly two faces"), std::string::npos) << why;
}

TEST(HullValidation, RejectsANonConvexVertex) {
  const Hull good = *build_hull(box_points(1, 1, 1)).hull;
  std::vector<Vec3> vertices;
  for (int i = 0; i < good.vertex_count(); ++i) vertices.push_back(good.vertex(i));
  vertices[0] *= 0.5;  // pull one corner in: its faces are no longer planar
  std::vector<std::vector<int>> loops;
  std::vector<Vec3> normals;
  for (int f = 0; f < good.face_count(); ++f) {
    loops.emplace_back();
    for (int k = 0; k < good.face_size(f); ++k) loops.back().push_back(good.face_vertex(f, k));
    normals.push_back(good.face_normal(f));
  }
  EXPECT_NE(validate_hull(Hull::from_faces(vertices, loops, normals)), "");
}

}  // namespace
}  // namespace mfz

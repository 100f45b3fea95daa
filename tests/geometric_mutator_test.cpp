#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <stdexcept>

#include "case/scene.h"
#include "families.h"
#include "geometric_mutator.h"
#include "oracles/exact_depth.h"

namespace mfz::props {
namespace {

bool decodes(const FuzzCase& c) {
  const std::vector<uint8_t> bytes = encode_fuzz_input(c);
  return decode_fuzz_input(bytes.data(), bytes.size()).has_value();
}

const Mutation& mutation(const std::string& name) {
  for (const Mutation& m : geometric_mutations())
    if (m.name == name) return m;
  throw std::invalid_argument(name);
}

double exact_signed_depth_over_l(const CaseFile& c) {
  const SceneBuild built = make_scene(c);
  if (!built.scene) return NAN;
  return exact_depth(*built.scene, rank_sat_axes(*built.scene)).signed_depth / built.scene->scale;
}

TEST(GeometricMutator, EveryMutationKeepsACaseTheFuzzerCanRead) {
  for (const Mutation& m : geometric_mutations())
    for (uint64_t seed = 1; seed <= 40; ++seed) {
      FuzzCase c = draw_fuzz_case(seed);
      MutationRandom random(seed);
      m.apply(c, random);
      EXPECT_TRUE(decodes(c)) << m.name << ", seed " << seed;
    }
}

TEST(GeometricMutator, SlidingToTouchingLeavesTheHullsTouchingOrJustOverlapping) {
  int touching = 0, tried = 0;
  for (uint64_t seed = 1; seed <= 40; ++seed) {
    FuzzCase c = draw_fuzz_case(seed);
    if (!make_scene(c.file).scene) continue;
    MutationRandom random(seed);
    ASSERT_TRUE(mutation("slide-to-touching").apply(c, random));
    const double depth = exact_signed_depth_over_l(c.file);
    ++tried;
    EXPECT_GE(depth, -1e-9) << "seed " << seed;  // never pushed apart
    EXPECT_LE(depth, 0.1 + 1e-9) << "seed " << seed;
    if (std::abs(depth) <= 1e-9) ++touching;
  }
  EXPECT_GT(tried, 20);
  EXPECT_GT(touching, tried / 3);
}

TEST(GeometricMutator, FoldingAFaceMovesOnePointOffItsPlane) {
  for (uint64_t seed = 1; seed <= 20; ++seed) {
    FuzzCase c = draw_fuzz_case(seed);
    const FuzzCase before = c;
    MutationRandom random(seed);
    if (!mutation("fold-face").apply(c, random)) continue;
    int moved = 0;
    for (size_t i = 0; i < c.file.points_a.size(); ++i) moved += c.file.points_a[i] != before.file.points_a[i];
    for (size_t i = 0; i < c.file.points_b.size(); ++i) moved += c.file.points_b[i] != before.file.points_b[i];
    EXPECT_GE(moved, 1) << "seed " << seed;
  }
}

TEST(GeometricMutator, MovingFarKeepsTheRelativePose) {
  FuzzCase c = draw_fuzz_case(7);
  const Vec3 offset = c.file.pose_b.position - c.file.pose_a.position;
  MutationRandom random(7);
  ASSERT_TRUE(mutation("move-far").apply(c, random));
  EXPECT_GT(c.file.pose_a.position.norm(), 10.0);
  EXPECT_LE((c.file.pose_b.position - c.file.pose_a.position - offset).norm(), 1e-6 * c.file.pose_a.position.norm());
}

TEST(GeometricMutator, TheNamesAreOneTableAndEachIsDrawn) {
  std::set<std::string> drawn;
  for (uint64_t seed = 1; seed <= 400; ++seed) {
    FuzzCase c = draw_fuzz_case(seed % 30 + 1);
    MutationRandom random(seed);
    drawn.insert(mutate_geometrically(c, random));
  }
  for (const Mutation& m : geometric_mutations()) EXPECT_TRUE(drawn.count(m.name)) << m.name;
}

TEST(GeometricMutator, ACrossOverTakesItsHullsFromItsParents) {
  const FuzzCase x = draw_fuzz_case(3), y = draw_fuzz_case(4);
  for (uint64_t seed = 1; seed <= 10; ++seed) {
    MutationRandom random(seed);
    const FuzzCase child = cross_over(x, y, random);
    EXPECT_TRUE(child.file.points_a == x.file.points_a || child.file.points_a == y.file.points_a);
    EXPECT_TRUE(child.file.points_b == x.file.points_b || child.file.points_b == y.file.points_b);
  }
}

TEST(SeedInputs, OneValidInputForEveryHullFamilyTheSameEachTime) {
  const auto inputs = seed_inputs();
  EXPECT_EQ(inputs.size(), hull_family_names().size());
  for (const auto& [name, bytes] : inputs) {
    const auto c = decode_fuzz_input(bytes.data(), bytes.size());
    ASSERT_TRUE(c) << name;
    EXPECT_TRUE(make_scene(c->file).scene) << name;
  }
  EXPECT_EQ(seed_inputs(), inputs);
}

}  // namespace
}  // namespace mfz::props

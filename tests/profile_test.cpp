// Profiles: what each key relaxes, and that it relaxes only that, by the
// amount it names. Each relaxation is shown both ways: the wrong manifold
// fails without the profile (or with a smaller amount) and passes with it.
#include "harness/profile.h"

#include <gtest/gtest.h>

#include <cfloat>

#include "harness/invariants.h"
#include "test_support.h"

namespace mfz {
namespace {

using test::box_points;

Profile parsed(const std::string& text) {
  std::string error;
  const auto p = parse_profile(text, error);
  EXPECT_TRUE(p) << error;
  return p.value_or(Profile{});
}

std::string parse_error(const std::string& text) {
  std::string error;
  EXPECT_FALSE(parse_profile(text, error)) << text;
  return error;
}

TEST(ProfileText, ReadsEveryKeyAndWritesItBack) {
  const Profile p = parsed("precision=float max-contacts=4 face-bias=0.05 margin=0.01");
  EXPECT_EQ(p.precision_epsilon, FLT_EPSILON);
  EXPECT_EQ(p.max_contacts, 4);
  EXPECT_EQ(p.face_bias, 0.05);
  EXPECT_EQ(p.margin, 0.01);
  EXPECT_EQ(p.text(), "precision=float max-contacts=4 face-bias=0.05 margin=0.01");
  EXPECT_EQ(parsed("").text(), "none");
  EXPECT_TRUE(parsed("precision=double").empty());
}

TEST(ProfileText, RefusesUnknownRepeatedAndOutOfRangeKeysInOneLine) {
  EXPECT_NE(parse_error("precision=half").find("float or double"), std::string::npos);
  EXPECT_NE(parse_error("max-contacts=0").find("1 to 64"), std::string::npos);
  EXPECT_NE(parse_error("max-contacts=65").find("1 to 64"), std::string::npos);
  EXPECT_NE(parse_error("max-contacts=2.5").find("whole number"), std::string::npos);
  EXPECT_NE(parse_error("face-bias=nan").find("0 to 1"), std::string::npos);
  EXPECT_NE(parse_error("margin=-0.1").find("0 to 1"), std::string::npos);
  EXPECT_NE(parse_error("margin=0.1 margin=0.2").find("twice"), std::string::npos);
  EXPECT_NE(parse_error("stiffness=3").find("unknown key"), std::string::npos);
  EXPECT_NE(parse_error("margin").find("key=value"), std::string::npos);
  for (const std::string& e : {parse_error("stiffness=3"), parse_error("margin=")})
    EXPECT_EQ(e.find('\n'), std::string::npos);
}

TEST(ProfileInForce, CommandLineKeysReplaceDeclaredOnesAndNoneClearsThem) {
  std::string error;
  const auto kept = profile_in_force("precision=float max-contacts=4", std::string("max-contacts=8"), error);
  ASSERT_TRUE(kept) << error;
  EXPECT_EQ(kept->text(), "precision=float max-contacts=8");
  const auto cleared = profile_in_force("precision=float max-contacts=4", std::string("none"), error);
  ASSERT_TRUE(cleared) << error;
  EXPECT_TRUE(cleared->empty());
  EXPECT_FALSE(profile_in_force("precision=quad", std::nullopt, error));
  EXPECT_NE(error.find("declares a profile"), std::string::npos);
  EXPECT_FALSE(profile_in_force("", std::string("precision=quad"), error));
  EXPECT_EQ(error.rfind("--profile", 0), 0u) << error;
}

CheckStatus status_of(const CaseRun& run, const mfz_manifold& m, const std::string& name, const Profile& profile) {
  Scene scene = run.scene;
  scene.precision_epsilon = profile.precision_epsilon;
  for (const InvariantCheck& c : check_manifold(scene, run.oracles, 0, m, profile).checks)
    if (c.name == name) return c.status;
  ADD_FAILURE() << "no check named " << name;
  return CheckStatus::skipped;
}

// B, a unit cube, rests 0.1 deep on the 4 x 4 x 1 slab A: n = +z, four contacts.
CaseRun resting_box() {
  return test::run_builtin(test::make_case(box_points(2, 2, 0.5), {}, box_points(0.5, 0.5, 0.5),
                                           {Vec3(0, 0, 0.9), Quat::Identity()}));
}

TEST(ProfileRelaxes, PrecisionFloatAcceptsFloatRoundingButNotAWrongPoint) {
  const CaseRun run = resting_box();
  mfz_manifold m = run.manifold;
  const double L = run.scene.scale;
  m.contacts[0].point_on_a.z += 2e-6 * L;  // a few float ulps off A's top face
  m.contacts[0].point_on_b.z += 2e-6 * L;
  EXPECT_EQ(status_of(run, m, "on-surface", {}), CheckStatus::fail);
  EXPECT_EQ(status_of(run, m, "on-surface", parsed("precision=float")), CheckStatus::pass);
  m.contacts[0].point_on_a.z += 1e-3 * L;  // a fault, not rounding
  m.contacts[0].point_on_b.z += 1e-3 * L;
  EXPECT_EQ(status_of(run, m, "on-surface", parsed("precision=float")), CheckStatus::fail);
}

TEST(ProfileRelaxes, MaxContactsIsAPromiseTheHarnessHolds) {
  const CaseRun run = resting_box();
  ASSERT_EQ(run.manifold.contact_count, 4);
  EXPECT_EQ(status_of(run, run.manifold, "finite", parsed("max-contacts=4")), CheckStatus::pass);
  EXPECT_EQ(status_of(run, run.manifold, "finite", parsed("max-contacts=3")), CheckStatus::fail);
}

// The normal is the slab's face; a depth 2% past the exact one is what a
// face-biased generator reports when it prefers a face axis that much
// shallower than the best, and the contract's 1e-9 L refuses it.
TEST(ProfileRelaxes, FaceBiasAcceptsAFaceAxisWithinItsFractionOnly) {
  const CaseRun run = resting_box();
  mfz_manifold m = run.manifold;
  const double exact = run.oracles.exact.signed_depth;
  m.penetration = -1.02 * exact;
  for (int i = 0; i < m.contact_count; ++i) m.contacts[i].penetration = std::max(m.contacts[i].penetration, m.penetration);
  EXPECT_EQ(status_of(run, m, "depth-exact", {}), CheckStatus::fail);
  EXPECT_EQ(status_of(run, m, "depth-exact", parsed("face-bias=0.05")), CheckStatus::pass);
  EXPECT_EQ(status_of(run, m, "depth-exact", parsed("face-bias=0.01")), CheckStatus::fail);
  // A depth below the exact one is never a bias.
  m.penetration = -0.98 * exact;
  EXPECT_EQ(status_of(run, m, "depth-exact", parsed("face-bias=0.05")), CheckStatus::fail);
}

// The cube hovers 0.005 above the slab (L = 4.24): a margin engine reports it
// colliding with the gap as a positive penetration.
TEST(ProfileRelaxes, MarginAcceptsContactsBeforeTouchingWithinItsDistanceOnly) {
  const CaseRun run = test::run_builtin(test::make_case(box_points(2, 2, 0.5), {}, box_points(0.5, 0.5, 0.5),
                                                        {Vec3(0, 0, 1.005), Quat::Identity()}));
  ASSERT_FALSE(run.oracles.exact.colliding);
  const double gap = -run.oracles.exact.signed_depth, L = run.scene.scale;
  mfz_manifold m = run.manifold;
  m.colliding = 1;
  m.normal = {0, 0, 1};
  m.penetration = gap;
  m.contact_count = 1;
  m.contacts[0] = {{0.5, 0.5, 0.5}, {0.5, 0.5, 0.5 + gap}, gap};
  for (const char* name : {"agrees-with-gjk", "negative-penetration"}) {
    EXPECT_EQ(status_of(run, m, name, {}), CheckStatus::fail) << name;
    EXPECT_EQ(status_of(run, m, name, parsed("margin=0.01")), CheckStatus::pass) << name;
    EXPECT_EQ(status_of(run, m, name, parsed("margin=" + std::to_string(0.5 * gap / L))), CheckStatus::fail) << name;
  }
}

// A margin engine overlapping by the resting box's 0.1 still keeps an
// incident point that lies a little above the reference face (Bullet's clip
// keeps points up to its breaking threshold): a contact's positive distance
// within the margin passes, past it or without a margin it fails.
TEST(ProfileRelaxes, MarginAcceptsAContactAboveTheReferenceFaceOfAnOverlappingCase) {
  const CaseRun run = resting_box();
  ASSERT_TRUE(run.oracles.exact.colliding);
  const double L = run.scene.scale, above = 0.005 * L;
  mfz_manifold m = run.manifold;
  mfz_contact& c = m.contacts[0];
  c.point_on_b = {c.point_on_a.x, c.point_on_a.y, c.point_on_a.z + above};
  c.penetration = above;
  EXPECT_EQ(status_of(run, m, "negative-penetration", {}), CheckStatus::fail);
  EXPECT_EQ(status_of(run, m, "negative-penetration", parsed("margin=0.01")), CheckStatus::pass);
  EXPECT_EQ(status_of(run, m, "negative-penetration", parsed("margin=0.004")), CheckStatus::fail);
}

TEST(ProfileReport, EachCheckSaysWhatTheProfileAddedToItsTolerance) {
  const CaseRun run = resting_box();
  Scene scene = run.scene;
  scene.precision_epsilon = FLT_EPSILON;
  for (const InvariantCheck& c : check_manifold(scene, run.oracles, 0, run.manifold, parsed("precision=float")).checks)
    if (c.name == "depth-exact" || c.name == "on-surface") {
      EXPECT_GT(c.profile_share, 0) << c.name;
      EXPECT_LE(c.profile_share, c.tolerance) << c.name;
    }
  for (const InvariantCheck& c : check_manifold(run.scene, run.oracles, 0, run.manifold).checks)
    EXPECT_EQ(c.profile_share, 0) << c.name;
}

}  // namespace
}  // namespace mfz

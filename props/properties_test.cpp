// The property suite under GoogleTest: one RapidCheck property per invariant
// and relation of the contract, over every case family, against the generator
// named by MANIFUZZ_GENERATOR (default: builtin). A failure prints the shrunk
// case as a case file, writes it to failures/<name>.case (the last write is
// the smallest), and RapidCheck prints the RC_PARAMS line that replays it.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "case_property.h"
#include "families.h"

namespace rc {
template <>
struct Arbitrary<mfz::props::GeneratedCase> {
  static Gen<mfz::props::GeneratedCase> arbitrary() { return mfz::props::any_case(); }
};
}  // namespace rc

namespace mfz::props {
namespace {

GeneratorSession& generator_under_test() {
  static const std::unique_ptr<GeneratorSession> session = [] {
    const char* spec = std::getenv("MANIFUZZ_GENERATOR");
    std::string error;
    auto s = open_session(spec && *spec ? spec : "builtin", 5, error);
    if (!s) {
      std::fprintf(stderr, "MANIFUZZ_GENERATOR: %s\n", error.c_str());
      std::exit(2);
    }
    return s;
  }();
  return *session;
}

// The built-in generator is held to the strict level (one canonical answer
// even in a tie); a plugin named by MANIFUZZ_GENERATOR to the contract's,
// unless MANIFUZZ_LEVEL=strict.
Level level_under_test() {
  const char* spec = std::getenv("MANIFUZZ_GENERATOR");
  const char* level = std::getenv("MANIFUZZ_LEVEL");
  if (level && std::string(level) == "strict") return Level::strict;
  return spec && *spec ? Level::contract : Level::strict;
}

void save_failure(const std::string& name, const GeneratedCase& c, const Finding& f) {
  std::filesystem::create_directories("failures");
  CaseFile file = c.file;
  for (const std::string& line : replay_lines(f, {{}, level_under_test()})) file.extensions.push_back(line);
  std::string error;
  write_case_file("failures/" + name + ".case", file, error);
}

// The whole property for one invariant or relation `name`.
void holds(const std::string& name, const GeneratedCase& c) {
  const CaseOutcome outcome = check_case(c.file, generator_under_test(), Selection{{name}, level_under_test()});
  RC_PRE(!outcome.invalid);
  RC_TAG(c.placement, outcome.tags.contact_kind);
  if (outcome.finding) {
    save_failure(name, c, *outcome.finding);
    RC_FAIL(outcome.finding->name + ": " + outcome.finding->detail + " (case written to failures/" + name + ".case)");
  }
}

RC_GTEST_PROP(Manifold, hasOnlyFiniteFields, (const GeneratedCase& c)) { holds("finite", c); }
RC_GTEST_PROP(Manifold, hasAUnitNormal, (const GeneratedCase& c)) { holds("unit-normal", c); }
RC_GTEST_PROP(Manifold, penetratesNegativelyAndNoContactDeeperThanTheManifold, (const GeneratedCase& c)) {
  holds("negative-penetration", c);
}
RC_GTEST_PROP(Manifold, pairsEachPointOnBWithItsPointOnAAlongTheNormal, (const GeneratedCase& c)) {
  holds("pair-consistency", c);
}
RC_GTEST_PROP(Manifold, putsEachContactPointOnItsOwnHullsSurface, (const GeneratedCase& c)) { holds("on-surface", c); }
RC_GTEST_PROP(Manifold, keepsEachContactPointWithinBothHulls, (const GeneratedCase& c)) {
  holds("within-both-hulls", c);
}
RC_GTEST_PROP(Manifold, hasContactsWheneverItPenetrates, (const GeneratedCase& c)) { holds("has-contacts", c); }
RC_GTEST_PROP(Manifold, collidesExactlyWhenGjkSaysIntersecting, (const GeneratedCase& c)) {
  holds("agrees-with-gjk", c);
}
RC_GTEST_PROP(Manifold, hasTheExactPenetrationDepth, (const GeneratedCase& c)) { holds("depth-exact", c); }
RC_GTEST_PROP(Manifold, hasADepthWithinEpasBounds, (const GeneratedCase& c)) { holds("depth-within-epa-bounds", c); }
RC_GTEST_PROP(Manifold, hasTheNormalEpaFindsUnlessTheyTie, (const GeneratedCase& c)) {
  holds("normal-agrees-with-epa", c);
}
RC_GTEST_PROP(Manifold, hasANormalAlongWhichTheOverlapIsTheDepth, (const GeneratedCase& c)) {
  holds("normal-realises-depth", c);
}
RC_GTEST_PROP(Manifold, separatesTheHullsWhenBMovesByTheDepthAlongTheNormal, (const GeneratedCase& c)) {
  holds("separates", c);
}

RC_GTEST_PROP(Manifold, spansTheRegionWhereTheHullsFirstTouched, (const GeneratedCase& c)) {
  holds("spans-contact-region", c);
}

RC_GTEST_PROP(Relation, swappingAAndBFlipsTheNormalAndSwapsThePoints, (const GeneratedCase& c)) {
  holds("swap-symmetry", c);
}
RC_GTEST_PROP(Relation, aRigidMotionOfBothPosesMovesTheWholeManifold, (const GeneratedCase& c)) {
  holds("rigid-motion", c);
}
RC_GTEST_PROP(Relation, permutingAHullsPointsChangesNothing, (const GeneratedCase& c)) { holds("vertex-order", c); }
RC_GTEST_PROP(Relation, scalingTheCaseScalesDepthAndPoints, (const GeneratedCase& c)) { holds("scale", c); }
RC_GTEST_PROP(Relation, theSameInputGivesBitIdenticalOutput, (const GeneratedCase& c)) { holds("deterministic", c); }
RC_GTEST_PROP(Relation, theSameCaseFarFromTheOriginGivesTheManifoldShifted, (const GeneratedCase& c)) {
  holds("far-from-origin", c);
}
RC_GTEST_PROP(Relation, movingBByNinetyNinePercentOfTheDepthKeepsContactAndByOneHundredOneSeparates,
              (const GeneratedCase& c)) {
  holds("move-along-normal", c);
}
RC_GTEST_PROP(Relation, triangulatedFacesGiveTheSameManifoldAsMergedOnes, (const GeneratedCase& c)) {
  holds("triangulated-faces", c);
}

}  // namespace
}  // namespace mfz::props

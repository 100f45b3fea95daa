// The placements do what their names say: a touching case (and one of an
// ulp's overlap) touches, whatever features meet; pointed vertices and edges
// used to miss each other. Shallow and deep pushes are not pinned: through a
// slab 1e-3 thick either can come out on the other side.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "families.h"
#include "harness/invariants.h"
#include "geometry/tolerances.h"

namespace mfz::props {
namespace {

RC_GTEST_PROP(Placements, TouchingCasesTouch, ()) {
  const GeneratedCase c = *any_case();
  RC_PRE(c.overlap == "touching" || c.overlap == "one-ulp");
  SceneBuild built = make_scene(c.file);
  RC_PRE(built.scene.has_value());
  const Scene& s = *built.scene;
  const ExactDepth exact = exact_depth(s, rank_sat_axes(s));
  RC_TAG(c.overlap, c.placement);
  RC_ASSERT(std::abs(exact.signed_depth) <= s.length_tolerance(tol::kTouching));
}

// The wide-face family makes the faces the others never do (theirs have 64
// corners at most): a base of 65 to 520 corners, which hulls of up to 1,024
// points have (F61: the built-in refused a box on a 508-gon face). It is
// drawn only where named: among every family's names, or under `hulls`, a
// pair of them would cost the suite up to a second a case.
TEST(HullFamilies, WideFaceMakesABaseOfMoreCornersThanAnyOtherFamilyAndOnlyWhereNamed) {
  std::string error;
  ASSERT_TRUE(hull_families_named("wide-face", error)) << error;
  const auto every = *hull_families_named("hulls", error);
  EXPECT_EQ(std::count(every.begin(), every.end(), "wide-face"), 0);
  const auto& names = hull_family_names();
  EXPECT_EQ(std::count(names.begin(), names.end(), "wide-face"), 0);
  const rc::Gen<std::vector<Vec3>> wide = hull_points("wide-face");
  rc::Random random(2026);
  int widest = 0, narrowest = 1 << 30;
  for (int k = 0; k < 10; ++k) {
    const HullBuild built = build_hull(wide(random.split(), k).value());
    ASSERT_TRUE(built.hull.has_value());
    int corners = 0;
    for (int f = 0; f < built.hull->face_count(); ++f) corners = std::max(corners, built.hull->face_size(f));
    widest = std::max(widest, corners), narrowest = std::min(narrowest, corners);
  }
  EXPECT_GE(narrowest, 65);
  EXPECT_LE(widest, 520);
  EXPECT_GT(widest, 256);  // ten draws reach past the clip's old room of 512 for two such faces
}

}  // namespace
}  // namespace mfz::props

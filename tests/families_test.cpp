// The placements do what their names say: a touching case (and one of an
// ulp's overlap) touches, whatever features meet; pointed vertices and edges
// used to miss each other. Shallow and deep pushes are not pinned: through a
// slab 1e-3 thick either can come out on the other side.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

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

}  // namespace
}  // namespace mfz::props

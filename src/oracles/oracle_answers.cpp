#include "oracles/oracle_answers.h"

#include <cmath>

#include "geometry/tolerances.h"

namespace mfz {

OracleAnswers consult_oracles(const Scene& s) {
  OracleAnswers o;
  o.sat_axes = rank_sat_axes(s, &o.least_reverse_overlap);
  o.exact = exact_depth(s, o.sat_axes);
  const double touching = s.length_tolerance(tol::kTouching);
  o.ccd = ask_libccd(s);
  o.touching = std::abs(o.exact.signed_depth) <= touching;
  o.axis_tie = has_axis_tie(o.sat_axes, s.length_tolerance(tol::kTie), o.least_reverse_overlap);
  o.ties = classify_ties(s, o.sat_axes, s.length_tolerance(tol::kTie), o.least_reverse_overlap);
  o.face_contact = has_minimal_face_axis(o.sat_axes, s.length_tolerance(tol::kTie));
  return o;
}

}  // namespace mfz

#pragma once
/// \file
/// Shrinking a failing case file itself, after RapidCheck's shrink tree has
/// done what the families allow: move the case so that A sits at the origin
/// with the identity rotation, drop whole points (a duplicate or an
/// interior point never changes the hull, and the families cannot tell), and
/// round each coordinate, position and quaternion component to zero or as
/// few significant digits as keep the failure.
/// What a person reads in the case file is what is left.
#include <functional>

#include "case/case_file.h"

namespace mfz::props {

/// True when `candidate` still fails the same way (and is a valid case).
using StillFails = std::function<bool(const CaseFile& candidate)>;

/// Shrinks `failing` in place while `still_fails` holds, for at most
/// `seconds`. Returns how many shrink steps were taken.
int shrink_case_file(CaseFile& failing, const StillFails& still_fails, double seconds);

}  // namespace mfz::props

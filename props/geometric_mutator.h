#pragma once
/// \file
/// Mutations of a fuzz case in the geometric domain, where a contact
/// generator's bugs live: nudge, add or remove a point; rotate a hull by a
/// small angle; slide B along the contact normal to touching, or one ulp past
/// it; fold a face by a tiny angle; scale; move the pair far from the origin;
/// snap to an exact symmetry; redraw a hull from its family; swap the hulls.
/// libFuzzer's own byte mutations, mixed in by the fuzz target, reach the
/// numeric edge cases these do not.
#include <cstdint>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "fuzz_input.h"

namespace mfz::props {

using MutationRandom = std::mt19937_64;

/// One geometric mutation: its name and what it does. `apply` returns false
/// when it does not apply to this case (nothing to remove, no face to fold).
struct Mutation {
  const char* name;
  bool (*apply)(FuzzCase&, MutationRandom&);
};

/// Every geometric mutation, in one table.
const std::vector<Mutation>& geometric_mutations();

/// Applies one mutation drawn at random (another when the first does not
/// apply); returns its name.
std::string mutate_geometrically(FuzzCase& c, MutationRandom& random);

/// A child of two cases: A from one, B from the other, or one's hulls in the
/// other's poses.
FuzzCase cross_over(const FuzzCase& x, const FuzzCase& y, MutationRandom& random);

/// A fresh case from the property suite's families (the same draw as
/// `manifuzz check`), for a seed corpus or an input that holds no case.
FuzzCase draw_fuzz_case(uint64_t seed);

/// The fuzzer's seed corpus: one valid input for each hull family (as hull
/// A), named after it. The same inputs on every call.
std::vector<std::pair<std::string, std::vector<uint8_t>>> seed_inputs();

}  // namespace mfz::props

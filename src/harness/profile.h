#pragma once
/// \file
/// A generator profile (docs/contract.md, "Generator profiles"): what a
/// generator promises where the contract asks for more than real engines give
/// on purpose. Each key relaxes exactly the checks the contract names, by the
/// amount it names; every report says which profile was in force.
#include <optional>
#include <string>
#include <string_view>

namespace mfz {

struct Profile {
  /// The unit roundoff of the arithmetic inside (float: 2^-23), or 0 for
  /// double, which the contract's tolerances already cover.
  double precision_epsilon = 0;
  int max_contacts = 0;   ///< keeps at most this many contacts; 0: no promise
  double face_bias = 0;   ///< prefers a face axis within this fraction of the least overlap
  double margin = 0;      ///< reports contacts up to this distance (x L) before touching

  bool empty() const { return precision_epsilon == 0 && max_contacts == 0 && face_bias == 0 && margin == 0; }
  /// The profile as the keys that differ from the contract, e.g.
  /// `precision=float max-contacts=4`; `none` when it asks for nothing.
  std::string text() const;
};

/// Parses `precision=float|double max-contacts=K face-bias=F margin=M`
/// (any subset, in any order, separated by spaces) on top of `base`: a key
/// given replaces base's. nullopt and a one-line reason on an unknown key, a
/// repeated key or a value out of range (max-contacts 1..64, face-bias 0..1,
/// margin 0..1). `none` alone clears every key.
std::optional<Profile> parse_profile(std::string_view text, std::string& error, const Profile& base = {});

/// The profile in force: what the generator declares, with the keys that
/// `override_text` (--profile) names replacing its own. nullopt and a
/// one-line reason when either cannot be read.
std::optional<Profile> profile_in_force(const std::string& declared, const std::optional<std::string>& override_text,
                                        std::string& error);

}  // namespace mfz

#pragma once
/// \file
/// One interface for every generator: the built-in one and plugins loaded
/// with dlopen are both reached through the C ABI's three functions.
#include <memory>
#include <optional>
#include <string>

#include "manifuzz/abi.h"

namespace mfz {

/// Fills a manifold with NaN and the counts with -1, so that a field the
/// generator leaves unset shows up as non-finite or out of range.
void poison(mfz_manifold& out);

class Generator {
 public:
  /// The built-in clipping generator.
  static Generator builtin();
  /// `builtin`, or a path to a plugin `.so`. On failure: nullopt and a one-line
  /// reason (missing file, not a shared library, missing symbol, wrong ABI).
  static std::optional<Generator> open(const std::string& spec, std::string& error);

  /// The path `open` hands to dlopen for a plugin's spec: a name without
  /// a slash means the file in the current folder, as a user expects.
  static std::string library_path(const std::string& spec);

  const std::string& name() const { return name_; }
  /// What its optional `mfz_generator_profile()` returned (empty: none).
  const std::string& declared_profile() const { return profile_; }
  /// Poisons `out`, then calls the generator; returns its status (0 = done,
  /// non-zero = refused).
  int32_t generate(const mfz_hull& a, const mfz_pose& pose_a, const mfz_hull& b, const mfz_pose& pose_b,
                   mfz_manifold& out) const;
  /// The generator's own entry point, without the poisoning: for timing
  /// it side by side with others (bench/).
  mfz_generate_fn entry_point() const { return generate_; }

 private:
  std::shared_ptr<void> library_;  // keeps a plugin loaded while copies live
  mfz_generate_fn generate_ = nullptr;
  std::string name_;
  std::string profile_;
};

}  // namespace mfz

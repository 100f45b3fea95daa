#pragma once
/// \file
/// The fuzz targets' input: a case in a compact binary form that libFuzzer's
/// byte mutations can reach every double of, and the geometric mutator
/// (geometric_mutator.h) can decode, move and encode again.
///
///     byte 0, 1   hull family of A, of B (an index into hull_family_names;
///                 what the points came from, for the statistics and for
///                 redrawing a hull from its family)
///     byte 2, 3   point counts of A and B, 4 .. kFuzzMaxPoints
///     then        A's points, B's points (x y z, IEEE doubles, little-endian),
///                 pose A (px py pz qw qx qy qz), pose B
/// Bytes past the end of that are ignored; a shorter input, a count out of
/// range or a NaN or Inf is no case (the target rejects it).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "case/case_file.h"

namespace mfz::props {

/// Fuzz inputs keep hulls small: a fuzzer's speed is its reach, and the
/// property suite covers the 64-gon caps.
inline constexpr int kFuzzMaxPoints = 64;

/// A decoded fuzz input.
struct FuzzCase {
  CaseFile file;
  uint8_t family_a = 0, family_b = 0;
};

/// The case in `data`, or nullopt when the bytes hold none.
std::optional<FuzzCase> decode_fuzz_input(const uint8_t* data, size_t size);

/// The bytes of `c`; decode_fuzz_input gives it back bit for bit. Hulls of
/// more than kFuzzMaxPoints points keep their first kFuzzMaxPoints.
std::vector<uint8_t> encode_fuzz_input(const FuzzCase& c);

/// A finding as a file: a case file, or a fuzz input (libFuzzer's raw
/// artefact, `crash-<sha1>`). An error names the file and, for a case file,
/// the line.
CaseParse read_case_or_fuzz_input(const std::string& path);

/// The size of an input with these point counts.
size_t fuzz_input_size(int points_a, int points_b);

}  // namespace mfz::props

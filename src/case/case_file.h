#pragma once
/// \file
/// The case file of the contract: a text format a person can read and edit.
///
///     manifuzz-case 1
///     hull A
///     v 0.5 0.5 0.5          (local-space points; the hull is their convex hull)
///     pose A  px py pz  qw qx qy qz
///     hull B
///     ...
///
/// `#` starts a comment. Lines with another lowercase keyword (`note`,
/// `expect`, ...) are extensions: kept, never fatal, so that older readers
/// survive what newer writers add.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/vec.h"

namespace mfz {

/// Input limits: a case file is small text; past these it is an input error.
inline constexpr size_t kMaxCaseFileBytes = 1 << 20;
inline constexpr size_t kMaxPointsPerHull = 1024;

/// `text` in single quotes for a one-line message: control bytes as \xNN,
/// at most `limit` characters, so that input never breaks a message's line.
std::string quoted(std::string_view text, size_t limit = 64);
/// The same without the quotes.
std::string printable(std::string_view text, size_t limit = 64);

/// A case as written: points and poses exactly as read (the quaternion is not
/// normalised here; `Scene` does that).
struct CaseFile {
  std::vector<Vec3> points_a, points_b;
  Pose pose_a, pose_b;
  /// Extension lines, verbatim (without the newline), in file order.
  std::vector<std::string> extensions;
};

/// A parse: the case, or a one-line error "line N: reason".
struct CaseParse {
  std::optional<CaseFile> value;
  std::string error;
};

CaseParse parse_case(std::string_view text);
/// Reads and parses `path`; errors are prefixed with the path.
CaseParse read_case_file(const std::string& path);

/// The shortest decimal that strtod reads back to the same double.
std::string format_double(double value);
/// The case as text; `parse_case(format_case(c))` gives `c` back bit for bit.
std::string format_case(const CaseFile& c);
/// Writes `format_case(c)` to `path` through a temporary file and a rename;
/// false and a reason on failure (the old file, if any, is left as it was).
bool write_case_file(const std::string& path, const CaseFile& c, std::string& error);

}  // namespace mfz

#pragma once
/// \file
/// A JUnit XML report (`--junit FILE`), the format CI systems read: one test
/// suite per command, one test case per check (or case file, or kind of
/// disagreement), a failure carrying the finding and its case file.
#include <optional>
#include <string>
#include <vector>

namespace mfz {

struct JunitCase {
  std::string classname;  ///< e.g. manifuzz.check.bullet-sat
  std::string name;       ///< the check, the case file, the disagreement
  double seconds = 0;
  bool skipped = false;
  /// A failure: its one-line message and its longer text (the case file's path, ...).
  std::optional<std::string> failure_message = std::nullopt;
  std::string failure_text = {};
};

/// Writes `cases` as one test suite `suite` to `path`; false and a one-line
/// `error` when the file cannot be written.
bool write_junit(const std::string& path, const std::string& suite, const std::vector<JunitCase>& cases, double seconds,
                 std::string& error);

/// `text` with XML's five special characters escaped (and control characters
/// other than tab and newline dropped, which XML 1.0 cannot hold).
std::string xml_escaped(const std::string& text);

}  // namespace mfz

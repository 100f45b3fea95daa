#pragma once
/// \file
/// --report DIR for `check`, `fuzz` and `diff`: the pieces of a run's report
/// that the commands share (a finding with its picture, its case file and
/// the command that replays it).
#include <optional>
#include <string>

#include "render/run_report.h"

namespace mfz::cli {

/// How a finding is replayed: the generator as the user named it, and the
/// options that change a verdict.
struct ReplayWith {
  std::string generator = "builtin";  ///< as given to --generator
  bool strict = false;
  std::optional<std::string> profile;  ///< --profile's text
  double call_timeout = 5;
};

/// A finding of the run, read back from its case file: its picture (through
/// the one pipeline), the file's text, and the replay command.
ReportedFinding reported_finding(const std::string& name, const std::string& detail, const std::string& case_path,
                                 const ReplayWith& replay);

/// Writes the report, saying where on `log`; false (and the one-line error
/// on `log`) when it cannot.
bool write_report_to(const std::string& dir, const RunReport& report, const std::string& command, std::ostream& log);

/// --report's folder can be written: tried before a run, so that a long run
/// never ends without its report.
bool report_dir_writable(const std::string& dir, std::string& error);

}  // namespace mfz::cli

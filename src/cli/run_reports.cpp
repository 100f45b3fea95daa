#include "cli/run_reports.h"

#include <filesystem>
#include <fstream>
#include <ostream>
#include <sstream>

#include "cli/arguments.h"
#include "case_pictures.h"
#include "cli/program_files.h"
#include "fuzz_input.h"

namespace mfz::cli {

ReportedFinding reported_finding(const std::string& name, const std::string& detail, const std::string& case_path,
                                 const ReplayWith& replay) {
  ReportedFinding f;
  f.name = name, f.detail = detail, f.case_path = case_path;
  f.replay_command = "manifuzz replay --generator " + replay.generator + (replay.strict ? " --strict" : "") +
                     (replay.profile ? " --profile '" + *replay.profile + "'" : "") + " " + case_path;
  std::ifstream in(case_path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  f.case_text = text.str();
  const CaseParse parsed = props::read_case_or_fuzz_input(case_path);
  std::string error;
  auto session = parsed.value ? open_session(resolve_generator(replay.generator), replay.call_timeout, error) : nullptr;
  if (!parsed.value) error = parsed.error;
  if (session) {
    props::Selection selection;
    if (replay.strict) selection.level = props::Level::strict;
    if (replay.profile) {
      const auto profile = profile_in_force(session->declared_profile(), replay.profile, error);
      if (profile) selection.profile = *profile, selection.profile_from_command_line = true;
    }
    f.pictures = props::pictures_of_case(*parsed.value, *session, selection, error);
  }
  if (f.pictures.empty()) f.note = "no picture: " + error;
  return f;
}

bool report_dir_writable(const std::string& dir, std::string& error) {
  std::error_code ec;
  if (dir.empty()) {
    error = "--report needs a folder name";
    return false;
  }
  std::filesystem::create_directories(dir, ec);
  const std::string probe = (std::filesystem::path(dir) / "report.html").string();
  std::ofstream out(probe, std::ios::app);
  if (ec || !out) {
    error = "cannot write the report in " + dir;
    return false;
  }
  return true;
}

bool write_report_to(const std::string& dir, const RunReport& report, const std::string& command, std::ostream& log) {
  std::string error;
  if (!write_run_report(dir, report, error)) {
    log << "manifuzz " << command << ": " << error << "\n";
    return false;
  }
  log << "manifuzz " << command << ": report in " << (std::filesystem::path(dir) / "report.html").string() << "\n";
  return true;
}

}  // namespace mfz::cli

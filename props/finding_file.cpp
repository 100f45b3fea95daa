#include "finding_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>

#include <unistd.h>

namespace mfz::props {

bool prepare_out_dir(const std::string& dir, std::string& error) {
  if (dir.empty()) {
    error = "--out needs a folder name";
    return false;
  }
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) {
    error = "cannot create --out folder " + quoted(dir, 4096) + ": " + ec.message();
    return false;
  }
  const std::string probe = dir + "/.manifuzz-probe-" + std::to_string(getpid());
  std::FILE* f = std::fopen(probe.c_str(), "wb");
  const bool writable = f && std::fputs("probe\n", f) >= 0 && std::fclose(f) == 0;
  if (!f) error = "cannot write into --out folder " + quoted(dir, 4096) + ": " + std::strerror(errno);
  else if (!writable) error = "cannot write into --out folder " + quoted(dir, 4096);
  std::remove(probe.c_str());
  return writable;
}

std::string write_finding(const std::string& dir, CaseFile file, const Finding& finding, const Selection& selection,
                          const std::vector<std::string>& notes, std::string& text, std::string& error) {
  for (const std::string& note : notes) file.extensions.push_back("note " + note);
  file.extensions.push_back("note violation: " + finding.name + ": " + finding.detail);
  for (const std::string& line : replay_lines(finding, selection)) file.extensions.push_back(line);
  text = format_case(file);
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  const std::string path =
      dir + "/" + finding.name + "-" + std::to_string(std::hash<std::string>{}(text) % 100000000) + ".case";
  if (!write_case_file(path, file, error)) return {};
  return path;
}

}  // namespace mfz::props

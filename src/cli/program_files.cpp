#include "cli/program_files.h"

#include <filesystem>

namespace mfz::cli {

std::string beside_this_program(const std::vector<std::string>& candidates) {
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) return {};
  for (const std::string& candidate : candidates) {
    const std::filesystem::path path = (self.parent_path() / candidate).lexically_normal();
    if (std::filesystem::is_regular_file(path, ec)) return path.string();
  }
  return {};
}

}  // namespace mfz::cli

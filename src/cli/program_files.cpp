#include "cli/program_files.h"

#include <algorithm>
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

const std::vector<std::string>& bundled_generator_names() {
  static const std::vector<std::string> names = {"tutorial",   "bullet-sat", "bullet",  "bullet-sat-double",
                                                 "bullet-double", "ode",     "ode-box"};
  return names;
}

std::string resolve_generator(const std::string& spec) {
  const auto& names = bundled_generator_names();
  if (std::find(names.begin(), names.end(), spec) == names.end()) return spec;
  // libmanifuzz_tutorial.so, libmanifuzz_peer_bullet_sat.so, ...
  std::string file = spec == "tutorial" ? "libmanifuzz_tutorial.so" : "libmanifuzz_peer_" + spec + ".so";
  std::replace(file.begin(), file.end(), '-', '_');
  const std::string path = beside_this_program({"../plugins/" + file, "../lib/manifuzz/" + file});
  return path.empty() ? spec : path;
}

}  // namespace mfz::cli

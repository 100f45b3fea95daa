#include "process_memory.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include <fcntl.h>
#include <unistd.h>

namespace mfz::props {

namespace fs = std::filesystem;

std::optional<std::string> read_to_end(int fd) {
  std::string text;
  char buffer[4096];
  for (;;) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n == 0) return text;
    if (n < 0) return std::nullopt;
    text.append(buffer, static_cast<size_t>(n));
  }
}

namespace {

// Fields 5 (process group) and 24 (resident pages) of /proc/PID/stat, after
// the command name in parentheses; nullopt when the process is gone.
std::optional<std::pair<long long, long long>> group_and_pages(const fs::path& stat_path) {
  const int fd = ::open(stat_path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return std::nullopt;
  const std::optional<std::string> text = read_to_end(fd);
  ::close(fd);
  if (!text) return std::nullopt;
  const size_t close = text->rfind(')');
  if (close == std::string::npos || close + 2 > text->size()) return std::nullopt;
  std::istringstream fields(text->substr(close + 2));
  std::string field;
  long long group = 0, pages = 0;
  for (int k = 3; k <= 24 && fields >> field; ++k) {
    if (k == 5) group = std::atoll(field.c_str());
    if (k == 24) pages = std::atoll(field.c_str());
  }
  return std::make_pair(group, pages);
}

}  // namespace

double group_resident_mb(pid_t group) {
  double pages = 0;
  std::error_code ec;
  fs::directory_iterator entry("/proc", fs::directory_options::skip_permission_denied, ec);
  for (; !ec && entry != fs::directory_iterator(); entry.increment(ec)) {
    const std::string pid = entry->path().filename().string();
    if (pid.empty() || !std::all_of(pid.begin(), pid.end(), [](unsigned char c) { return std::isdigit(c); }))
      continue;
    if (const auto found = group_and_pages(entry->path() / "stat"); found && found->first == group)
      pages += static_cast<double>(found->second);
  }
  return pages * static_cast<double>(sysconf(_SC_PAGESIZE)) / (1 << 20);
}

}  // namespace mfz::props

#include "cli/arguments.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>

namespace mfz::cli {

std::string Arguments::get(const std::string& name, const std::string& fallback) const {
  const auto found = options.find(name);
  return found == options.end() ? fallback : found->second;
}

std::optional<Arguments> parse_arguments(const std::vector<std::string>& words, const std::set<std::string>& valued,
                                         const std::set<std::string>& switches, std::string& error) {
  Arguments args;
  for (size_t i = 0; i < words.size(); ++i) {
    const std::string& w = words[i];
    const bool named = switches.count(w) || valued.count(w);  // also a short name such as -o
    if (!named && (w.rfind("--", 0) != 0 || w == "--")) {
      args.positional.push_back(w);
      continue;
    }
    if (switches.count(w)) {
      args.flags.insert(w);
    } else if (valued.count(w)) {
      if (i + 1 >= words.size()) {
        error = "option " + w + " needs a value";
        return std::nullopt;
      }
      args.options[w] = words[++i];
    } else {
      error = "unknown option " + w;
      return std::nullopt;
    }
  }
  return args;
}

std::optional<long long> parse_count(const std::string& text, long long low, long long high) {
  char* end = nullptr;
  errno = 0;
  const long long v = std::strtoll(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || errno != 0 || v < low || v > high) return std::nullopt;
  return v;
}

std::optional<double> call_timeout(const Arguments& args, std::string& error) {
  if (!args.options.count("--call-timeout")) return 5.0;
  const auto t = parse_seconds(args.get("--call-timeout", ""));
  if (t && *t >= kShortestCallTimeout) return t;
  error = "--call-timeout takes a number of seconds >= 0.05";
  return std::nullopt;
}

std::optional<double> parse_seconds(const std::string& text) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(v) || v < 0) return std::nullopt;
  return v;
}

std::optional<RunBudget> run_budget(const Arguments& args, long long default_cases, std::string& error) {
  RunBudget budget;
  if (args.options.count("--cases")) {
    budget.cases = parse_count(args.get("--cases", ""), 1, 1LL << 50);
    if (!budget.cases) return error = "--cases takes a whole number >= 1", std::nullopt;
  }
  if (args.options.count("--seconds")) {
    budget.seconds = parse_seconds(args.get("--seconds", ""));
    if (!budget.seconds) return error = "--seconds takes a number >= 0", std::nullopt;
  }
  if (!budget.cases && !budget.seconds) budget.cases = default_cases;
  if (args.options.count("--seed")) {
    const auto seed = parse_count(args.get("--seed", ""), 0, (1LL << 62));
    if (!seed) return error = "--seed takes a whole number >= 0", std::nullopt;
    budget.seed = static_cast<uint64_t>(*seed);
  } else {
    budget.seed = std::random_device{}() % 1000000000;
  }
  return budget;
}

bool junit_writable(const std::string& path, std::string& error) {
  if (path.empty()) {
    error = "--junit needs a file name";
    return false;
  }
  // Its folder is made, as --out's is.
  std::error_code ec;
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  if (!parent.empty()) std::filesystem::create_directories(parent, ec);
  std::ofstream probe(path, std::ios::app);
  if (!probe) {
    error = "cannot write --junit file '" + path + "': " + std::strerror(errno);
    return false;
  }
  return true;
}

std::optional<std::string> profile_override(const Arguments& args) {
  if (!args.options.count("--profile")) return std::nullopt;
  return args.get("--profile", "");
}

bool apply_profile(const Arguments& args, const GeneratorSession& session, props::Selection& selection,
                   std::string& error) {
  const auto profile = profile_in_force(session.declared_profile(), profile_override(args), error);
  if (!profile) return false;
  selection.profile = *profile;
  selection.profile_from_command_line = args.options.count("--profile") > 0;
  return true;
}

}  // namespace mfz::cli

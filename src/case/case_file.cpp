#include "case/case_file.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

#include <unistd.h>

namespace mfz {

std::string quoted(std::string_view text, size_t limit) { return "'" + printable(text, limit) + "'"; }

std::string printable(std::string_view text, size_t limit) {
  std::string out;
  for (const char c : text.substr(0, limit)) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x20 || byte == 0x7f) {
      char escape[8];
      std::snprintf(escape, sizeof escape, "\\x%02x", byte);
      out += escape;
    } else {
      out += c;
    }
  }
  return out + (text.size() > limit ? "..." : "");
}

namespace {

std::vector<std::string_view> split_words(std::string_view line) {
  std::vector<std::string_view> words;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    size_t j = i;
    while (j < line.size() && line[j] != ' ' && line[j] != '\t' && line[j] != '\r') ++j;
    if (j > i) words.push_back(line.substr(i, j - i));
    i = j;
  }
  return words;
}

// strtod accepts decimal and hex floats, as the contract says; the whole word
// must be consumed (a NUL inside it ends strtod's reading, not the word), and
// NaN and Inf are input errors.
bool read_number(std::string_view word, double& out, std::string& why) {
  const std::string text(word);
  char* end = nullptr;
  errno = 0;
  out = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || end != text.c_str() + text.size()) {
    why = quoted(text) + " is not a number";
    return false;
  }
  if (!std::isfinite(out)) {
    why = quoted(text) + " is not finite (NaN and Inf are not allowed)";
    return false;
  }
  return true;
}

bool read_numbers(const std::vector<std::string_view>& words, size_t first, size_t count, double* out,
                  std::string& why) {
  if (words.size() != first + count) {
    why = "expected " + std::to_string(count) + " numbers after " +
          quoted(std::string(words[0]) + (first > 1 ? " " + std::string(words[1]) : "")) + ", found " +
          std::to_string(words.size() - first);
    return false;
  }
  for (size_t k = 0; k < count; ++k)
    if (!read_number(words[first + k], out[k], why)) return false;
  return true;
}

bool is_extension_keyword(std::string_view word) {
  if (word.empty() || word[0] < 'a' || word[0] > 'z') return false;
  for (char c : word)
    if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-' || c == '_')) return false;
  return true;
}

struct Parser {
  CaseFile result;
  char section = 0;  // 'A' or 'B' after "hull A" / "hull B"
  bool seen_header = false, seen_hull[2] = {false, false}, seen_pose[2] = {false, false};

  std::string line_error(size_t line, const std::string& why) { return "line " + std::to_string(line) + ": " + why; }

  // Returns an empty string or the reason this line is wrong.
  std::string take(std::string_view raw) {
    const std::string_view line = raw.substr(0, raw.find('#'));
    const auto words = split_words(line);
    if (words.empty()) return {};
    std::string why;
    if (!seen_header) {
      if (words.size() == 2 && words[0] == "manifuzz-case") {
        if (words[1] != "1") return "unsupported case file version " + quoted(words[1]) + " (this reader knows 1)";
        seen_header = true;
        return {};
      }
      return "expected the header 'manifuzz-case 1'";
    }
    if (words[0] == "hull") {
      if (words.size() != 2 || (words[1] != "A" && words[1] != "B")) return "expected 'hull A' or 'hull B'";
      section = words[1][0];
      if (seen_hull[section - 'A']) return "hull " + std::string(1, section) + " appears twice";
      seen_hull[section - 'A'] = true;
      return {};
    }
    if (words[0] == "v") {
      if (!section) return "a vertex 'v' before 'hull A' or 'hull B'";
      double xyz[3];
      if (!read_numbers(words, 1, 3, xyz, why)) return why;
      auto& points = section == 'A' ? result.points_a : result.points_b;
      if (points.size() >= kMaxPointsPerHull)
        return "hull " + std::string(1, section) + " has more than " + std::to_string(kMaxPointsPerHull) +
               " points (the limit)";
      points.emplace_back(xyz[0], xyz[1], xyz[2]);
      return {};
    }
    if (words[0] == "pose") {
      if (words.size() < 2 || (words[1] != "A" && words[1] != "B")) return "expected 'pose A' or 'pose B'";
      const int which = words[1][0] - 'A';
      if (seen_pose[which]) return "pose " + std::string(words[1]) + " appears twice";
      double p[7];
      if (!read_numbers(words, 2, 7, p, why)) return why;
      const Quat q(p[3], p[4], p[5], p[6]);
      if (q.coeffs().cwiseAbs().maxCoeff() == 0) return "the orientation quaternion is zero";
      (which == 0 ? result.pose_a : result.pose_b) = Pose{Vec3(p[0], p[1], p[2]), q};
      seen_pose[which] = true;
      return {};
    }
    if (is_extension_keyword(words[0])) {
      size_t begin = raw.find_first_not_of(" \t");
      std::string kept(raw.substr(begin));
      while (!kept.empty() && (kept.back() == '\r' || kept.back() == ' ')) kept.pop_back();
      result.extensions.push_back(kept);
      return {};
    }
    return "unrecognised line starting with " + quoted(words[0]);
  }

  std::string finish() {
    if (!seen_header) return "empty file: expected the header 'manifuzz-case 1'";
    for (int k = 0; k < 2; ++k) {
      const std::string name(1, static_cast<char>('A' + k));
      if (!seen_hull[k]) return "no 'hull " + name + "' section";
      if (!seen_pose[k]) return "no 'pose " + name + "' line";
    }
    return {};
  }
};

}  // namespace

CaseParse parse_case(std::string_view text) {
  Parser parser;
  size_t line_number = 0, start = 0;
  while (start <= text.size()) {
    const size_t end = std::min(text.find('\n', start), text.size());
    ++line_number;
    if (std::string why = parser.take(text.substr(start, end - start)); !why.empty())
      return {std::nullopt, parser.line_error(line_number, why)};
    start = end + 1;
  }
  if (std::string why = parser.finish(); !why.empty()) return {std::nullopt, parser.line_error(line_number, why)};
  return {std::move(parser.result), {}};
}

CaseParse read_case_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return {std::nullopt, quoted(path, 4096) + ": cannot open"};
  // Bounded: a case file is small, and /dev/zero or a mistaken path must not
  // grow until memory runs out.
  std::string text(kMaxCaseFileBytes + 1, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<size_t>(in.gcount()));
  if (text.size() > kMaxCaseFileBytes)
    return {std::nullopt, quoted(path, 4096) + ": larger than " + std::to_string(kMaxCaseFileBytes) + " bytes (the limit)"};
  CaseParse parsed = parse_case(text);
  if (!parsed.value) parsed.error = quoted(path, 4096) + ": " + parsed.error;
  return parsed;
}

std::string format_double(double value) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

std::string format_case(const CaseFile& c) {
  std::string out = "manifuzz-case 1\n";
  const auto hull = [&](char name, const std::vector<Vec3>& points, const Pose& pose) {
    out += std::string("hull ") + name + "\n";
    for (const Vec3& p : points)
      out += "v " + format_double(p.x()) + " " + format_double(p.y()) + " " + format_double(p.z()) + "\n";
    const Quat& q = pose.orientation;
    out += std::string("pose ") + name + "  " + format_double(pose.position.x()) + " " +
           format_double(pose.position.y()) + " " + format_double(pose.position.z()) + "  " + format_double(q.w()) +
           " " + format_double(q.x()) + " " + format_double(q.y()) + " " + format_double(q.z()) + "\n";
  };
  hull('A', c.points_a, c.pose_a);
  hull('B', c.points_b, c.pose_b);
  for (const std::string& line : c.extensions) out += line + "\n";
  return out;
}

// Written to a temporary name beside it, then renamed: a full disk or an
// interrupted run never leaves a half-written or empty case in its place.
bool write_case_file(const std::string& path, const CaseFile& c, std::string& error) {
  const std::string temporary = path + ".tmp" + std::to_string(getpid());
  const std::string text = format_case(c);
  FILE* out = std::fopen(temporary.c_str(), "wb");
  if (!out) {
    error = quoted(path, 4096) + ": cannot write: " + std::strerror(errno);
    return false;
  }
  const bool written = std::fwrite(text.data(), 1, text.size(), out) == text.size();
  const int saved = errno;
  const bool closed = std::fclose(out) == 0;
  if (!written || !closed || std::rename(temporary.c_str(), path.c_str()) != 0) {
    error = quoted(path, 4096) + ": write failed: " + std::strerror(written && closed ? errno : saved);
    std::remove(temporary.c_str());
    return false;
  }
  return true;
}

}  // namespace mfz

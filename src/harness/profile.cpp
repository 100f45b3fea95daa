#include "harness/profile.h"

#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <sstream>

namespace mfz {

namespace {

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

// A whole finite number within [low, high], or nullopt.
std::optional<double> read_number(const std::string& text, double low, double high) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(value) || value < low || value > high) return std::nullopt;
  return value;
}

}  // namespace

std::string Profile::text() const {
  std::string out;
  const auto add = [&](const std::string& pair) { out += (out.empty() ? "" : " ") + pair; };
  if (precision_epsilon > 0) add(precision_epsilon == FLT_EPSILON ? "precision=float" : "precision=" + number(precision_epsilon));
  if (max_contacts > 0) add("max-contacts=" + std::to_string(max_contacts));
  if (face_bias > 0) add("face-bias=" + number(face_bias));
  if (margin > 0) add("margin=" + number(margin));
  return out.empty() ? "none" : out;
}

std::optional<Profile> parse_profile(std::string_view text, std::string& error, const Profile& base) {
  Profile p = base;
  std::istringstream words{std::string(text)};
  std::set<std::string> seen;
  for (std::string word; words >> word;) {
    if (word == "none") {
      p = {};
      continue;
    }
    const size_t eq = word.find('=');
    const std::string key = word.substr(0, eq), value = eq == std::string::npos ? "" : word.substr(eq + 1);
    if (eq == std::string::npos || value.empty()) {
      error = "profile: '" + word + "' is not key=value";
      return std::nullopt;
    }
    if (!seen.insert(key).second) {
      error = "profile: '" + key + "' is given twice";
      return std::nullopt;
    }
    if (key == "precision") {
      if (value != "float" && value != "double") {
        error = "profile: precision is float or double, not '" + value + "'";
        return std::nullopt;
      }
      p.precision_epsilon = value == "float" ? FLT_EPSILON : 0;
    } else if (key == "max-contacts") {
      const auto k = read_number(value, 1, 64);
      if (!k || *k != std::floor(*k)) {
        error = "profile: max-contacts is a whole number from 1 to 64, not '" + value + "'";
        return std::nullopt;
      }
      p.max_contacts = static_cast<int>(*k);
    } else if (key == "face-bias" || key == "margin") {
      const auto f = read_number(value, 0, 1);
      if (!f) {
        error = "profile: " + key + " is a number from 0 to 1, not '" + value + "'";
        return std::nullopt;
      }
      (key == "face-bias" ? p.face_bias : p.margin) = *f;
    } else {
      error = "profile: unknown key '" + key + "' (precision, max-contacts, face-bias, margin)";
      return std::nullopt;
    }
  }
  return p;
}

std::optional<Profile> profile_in_force(const std::string& declared, const std::optional<std::string>& override_text,
                                        std::string& error) {
  std::optional<Profile> p = parse_profile(declared, error);
  if (!p) {
    error = "the generator declares a profile the harness cannot read: " + error;
    return std::nullopt;
  }
  if (override_text && !(p = parse_profile(*override_text, error, *p))) error = "--" + error;
  return p;
}

}  // namespace mfz

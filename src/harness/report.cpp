#include "harness/report.h"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "case/case_file.h"

namespace mfz {

std::string vec_text(const Vec3& v) {
  char buffer[128];
  std::snprintf(buffer, sizeof buffer, "(%.9g, %.9g, %.9g)", v.x(), v.y(), v.z());
  return buffer;
}

std::string manifold_text(const mfz_manifold& m, const std::string& indent) {
  std::ostringstream out;
  out << indent << "colliding    " << m.colliding << "\n";
  if (m.colliding != 1) return out.str();
  out << indent << "normal       " << vec_text(to_vec(m.normal)) << "\n";
  out << indent << "penetration  " << m.penetration << "\n";
  out << indent << "contacts     " << m.contact_count << "\n";
  for (int i = 0; i < m.contact_count && i < MFZ_MAX_CONTACTS; ++i) {
    const mfz_contact& c = m.contacts[i];
    out << indent << "  [" << i << "] on A " << vec_text(to_vec(c.point_on_a)) << "  on B "
        << vec_text(to_vec(c.point_on_b)) << "  p " << c.penetration << "\n";
  }
  return out.str();
}

const char* verdict_word(const Verdict& v) {
  if (v.refused()) return "refused";
  if (v.first_violation()) return "violation";
  if (v.has_oracle_disagreement()) return "oracle-disagreement";
  return "pass";
}

std::string verdict_text(const Verdict& v, const std::string& indent) {
  if (v.refused()) return indent + "REFUSED: the generator returned status " + std::to_string(v.generator_status) + "\n";
  std::ostringstream out;
  for (const InvariantCheck& c : v.checks) {
    char line[256];
    std::snprintf(line, sizeof line, "%-20s %-24s", status_name(c.status), c.name.c_str());
    out << indent << line;
    if (c.status != CheckStatus::skipped) {
      char margin[96];
      std::snprintf(margin, sizeof margin, " error %.3g L  tol %.3g L", c.error, c.tolerance);
      out << margin;
      if (c.profile_share > 0) {
        std::snprintf(margin, sizeof margin, " (profile %.3g L)", c.profile_share);
        out << margin;
      }
    }
    if (!c.detail.empty()) out << "  " << c.detail;
    out << "\n";
  }
  return out.str();
}

void Json::separate() {
  if (need_comma_) out_ += ',';
  need_comma_ = true;
}
Json& Json::begin_object() { separate(); out_ += '{'; need_comma_ = false; return *this; }
Json& Json::end_object() { out_ += '}'; need_comma_ = true; return *this; }
Json& Json::begin_array() { separate(); out_ += '['; need_comma_ = false; return *this; }
Json& Json::end_array() { out_ += ']'; need_comma_ = true; return *this; }
Json& Json::key(const std::string& k) {
  value(k);
  out_ += ':';
  need_comma_ = false;
  return *this;
}
Json& Json::value(const std::string& s) {
  separate();
  out_ += '"';
  for (char c : s) {
    if (c == '"' || c == '\\') out_ += '\\', out_ += c;
    else if (static_cast<unsigned char>(c) < 0x20) {
      char esc[8];
      std::snprintf(esc, sizeof esc, "\\u%04x", c);
      out_ += esc;
    } else out_ += c;
  }
  out_ += '"';
  return *this;
}
Json& Json::value(double d) {
  separate();
  out_ += std::isfinite(d) ? format_double(d) : "null";
  return *this;
}
Json& Json::value(int i) {
  separate();
  out_ += std::to_string(i);
  return *this;
}
Json& Json::value(bool b) {
  separate();
  out_ += b ? "true" : "false";
  return *this;
}
Json& Json::value(const Vec3& v) {
  begin_array().value(v.x()).value(v.y()).value(v.z());
  return end_array();
}

void manifold_json(Json& j, const mfz_manifold& m) {
  j.key("colliding").value(static_cast<int>(m.colliding));
  j.key("normal").value(to_vec(m.normal));
  j.key("penetration").value(m.penetration);
  j.key("contacts").begin_array();
  for (int i = 0; i < m.contact_count && i < MFZ_MAX_CONTACTS; ++i) {
    j.begin_object();
    j.key("point_on_a").value(to_vec(m.contacts[i].point_on_a));
    j.key("point_on_b").value(to_vec(m.contacts[i].point_on_b));
    j.key("penetration").value(m.contacts[i].penetration);
    j.end_object();
  }
  j.end_array();
}

void verdict_json(Json& j, const Verdict& v) {
  j.key("verdict").value(verdict_word(v));
  j.key("generator_status").value(static_cast<int>(v.generator_status));
  j.key("invariants").begin_array();
  for (const InvariantCheck& c : v.checks) {
    j.begin_object();
    j.key("name").value(c.name);
    j.key("status").value(status_name(c.status));
    j.key("error").value(c.error);
    j.key("tolerance").value(c.tolerance);
    j.key("profile_share").value(c.profile_share);
    j.key("detail").value(c.detail);
    j.end_object();
  }
  j.end_array();
}

}  // namespace mfz

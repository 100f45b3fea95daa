#include "harness/junit_report.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

namespace mfz {

std::string xml_escaped(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default:
        if (static_cast<unsigned char>(c) >= 0x20 || c == '\t' || c == '\n') out += c;
    }
  }
  return out;
}

bool write_junit(const std::string& path, const std::string& suite, const std::vector<JunitCase>& cases, double seconds,
                 std::string& error) {
  int failures = 0, skipped = 0;
  for (const JunitCase& c : cases) {
    failures += c.failure_message ? 1 : 0;
    skipped += c.skipped ? 1 : 0;
  }
  std::ostringstream xml;
  xml << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<testsuites tests=\"" << cases.size() << "\" failures=\"" << failures << "\" time=\"" << seconds << "\">\n"
      << "  <testsuite name=\"" << xml_escaped(suite) << "\" tests=\"" << cases.size() << "\" failures=\"" << failures
      << "\" skipped=\"" << skipped << "\" errors=\"0\" time=\"" << seconds << "\">\n";
  for (const JunitCase& c : cases) {
    xml << "    <testcase classname=\"" << xml_escaped(c.classname) << "\" name=\"" << xml_escaped(c.name)
        << "\" time=\"" << c.seconds << "\"";
    if (!c.failure_message && !c.skipped) {
      xml << "/>\n";
      continue;
    }
    xml << ">\n";
    if (c.skipped) xml << "      <skipped/>\n";
    if (c.failure_message)
      xml << "      <failure message=\"" << xml_escaped(*c.failure_message) << "\">" << xml_escaped(c.failure_text)
          << "</failure>\n";
    xml << "    </testcase>\n";
  }
  xml << "  </testsuite>\n</testsuites>\n";
  std::ofstream file(path, std::ios::binary | std::ios::trunc);
  if (!(file << xml.str()) || !file.flush()) {
    error = "cannot write --junit file '" + path + "': " + std::strerror(errno);
    return false;
  }
  return true;
}

}  // namespace mfz

#include "render/run_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <filesystem>
#include <fstream>

#include "harness/report.h"
#include "render/html_case_view.h"
#include "render/markup.h"
#include "render/svg_picture.h"

namespace mfz {
namespace {

std::string fixed(double x, int digits = 1) {
  char text[48];
  std::snprintf(text, sizeof text, "%.*f", digits, x);
  return text;
}

std::string general(double x) {
  char text[48];
  std::snprintf(text, sizeof text, "%.3g", x);
  return text;
}

// ---- charts: inline SVG ----

// Keys that start with a number ("2", "5-8", "1e-3") in the order of that
// number, then the others by name.
std::vector<std::pair<std::string, long long>> in_reading_order(const std::map<std::string, long long>& rows) {
  std::vector<std::pair<std::string, long long>> sorted(rows.begin(), rows.end());
  const auto leading = [](const std::string& key) {
    char* end = nullptr;
    const double x = std::strtod(key.c_str(), &end);
    return end != key.c_str() ? x : INFINITY;
  };
  std::stable_sort(sorted.begin(), sorted.end(),
                   [&](const auto& x, const auto& y) { return leading(x.first) < leading(y.first); });
  return sorted;
}

// One table's counts as horizontal bars, in percent of the table's total.
std::string bar_chart(const std::map<std::string, long long>& table) {
  const auto rows = in_reading_order(table);
  long long total = 0, most = 1;
  for (const auto& [key, n] : rows) total += n, most = std::max(most, n);
  const double row = 18, label = 170, bars = 300;
  std::string svg = "<svg class=\"chart\" xmlns=\"http://www.w3.org/2000/svg\" width=\"" + fixed(label + bars + 120, 0) +
                    "\" height=\"" + fixed(row * rows.size() + 4, 0) + "\">\n";
  double y = 2;
  for (const auto& [key, n] : rows) {
    const double w = bars * static_cast<double>(n) / static_cast<double>(most);
    svg += "<text x=\"0\" y=\"" + fixed(y + 13) + "\" font-size=\"12\">" + markup_escaped(key) + "</text>";
    svg += "<rect x=\"" + fixed(label) + "\" y=\"" + fixed(y + 2) + "\" width=\"" + fixed(std::max(w, 1.0)) +
           "\" height=\"" + fixed(row - 5) + "\" fill=\"#5b8bd6\"/>";
    svg += "<text x=\"" + fixed(label + w + 6) + "\" y=\"" + fixed(y + 13) + "\" font-size=\"12\">" + std::to_string(n) +
           " (" + fixed(100.0 * n / std::max(1LL, total)) + "%)</text>\n";
    y += row;
  }
  return svg + "</svg>\n";
}

// One check's margins: a bar per bin, passes blue, failures red.
std::string margin_histogram(const CheckMargins& m) {
  long long most = 1;
  for (const long long n : m.bins) most = std::max(most, n);
  const double width = 46, height = 44;
  std::string svg = "<svg class=\"chart\" xmlns=\"http://www.w3.org/2000/svg\" width=\"" + fixed(width * kMarginBins, 0) +
                    "\" height=\"" + fixed(height + 14, 0) + "\">";
  for (int k = 0; k < kMarginBins; ++k) {
    const double h = m.bins[k] ? std::max(2.0, height * std::log1p(m.bins[k]) / std::log1p(most)) : 0;
    svg += "<rect x=\"" + fixed(k * width + 2) + "\" y=\"" + fixed(height - h) + "\" width=\"" + fixed(width - 4) +
           "\" height=\"" + fixed(h) + "\" fill=\"" + (k >= kMarginBins - 2 ? "#d0182b" : "#5b8bd6") + "\"><title>" +
           margin_bin_names()[k] + ": " + std::to_string(m.bins[k]) + "</title></rect>";
    svg += "<text x=\"" + fixed(k * width + width / 2) + "\" y=\"" + fixed(height + 12) +
           "\" font-size=\"9\" text-anchor=\"middle\">" + markup_escaped(margin_bin_names()[k]) + "</text>";
  }
  return svg + "</svg>";
}

// A line over time; `value` picks each sample's y (nullopt: skipped).
template <class Value>
std::string time_chart(const std::vector<ProgressSample>& samples, Value value, const std::string& unit) {
  std::vector<std::pair<double, double>> points;
  for (size_t k = 0; k < samples.size(); ++k)
    if (const auto y = value(k)) points.push_back({samples[k].seconds, *y});
  if (points.empty()) return "<p>(no samples)</p>\n";
  double t_max = 1e-9, y_max = 1e-9;
  for (const auto& [t, y] : points) t_max = std::max(t_max, t), y_max = std::max(y_max, y);
  const double w = 520, h = 160, left = 60, bottom = 20;
  std::string svg = "<svg class=\"chart\" xmlns=\"http://www.w3.org/2000/svg\" width=\"" + fixed(w + left + 10, 0) +
                    "\" height=\"" + fixed(h + bottom + 10, 0) + "\">\n";
  svg += "<line x1=\"" + fixed(left) + "\" y1=\"" + fixed(h + 5) + "\" x2=\"" + fixed(left + w) + "\" y2=\"" + fixed(h + 5) +
         "\" stroke=\"#888\"/><line x1=\"" + fixed(left) + "\" y1=\"5\" x2=\"" + fixed(left) + "\" y2=\"" + fixed(h + 5) +
         "\" stroke=\"#888\"/>\n";
  svg += "<text x=\"" + fixed(left - 4) + "\" y=\"14\" font-size=\"11\" text-anchor=\"end\">" + general(y_max) + "</text>";
  svg += "<text x=\"" + fixed(left - 4) + "\" y=\"" + fixed(h + 5) + "\" font-size=\"11\" text-anchor=\"end\">0</text>";
  svg += "<text x=\"" + fixed(left + w) + "\" y=\"" + fixed(h + bottom + 5) + "\" font-size=\"11\" text-anchor=\"end\">" +
         general(t_max) + " s</text>";
  svg += "<text x=\"" + fixed(left + 6) + "\" y=\"14\" font-size=\"11\" fill=\"#555\">" + markup_escaped(unit) + "</text>\n";
  svg += "<polyline fill=\"none\" stroke=\"#2f6fd0\" stroke-width=\"1.6\" points=\"";
  for (const auto& [t, y] : points)
    svg += fixed(left + w * t / t_max) + "," + fixed(5 + h - h * y / y_max) + " ";
  return svg + "\"/>\n</svg>\n";
}

std::string rate_chart(const RunReport& r) {
  const std::vector<ProgressSample>& s = r.statistics.samples();
  return time_chart(
      s,
      [&](size_t k) -> std::optional<double> {
        if (k == 0) return std::nullopt;
        const double dt = s[k].seconds - s[k - 1].seconds;
        if (!(dt > 0)) return std::nullopt;
        return static_cast<double>(s[k].total - s[k - 1].total) / dt;
      },
      r.progress_unit + " per second");
}

std::string coverage_chart(const RunReport& r) {
  const std::vector<ProgressSample>& s = r.statistics.samples();
  return time_chart(
      s, [&](size_t k) -> std::optional<double> { return s[k].coverage >= 0 ? std::optional<double>(s[k].coverage) : std::nullopt; },
      "edges covered");
}

// ---- sections ----

std::string summary_section(const RunReport& r) {
  std::string html = "<h2>Summary</h2>\n<table class=\"summary\">\n";
  for (const auto& [key, value] : r.summary)
    html += "<tr><th>" + markup_escaped(key) + "</th><td>" + markup_escaped(value) + "</td></tr>\n";
  html += "<tr><th>findings</th><td>" + std::to_string(r.findings.size()) + "</td></tr>\n</table>\n";
  return html;
}

std::string coverage_section(const RunReport& r) {
  std::string html = "<h2>What the run covered</h2>\n";
  if (r.statistics.tables().empty()) html += "<p>(no cases recorded)</p>\n";
  for (const auto& [table, rows] : r.statistics.tables())
    html += "<h3>" + markup_escaped(table) + "</h3>\n" + bar_chart(rows);
  return html;
}

std::string margins_section(const RunReport& r) {
  std::string html =
      "<h2>Checks and margins</h2>\n<p>Each check's error over its tolerance, per measured case (a log scale of "
      "counts); red bins are failures. \"closest\" is the largest ratio of a pass.</p>\n"
      "<table class=\"margins\">\n<tr><th>check</th><th>measured</th><th>skipped</th><th>failed</th><th>closest</th>"
      "<th>error / tolerance</th></tr>\n";
  for (const auto& [name, m] : r.statistics.margins())
    html += "<tr><td>" + markup_escaped(name) + "</td><td>" + std::to_string(m.measured) + "</td><td>" +
            std::to_string(m.skipped) + "</td><td>" + std::to_string(m.failed) + "</td><td>" + general(m.closest) +
            "</td><td>" + margin_histogram(m) + "</td></tr>\n";
  return html + "</table>\n";
}

std::string progress_section(const RunReport& r) {
  std::string html = "<h2>Speed over time</h2>\n" + rate_chart(r);
  const auto& s = r.statistics.samples();
  if (std::any_of(s.begin(), s.end(), [](const ProgressSample& p) { return p.coverage >= 0; }))
    html += "<h2>Coverage over time</h2>\n" + coverage_chart(r);
  return html;
}

std::string finding_section(const ReportedFinding& f, int index) {
  std::string html = "<section class=\"finding\">\n<h3>" + std::to_string(index + 1) + ". " + markup_escaped(f.name) +
                     "</h3>\n<p>" + markup_escaped(f.detail) + "</p>\n";
  if (!f.case_path.empty()) html += "<p>case file: <code>" + markup_escaped(f.case_path) + "</code></p>\n";
  if (!f.replay_command.empty()) html += "<p>replay: <code>" + markup_escaped(f.replay_command) + "</code></p>\n";
  if (!f.pictures.empty()) {
    Json json;
    pictures_json(json, f.pictures);
    html += "<div class=\"case-views\"></div>\n<script type=\"application/json\" class=\"case-data\">" +
            script_safe(json.str()) + "</script>\n";
    html += "<details><summary>static picture (SVG)</summary>\n" + svg_of(f.pictures) + "</details>\n";
  } else if (!f.note.empty()) {
    html += "<p>(" + markup_escaped(f.note) + ")</p>\n";
  }
  if (!f.case_text.empty())
    html += "<details><summary>case file</summary>\n<pre>" + markup_escaped(f.case_text) + "</pre></details>\n";
  return html + "</section>\n";
}

}  // namespace

std::string html_run_report(const RunReport& r) {
  std::string page =
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" + markup_escaped(r.title) +
      "</title>\n<style>\nbody { font-family: sans-serif; margin: 16px; color: #222; max-width: 1400px; }\n"
      "table { border-collapse: collapse; } th, td { border-bottom: 1px solid #ddd; padding: 3px 10px; text-align: left; "
      "vertical-align: middle; }\n.case-views { display: flex; flex-wrap: wrap; gap: 24px; }\n"
      "canvas { border: 1px solid #bbb; cursor: grab; }\npre { font-size: 12px; background: #f6f6f6; padding: 6px; }\n"
      "section.finding { border-top: 2px solid #d0182b; margin-top: 18px; }\n</style>\n" + error_trap_script() +
      "</head>\n<body>\n";
  page += "<h1>" + markup_escaped(r.title) + "</h1>\n";
  page += summary_section(r);
  page += "<h2>Findings</h2>\n";
  if (r.findings.empty()) page += "<p>None.</p>\n";
  for (size_t k = 0; k < r.findings.size(); ++k) page += finding_section(r.findings[k], static_cast<int>(k));
  page += coverage_section(r) + margins_section(r) + progress_section(r);
  page += "<script>\n" + case_viewer_script() + "\n</script>\n</body>\n</html>\n";
  return page;
}

bool write_run_report(const std::string& dir, const RunReport& report, std::string& error) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  const std::string path = (std::filesystem::path(dir) / "report.html").string();
  std::ofstream out(path, std::ios::binary);
  out << html_run_report(report);
  out.close();
  if (ec || !out) {
    error = "cannot write the report " + path;
    return false;
  }
  return true;
}

}  // namespace mfz

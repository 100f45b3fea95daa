// Pictures of cases: the SVG's structure (every element a picture must have,
// every point inside its view, balanced tags), stable bytes, a failing case
// marked where it fails, a relation finding's two runs side by side, and the
// HTML view self-contained.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <cstdlib>
#include <sstream>

#include "case_pictures.h"
#include "render/html_case_view.h"
#include "render/svg_picture.h"
#include "test_support.h"

namespace mfz {
namespace {

// ---- what a test can read off an SVG ----

struct SvgShape {
  bool balanced = true;
  int runs = 0, views = 0;
  std::map<std::string, int> classes;  ///< each class word, how many elements carry it
  std::vector<std::string> outside;    ///< points past their view's square (or the picture)
  double width = 0, height = 0;
};

// The numbers in a list such as "1.00,2.00 3.00,4.00".
std::vector<double> numbers_in(const std::string& text) {
  std::vector<double> out;
  for (const char* at = text.c_str(); *at;) {
    char* end = nullptr;
    const double x = std::strtod(at, &end);
    if (end == at) ++at;
    else out.push_back(x), at = end;
  }
  return out;
}

std::string attribute(const std::string& attributes, const std::string& name) {
  const std::string key = " " + name + "=\"";
  const size_t at = (" " + attributes).find(key);
  if (at == std::string::npos) return "";
  const size_t begin = at + key.size() - 1;  // in `attributes`, past the quote
  return attributes.substr(begin, attributes.find('"', begin) - begin);
}

struct Tag {
  std::string name, attributes;
  bool closing = false, self_closing = false;
};

// The tags of an XML text in order (text between them is skipped).
std::vector<Tag> tags_of(const std::string& xml) {
  std::vector<Tag> tags;
  for (size_t at = xml.find('<'); at != std::string::npos; at = xml.find('<', at + 1)) {
    const size_t end = xml.find('>', at);
    if (end == std::string::npos) break;
    std::string inside = xml.substr(at + 1, end - at - 1);
    Tag t;
    t.closing = !inside.empty() && inside[0] == '/';
    if (t.closing) inside.erase(0, 1);
    t.self_closing = !inside.empty() && inside.back() == '/';
    if (t.self_closing) inside.pop_back();
    const size_t space = inside.find(' ');
    t.name = inside.substr(0, space);
    t.attributes = space == std::string::npos ? "" : inside.substr(space + 1);
    tags.push_back(t);
  }
  return tags;
}

// Reads the SVG's elements in order: the stack of open tags, and for each
// drawing element inside a view its points against that view's square (the
// first <rect> of a view group).
SvgShape shape_of(const std::string& svg) {
  SvgShape s;
  std::vector<std::string> open;
  double left = 0, top = 0, size = -1;  // the current view's square; size < 0: none yet
  bool in_view = false;
  for (const Tag& tag : tags_of(svg)) {
    const std::string &name = tag.name, &attributes = tag.attributes;
    const bool closing = tag.closing, self_closing = tag.self_closing;
    if (closing) {
      if (open.empty() || open.back() != name) s.balanced = false;
      else open.pop_back();
      if (name == "g" && in_view) in_view = false, size = -1;
      continue;
    }
    if (!self_closing) open.push_back(name);
    if (name == "svg") s.width = std::stod(attribute(attributes, "width")), s.height = std::stod(attribute(attributes, "height"));
    std::istringstream words(attribute(attributes, "class"));
    for (std::string word; words >> word;) ++s.classes[word];
    if (name == "g" && attribute(attributes, "class") == "run") ++s.runs;
    if (name == "g" && attribute(attributes, "class") == "view") ++s.views, in_view = true;
    if (name == "rect" && in_view && size < 0) {
      left = std::stod(attribute(attributes, "x")), top = std::stod(attribute(attributes, "y"));
      size = std::stod(attribute(attributes, "width"));
      continue;
    }
    std::vector<double> xy;
    if (name == "polygon") xy = numbers_in(attribute(attributes, "points"));
    if (name == "line")
      xy = {std::stod(attribute(attributes, "x1")), std::stod(attribute(attributes, "y1")),
            std::stod(attribute(attributes, "x2")), std::stod(attribute(attributes, "y2"))};
    if (name == "circle") xy = {std::stod(attribute(attributes, "cx")), std::stod(attribute(attributes, "cy"))};
    if (name == "text") xy = {std::stod(attribute(attributes, "x")), std::stod(attribute(attributes, "y"))};
    for (size_t k = 0; k + 1 < xy.size(); k += 2) {
      const double x = xy[k], y = xy[k + 1];
      const bool in_picture = x >= 0 && x <= s.width && y >= 0 && y <= s.height;
      const bool in_square = !in_view || size < 0 || name == "text" ||
                             (x >= left - 0.01 && x <= left + size + 0.01 && y >= top - 0.01 && y <= top + size + 0.01);
      if (!in_picture || !in_square) s.outside.push_back(name + " at " + std::to_string(x) + "," + std::to_string(y));
    }
  }
  if (!open.empty()) s.balanced = false;
  return s;
}

// ---- pictures through the one pipeline ----

std::vector<CasePicture> pictures(const CaseFile& c, const std::string& plugin = "") {
  std::string error;
  auto session = open_session(plugin.empty() ? "builtin" : std::string(MANIFUZZ_PLUGIN_DIR) + "/" + plugin, 5, error);
  EXPECT_TRUE(session) << error;
  if (!session) return {};
  auto runs = props::pictures_of_case(c, *session, {}, error);
  EXPECT_FALSE(runs.empty()) << error;
  return runs;
}

CaseFile read(const std::string& path) {
  const CaseParse parsed = read_case_file(path);
  EXPECT_TRUE(parsed.value) << parsed.error;
  return *parsed.value;
}

int count(const SvgShape& s, const std::string& cls) {
  const auto found = s.classes.find(cls);
  return found == s.classes.end() ? 0 : found->second;
}

TEST(RenderSvg, HandComputedCasesDrawBothHullsTheContactsAndTheNormalInsideEachView) {
  for (const char* name : {"box_on_box.case", "box_turned_45_on_box.case", "edge_crosses_edge.case",
                           "tetrahedron_tip_in_face.case", "touching.case", "separated.case"}) {
    SCOPED_TRACE(name);
    const std::vector<CasePicture> runs = pictures(read(test::corpus_path(name)));
    ASSERT_EQ(runs.size(), 1u);
    const SvgShape s = shape_of(svg_of(runs));
    EXPECT_TRUE(s.balanced);
    EXPECT_EQ(s.runs, 1);
    EXPECT_EQ(s.views, 4);  // along n, across twice, oblique
    EXPECT_TRUE(s.outside.empty()) << s.outside.size() << " points outside, the first " << s.outside[0];
    EXPECT_GT(count(s, "hull-A"), 0);
    EXPECT_GT(count(s, "hull-B"), 0);
    const mfz_manifold& m = *runs[0].manifold;
    // Every contact is in every view (the views are fitted to them).
    EXPECT_EQ(count(s, "contact"), 4 * m.contact_count);
    EXPECT_EQ(count(s, "contact-on-a"), 4 * m.contact_count);
    EXPECT_EQ(count(s, "normal") > 0, m.colliding == 1);
    EXPECT_EQ(count(s, "broken"), 0);
  }
}

TEST(RenderSvg, AFaceContactHighlightsTheReferenceAndIncidentFacesAndTheClippedPolygon) {
  const std::vector<CasePicture> runs = pictures(read(test::corpus_path("box_on_box.case")));
  ASSERT_EQ(runs.size(), 1u);
  EXPECT_GE(runs[0].reference_face, 0);
  EXPECT_GE(runs[0].clipped_polygon.size(), 3u);
  const SvgShape s = shape_of(svg_of(runs));
  EXPECT_GT(count(s, "reference-face"), 0);
  EXPECT_GT(count(s, "incident-face"), 0);
  EXPECT_GT(count(s, "clipped-polygon"), 0);
}

TEST(RenderSvg, AFailingCaseCirclesTheContactItsCheckNamesAndGivesTheMargin) {
  // The tutorial's method puts contact 1 of F1's frustum off B's surface.
  const std::vector<CasePicture> runs =
      pictures(read(test::corpus_path("regressions/f1-frustum-side-planes-slope-inwards.case")), "libmanifuzz_tutorial.so");
  ASSERT_EQ(runs.size(), 1u);
  ASSERT_TRUE(runs[0].broken);
  EXPECT_EQ(runs[0].broken->name, "on-surface");
  EXPECT_EQ(runs[0].broken->contact, 1);
  const std::string svg = svg_of(runs);
  const SvgShape s = shape_of(svg);
  EXPECT_TRUE(s.outside.empty());
  EXPECT_EQ(count(s, "broken"), 4);
  EXPECT_NE(svg.find("on-surface (contact 1)"), std::string::npos);
  EXPECT_NE(svg.find("FAILS on-surface: error 0.000427 L, tol 1e-09 L"), std::string::npos);
}

TEST(RenderSvg, ARelationFindingShowsTheCaseAndTheTransformedRunSideBySide) {
  // The mutant is built with the mutants (not in the sanitizer preset).
  if (!std::filesystem::exists(std::string(MANIFUZZ_PLUGIN_DIR) + "/libmfz_mutant_swapped_pair.so"))
    GTEST_SKIP() << "the swapped-pair mutant is not built here";
  CaseFile c = read(test::corpus_path("box_on_box.case"));
  c.extensions.push_back("relation swap-symmetry");
  const std::vector<CasePicture> runs = pictures(c, "libmfz_mutant_swapped_pair.so");
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_EQ(runs[1].title, "the swap-symmetry run");
  ASSERT_TRUE(runs[1].broken);
  EXPECT_EQ(runs[1].broken->name, "swap-symmetry");
  const SvgShape s = shape_of(svg_of(runs));
  EXPECT_TRUE(s.balanced);
  EXPECT_EQ(s.runs, 2);
  EXPECT_EQ(s.views, 8);
  EXPECT_TRUE(s.outside.empty());
  EXPECT_DOUBLE_EQ(s.width, 2 * shape_of(svg_of({runs[0]})).width);
}

TEST(RenderSvg, TheSameCaseGivesTheSameBytes) {
  const CaseFile c = read(test::corpus_path("box_turned_45_on_box.case"));
  const std::string first = svg_of(pictures(c)), second = svg_of(pictures(c));
  EXPECT_EQ(first, second);
  EXPECT_EQ(html_case_view(pictures(c), "t"), html_case_view(pictures(c), "t"));
}

TEST(RenderSvg, TheStructureCheckFiresOnAPointOutsideItsViewAndOnAnUnclosedTag) {
  const std::string svg = svg_of(pictures(read(test::corpus_path("box_on_box.case"))));
  std::string moved = svg;
  const size_t at = moved.find("<polygon points=\"") + 17;
  moved.replace(at, moved.find(',', at) - at, "9999.00");
  EXPECT_FALSE(shape_of(moved).outside.empty());
  std::string unclosed = svg;
  unclosed.erase(unclosed.rfind("</g>"), 4);
  EXPECT_FALSE(shape_of(unclosed).balanced);
}

TEST(RenderHtml, TheCaseViewLoadsNothingFromTheNetwork) {
  const std::string html = html_case_view(pictures(read(test::corpus_path("box_on_box.case"))), "box on box");
  EXPECT_EQ(html.find("<script src"), std::string::npos);
  EXPECT_EQ(html.find("<link"), std::string::npos);
  // The one address is the SVG's namespace, which names and loads nothing.
  std::string rest = html;
  for (size_t at; (at = rest.find("http://www.w3.org/2000/svg")) != std::string::npos;) rest.erase(at, 26);
  EXPECT_EQ(rest.find("http://"), std::string::npos);
  EXPECT_EQ(rest.find("https://"), std::string::npos);
  EXPECT_NE(html.find("class=\"case-data\""), std::string::npos);
  EXPECT_NE(html.find(case_viewer_script()), std::string::npos);
}

TEST(RenderHtml, CaseDataCannotCloseItsScriptElement) {
  CaseFile c = read(test::corpus_path("box_on_box.case"));
  std::vector<CasePicture> runs = pictures(c);
  runs[0].legend.push_back("</script><script>alert(1)</script>");
  const std::string html = html_case_view(runs, "t");
  EXPECT_EQ(html.find("</script><script>alert(1)"), std::string::npos);
}

TEST(ContactNamedIn, ReadsTheContactOfADetailAndNothingElse) {
  EXPECT_EQ(contact_named_in("distance to own surface (contact 3)"), 3);
  EXPECT_EQ(contact_named_in("the swap-symmetry run fails on-surface: x (contact 12) (error 1 L, tol 2 L)"), 12);
  EXPECT_EQ(contact_named_in("depth 0.1, exact 0.2"), -1);
  EXPECT_EQ(contact_named_in("(contact x)"), -1);
}

}  // namespace
}  // namespace mfz

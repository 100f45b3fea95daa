#include "render/svg_picture.h"

#include "render/markup.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>

namespace mfz {
namespace {

using Point2 = std::array<double, 2>;
using Polygon2 = std::vector<Point2>;

constexpr double kGap = 16;                // between views, and around a panel
constexpr double kTitleHeight = 24;
constexpr double kLegendLine = 15;
constexpr double kPanelWidth = 2 * kSvgViewSize + 3 * kGap;
const char* const kColourA = "#2f6fd0";
const char* const kColourB = "#e07a1f";
const char* const kColourClipped = "#1f9a4a";
const char* const kColourBroken = "#d0182b";

std::string number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", x);
  return std::string(text) == "-0.00" ? "0.00" : text;
}


// ---- one view: a projection of world space onto a square of the SVG ----

struct View {
  std::string name;
  Vec3 right, up;  ///< unit, orthogonal; the viewer looks along up x right
  double left = 0, top = 0;  ///< the view's corner in the SVG
  Vec3 centre = Vec3::Zero();
  double pixels_per_unit = 1;

  Vec3 towards_viewer() const { return right.cross(up); }
  Point2 at(const Vec3& p) const {
    const Vec3 d = p - centre;
    return {left + kSvgViewSize / 2 + pixels_per_unit * d.dot(right),
            top + kSvgViewSize / 2 - pixels_per_unit * d.dot(up)};
  }
  bool inside(const Point2& q) const {
    return q[0] >= left && q[0] <= left + kSvgViewSize && q[1] >= top && q[1] <= top + kSvgViewSize;
  }
};

std::vector<View> views_of(const CasePicture& p) {
  const Vec3 &n = p.normal, &t1 = p.across_1, &t2 = p.across_2;
  // Oblique: turned 35 degrees about n, then tipped 25 degrees towards n.
  const double turn = 35 * M_PI / 180, tip = 25 * M_PI / 180;
  const Vec3 side = std::cos(turn) * t1 + std::sin(turn) * t2;
  const Vec3 back = n.cross(side);
  const Vec3 up = std::cos(tip) * n + std::sin(tip) * back;
  return {{"along n (from B towards A)", t1, t2},
          {"across n: t1 right, n up", t1, n},
          {"across n: t2 right, n up", t2, n},
          {"oblique", side, up.normalized()}};
}

// What a view must show: the smaller hull, the contacts and the clipped
// polygon (a large hull is cut off at the view's edge).
std::vector<Vec3> points_of_interest(const CasePicture& p) {
  const auto diameter = [](const DrawnHull& h) {
    Vec3 low = Vec3::Constant(std::numeric_limits<double>::infinity()), high = -low;
    for (const Vec3& v : h.vertices) low = low.cwiseMin(v), high = high.cwiseMax(v);
    return h.vertices.empty() ? 0.0 : (high - low).norm();
  };
  std::vector<Vec3> points = diameter(p.a) <= diameter(p.b) ? p.a.vertices : p.b.vertices;
  if (p.manifold)
    for (int i = 0; i < std::clamp(p.manifold->contact_count, 0, MFZ_MAX_CONTACTS); ++i) {
      const mfz_contact& c = p.manifold->contacts[i];
      if (to_vec(c.point_on_a).allFinite()) points.push_back(to_vec(c.point_on_a));
      if (to_vec(c.point_on_b).allFinite()) points.push_back(to_vec(c.point_on_b));
    }
  points.insert(points.end(), p.clipped_polygon.begin(), p.clipped_polygon.end());
  return points;
}

void fit(View& view, const std::vector<Vec3>& points) {
  double low_x = INFINITY, high_x = -INFINITY, low_y = INFINITY, high_y = -INFINITY, low_z = INFINITY, high_z = -INFINITY;
  const Vec3 depth = view.towards_viewer();
  for (const Vec3& q : points) {
    low_x = std::min(low_x, q.dot(view.right)), high_x = std::max(high_x, q.dot(view.right));
    low_y = std::min(low_y, q.dot(view.up)), high_y = std::max(high_y, q.dot(view.up));
    low_z = std::min(low_z, q.dot(depth)), high_z = std::max(high_z, q.dot(depth));
  }
  if (points.empty()) low_x = high_x = low_y = high_y = low_z = high_z = 0;
  view.centre = 0.5 * ((low_x + high_x) * view.right + (low_y + high_y) * view.up + (low_z + high_z) * depth);
  const double span = std::max({high_x - low_x, high_y - low_y, 1e-300});
  view.pixels_per_unit = 0.8 * kSvgViewSize / span;
}

// ---- clipping to a view's square: Sutherland-Hodgman in 2-D, Liang-Barsky ----

Polygon2 clip_to_view(const Polygon2& polygon, const View& v) {
  Polygon2 out = polygon;
  const double bounds[4] = {v.left, v.left + kSvgViewSize, v.top, v.top + kSvgViewSize};
  for (int side = 0; side < 4 && !out.empty(); ++side) {
    const int axis = side / 2;
    const bool keep_above = side % 2 == 0;
    const auto inside = [&](const Point2& q) { return keep_above ? q[axis] >= bounds[side] : q[axis] <= bounds[side]; };
    Polygon2 next;
    for (size_t k = 0; k < out.size(); ++k) {
      const Point2 &p = out[k], &q = out[(k + 1) % out.size()];
      if (inside(p)) next.push_back(p);
      if (inside(p) != inside(q)) {
        const double s = (bounds[side] - p[axis]) / (q[axis] - p[axis]);
        next.push_back({p[0] + s * (q[0] - p[0]), p[1] + s * (q[1] - p[1])});
      }
    }
    out = std::move(next);
  }
  return out;
}

bool clip_segment(Point2& p, Point2& q, const View& v) {
  double t0 = 0, t1 = 1;
  const double dx = q[0] - p[0], dy = q[1] - p[1];
  const double ps[4] = {-dx, dx, -dy, dy};
  const double qs[4] = {p[0] - v.left, v.left + kSvgViewSize - p[0], p[1] - v.top, v.top + kSvgViewSize - p[1]};
  for (int k = 0; k < 4; ++k) {
    if (ps[k] == 0) {
      if (qs[k] < 0) return false;
      continue;
    }
    const double r = qs[k] / ps[k];
    if (ps[k] < 0) t0 = std::max(t0, r);
    else t1 = std::min(t1, r);
  }
  if (t0 > t1) return false;
  const Point2 from = p;
  p = {from[0] + t0 * dx, from[1] + t0 * dy};
  q = {from[0] + t1 * dx, from[1] + t1 * dy};
  return true;
}

// ---- drawing ----

class Svg {
 public:
  void raw(const std::string& s) { out_ += s; }
  void polygon(const Polygon2& points, const std::string& style) {
    if (points.size() < 3) return;
    out_ += "<polygon points=\"";
    for (size_t k = 0; k < points.size(); ++k) out_ += (k ? " " : "") + number(points[k][0]) + "," + number(points[k][1]);
    out_ += "\" " + style + "/>\n";
  }
  void line(Point2 p, Point2 q, const View& v, const std::string& style) {
    if (!clip_segment(p, q, v)) return;
    out_ += "<line x1=\"" + number(p[0]) + "\" y1=\"" + number(p[1]) + "\" x2=\"" + number(q[0]) + "\" y2=\"" +
            number(q[1]) + "\" " + style + "/>\n";
  }
  void circle(const Point2& c, double r, const View& v, const std::string& style) {
    if (!v.inside(c)) return;
    out_ += "<circle cx=\"" + number(c[0]) + "\" cy=\"" + number(c[1]) + "\" r=\"" + number(r) + "\" " + style + "/>\n";
  }
  void text(double x, double y, const std::string& s, const std::string& style = "") {
    out_ += "<text x=\"" + number(x) + "\" y=\"" + number(y) + "\"" + (style.empty() ? "" : " " + style) + ">" +
            markup_escaped(s) + "</text>\n";
  }
  const std::string& str() const { return out_; }

 private:
  std::string out_;
};

struct FaceToDraw {
  double depth;  ///< mean distance towards the viewer: far faces first
  char hull;
  int face;
};

Polygon2 projected_face(const DrawnHull& h, int f, const View& v) {
  Polygon2 points;
  for (const int i : h.faces[f]) points.push_back(v.at(h.vertices[i]));
  return clip_to_view(points, v);
}

void draw_hull_faces(Svg& svg, const CasePicture& p, const View& v) {
  std::vector<FaceToDraw> faces;
  const Vec3 depth = v.towards_viewer();
  for (const char which : {'A', 'B'}) {
    const DrawnHull& h = which == 'A' ? p.a : p.b;
    for (int f = 0; f < static_cast<int>(h.faces.size()); ++f) {
      Vec3 mean = Vec3::Zero();
      for (const int i : h.faces[f]) mean += h.vertices[i];
      faces.push_back({depth.dot(mean / static_cast<double>(h.faces[f].size())), which, f});
    }
  }
  std::stable_sort(faces.begin(), faces.end(), [](const FaceToDraw& x, const FaceToDraw& y) { return x.depth < y.depth; });
  for (const FaceToDraw& face : faces) {
    const DrawnHull& h = face.hull == 'A' ? p.a : p.b;
    const std::string colour = face.hull == 'A' ? kColourA : kColourB;
    const bool reference = face.hull == p.reference_hull && face.face == p.reference_face;
    const bool incident = face.hull != p.reference_hull && face.face == p.incident_face;
    std::string style = "fill=\"" + colour + "\" fill-opacity=\"" + (reference ? "0.40" : "0.08") + "\" stroke=\"" +
                        colour + "\" stroke-width=\"" + (reference || incident ? "2.2" : "0.8") + "\"";
    if (incident) style += " stroke-dasharray=\"6 3\"";
    style += " class=\"" + std::string(reference ? "reference-face" : incident ? "incident-face" : "face") + " hull-" +
             face.hull + "\"";
    svg.polygon(projected_face(h, face.face, v), style);
  }
}

void draw_clipped_polygon(Svg& svg, const CasePicture& p, const View& v) {
  Polygon2 points;
  for (const Vec3& q : p.clipped_polygon) points.push_back(v.at(q));
  svg.polygon(clip_to_view(points, v), std::string("fill=\"none\" stroke=\"") + kColourClipped +
                                           "\" stroke-width=\"2\" class=\"clipped-polygon\"");
}

Vec3 contact_centre(const CasePicture& p) {
  Vec3 sum = Vec3::Zero();
  int count = 0;
  if (p.manifold)
    for (int i = 0; i < std::clamp(p.manifold->contact_count, 0, MFZ_MAX_CONTACTS); ++i) {
      const Vec3 mid = 0.5 * (to_vec(p.manifold->contacts[i].point_on_a) + to_vec(p.manifold->contacts[i].point_on_b));
      if (mid.allFinite()) sum += mid, ++count;
    }
  return count ? Vec3(sum / count) : Vec3::Zero();
}

void draw_contacts(Svg& svg, const CasePicture& p, const View& v) {
  if (!p.manifold) return;
  for (int i = 0; i < std::clamp(p.manifold->contact_count, 0, MFZ_MAX_CONTACTS); ++i) {
    const Vec3 on_a = to_vec(p.manifold->contacts[i].point_on_a), on_b = to_vec(p.manifold->contacts[i].point_on_b);
    if (!on_a.allFinite() || !on_b.allFinite()) continue;
    svg.line(v.at(on_a), v.at(on_b), v, "stroke=\"#222\" stroke-width=\"1.4\" class=\"contact\"");
    svg.circle(v.at(on_a), 2.6, v, std::string("fill=\"") + kColourA + "\" class=\"contact-on-a\"");
    svg.circle(v.at(on_b), 2.6, v, std::string("fill=\"") + kColourB + "\" class=\"contact-on-b\"");
  }
}

// The normal as an arrow from the contacts' centre (the origin of the view's
// fit when there are none); seen along n, a dot in a ring.
void draw_normal(Svg& svg, const CasePicture& p, const View& v) {
  if (!p.manifold || p.manifold->colliding != 1) return;
  const Vec3 from = p.manifold->contact_count > 0 ? contact_centre(p) : v.centre;
  const Point2 tail = v.at(from), head = v.at(from + (0.25 * kSvgViewSize / v.pixels_per_unit) * p.normal);
  const double dx = head[0] - tail[0], dy = head[1] - tail[1], length = std::hypot(dx, dy);
  const std::string style = "stroke=\"#111\" stroke-width=\"1.8\" class=\"normal\"";
  if (length < 6) {
    svg.circle(tail, 7, v, "fill=\"none\" " + style);
    svg.circle(tail, 1.8, v, "fill=\"#111\" class=\"normal\"");
    return;
  }
  svg.line(tail, head, v, style);
  const double ux = dx / length, uy = dy / length;
  svg.polygon(clip_to_view({head, {head[0] - 9 * ux - 4 * uy, head[1] - 9 * uy + 4 * ux},
                            {head[0] - 9 * ux + 4 * uy, head[1] - 9 * uy - 4 * ux}},
                           v),
              "fill=\"#111\" class=\"normal-head\"");
}

std::string margin_text(const BrokenCheck& b) {
  char text[200];
  if (b.tolerance > 0)
    std::snprintf(text, sizeof text, "%s: error %.3g L, tol %.3g L (%.3g x tol)", b.name.c_str(), b.error, b.tolerance,
                  b.error / b.tolerance);
  else
    std::snprintf(text, sizeof text, "%s", b.name.c_str());
  return text;
}

void draw_broken_contact(Svg& svg, const CasePicture& p, const View& v) {
  if (!p.broken || p.broken->contact < 0 || !p.manifold) return;
  const mfz_contact& c = p.manifold->contacts[p.broken->contact];
  const Vec3 mid = 0.5 * (to_vec(c.point_on_a) + to_vec(c.point_on_b));
  if (!mid.allFinite()) return;
  const Point2 at = v.at(mid);
  svg.circle(at, 10, v, std::string("fill=\"none\" stroke=\"") + kColourBroken + "\" stroke-width=\"2\" class=\"broken\"");
  if (v.inside(at))
    svg.text(std::clamp(at[0] + 12, v.left + 2, v.left + kSvgViewSize - 150), std::clamp(at[1] - 12, v.top + 12, v.top + kSvgViewSize - 4),
             p.broken->name + " (contact " + std::to_string(p.broken->contact) + ")",
             std::string("font-size=\"10\" fill=\"") + kColourBroken + "\" class=\"broken-label\"");
}

void draw_view(Svg& svg, const CasePicture& p, const View& v) {
  svg.raw("<g class=\"view\" data-view=\"" + markup_escaped(v.name) + "\">\n");
  svg.raw("<rect x=\"" + number(v.left) + "\" y=\"" + number(v.top) + "\" width=\"" + number(kSvgViewSize) +
          "\" height=\"" + number(kSvgViewSize) + "\" fill=\"#fcfcfc\" stroke=\"#bbb\"/>\n");
  draw_hull_faces(svg, p, v);
  draw_clipped_polygon(svg, p, v);
  draw_contacts(svg, p, v);
  draw_normal(svg, p, v);
  draw_broken_contact(svg, p, v);
  svg.text(v.left + 4, v.top + 12, v.name, "font-size=\"10\" fill=\"#555\"");
  svg.raw("</g>\n");
}

std::vector<std::string> key_lines(const CasePicture& p) {
  std::vector<std::string> lines = p.legend;
  if (p.broken) {
    lines.push_back("FAILS " + margin_text(*p.broken));
    if (!p.broken->detail.empty()) lines.push_back("  " + p.broken->detail);
  }
  return lines;
}

double panel_height(const CasePicture& p) {
  return kTitleHeight + 2 * kSvgViewSize + 3 * kGap + kLegendLine * (key_lines(p).size() + 2) + kGap;
}

void draw_key(Svg& svg, double x, double y) {
  const std::pair<const char*, const char*> items[] = {{kColourA, "hull A"}, {kColourB, "hull B"},
                                                       {kColourClipped, "clipped polygon"}, {kColourBroken, "broken check"}};
  double at = x;
  for (const auto& [colour, what] : items) {
    svg.raw("<rect x=\"" + number(at) + "\" y=\"" + number(y - 9) + "\" width=\"10\" height=\"10\" fill=\"" + colour + "\"/>\n");
    svg.text(at + 14, y, what, "font-size=\"11\"");
    at += 110;
  }
  svg.text(x, y + kLegendLine,
           "filled: reference face; dashed: incident face; segments: each contact's point on A to its point on B; arrow: n",
           "font-size=\"10\" fill=\"#444\"");
}

void draw_panel(Svg& svg, const CasePicture& p, double left) {
  svg.raw("<g class=\"run\" data-title=\"" + markup_escaped(p.title) + "\">\n");
  svg.text(left + kGap, kGap + 12, p.title, "font-size=\"14\" font-weight=\"bold\"");
  std::vector<View> views = views_of(p);
  const std::vector<Vec3> points = points_of_interest(p);
  for (size_t k = 0; k < views.size(); ++k) {
    views[k].left = left + kGap + (k % 2) * (kSvgViewSize + kGap);
    views[k].top = kTitleHeight + kGap + (k / 2) * (kSvgViewSize + kGap);
    fit(views[k], points);
    draw_view(svg, p, views[k]);
  }
  double y = kTitleHeight + 2 * kSvgViewSize + 3 * kGap + 10;
  draw_key(svg, left + kGap, y);
  y += 2 * kLegendLine;
  for (std::string line : key_lines(p)) {
    if (line.size() > 110) line = line.substr(0, 107) + "...";
    const bool fails = line.rfind("FAILS", 0) == 0;
    svg.text(left + kGap, y, line, fails ? std::string("font-size=\"11\" fill=\"") + kColourBroken + "\" class=\"legend\""
                                         : "font-size=\"11\" class=\"legend\"");
    y += kLegendLine;
  }
  svg.raw("</g>\n");
}

}  // namespace

std::string svg_of(const std::vector<CasePicture>& runs) {
  double height = 0;
  for (const CasePicture& p : runs) height = std::max(height, panel_height(p));
  const double width = kPanelWidth * std::max<size_t>(1, runs.size());
  Svg svg;
  svg.raw("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + number(width) + "\" height=\"" + number(height) +
          "\" viewBox=\"0 0 " + number(width) + " " + number(height) + "\" font-family=\"sans-serif\">\n");
  svg.raw("<rect x=\"0\" y=\"0\" width=\"" + number(width) + "\" height=\"" + number(height) + "\" fill=\"#ffffff\"/>\n");
  for (size_t k = 0; k < runs.size(); ++k) draw_panel(svg, runs[k], k * kPanelWidth);
  svg.raw("</svg>\n");
  return svg.str();
}

}  // namespace mfz

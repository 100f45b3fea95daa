#include "render/html_case_view.h"

#include <algorithm>

#include "harness/report.h"
#include "render/markup.h"
#include "render/case_viewer_script.h"
#include "render/svg_picture.h"

namespace mfz {
namespace {

void hull_json(Json& json, const DrawnHull& h) {
  json.begin_object().key("vertices").begin_array();
  for (const Vec3& v : h.vertices) json.value(v);
  json.end_array().key("faces").begin_array();
  for (const std::vector<int>& loop : h.faces) {
    json.begin_array();
    for (const int i : loop) json.value(i);
    json.end_array();
  }
  json.end_array().end_object();
}

void picture_json(Json& json, const CasePicture& p) {
  json.begin_object().key("title").value(p.title);
  json.key("a");
  hull_json(json, p.a);
  json.key("b");
  hull_json(json, p.b);
  json.key("normal").value(p.normal).key("across1").value(p.across_1).key("across2").value(p.across_2);
  json.key("referenceHull").value(std::string(1, p.reference_hull)).key("referenceFace").value(p.reference_face);
  json.key("incidentFace").value(p.incident_face);
  json.key("clipped").begin_array();
  for (const Vec3& q : p.clipped_polygon) json.value(q);
  json.end_array();
  json.key("colliding").value(p.manifold && p.manifold->colliding == 1);
  json.key("contacts").begin_array();
  if (p.manifold)
    for (int i = 0; i < std::clamp(p.manifold->contact_count, 0, MFZ_MAX_CONTACTS); ++i) {
      const mfz_contact& c = p.manifold->contacts[i];
      json.begin_object().key("a").value(to_vec(c.point_on_a)).key("b").value(to_vec(c.point_on_b));
      json.key("penetration").value(c.penetration).end_object();
    }
  json.end_array();
  if (p.broken) {
    json.key("broken").begin_object().key("name").value(p.broken->name).key("contact").value(p.broken->contact);
    json.key("error").value(p.broken->error).key("tolerance").value(p.broken->tolerance);
    json.key("detail").value(p.broken->detail).end_object();
  }
  json.key("legend").begin_array();
  for (const std::string& line : p.legend) json.value(line);
  json.end_array().end_object();
}


}  // namespace


void pictures_json(Json& json, const std::vector<CasePicture>& runs) {
  json.begin_array();
  for (const CasePicture& p : runs) picture_json(json, p);
  json.end_array();
}

const std::string& error_trap_script() {
  static const std::string script =
      "<script>window.addEventListener(\"error\", function (e) { document.documentElement.dataset.scriptError = "
      "String(e.message || \"error\"); });</script>\n";
  return script;
}

const std::string& case_viewer_script() {
  static const std::string script(kCaseViewerScript);
  return script;
}

std::string html_case_view(const std::vector<CasePicture>& runs, const std::string& title) {
  Json json;
  pictures_json(json, runs);
  std::string page;
  page += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" + markup_escaped(title) +
          "</title>\n<style>\nbody { font-family: sans-serif; margin: 16px; color: #222; }\n"
          ".case-views { display: flex; flex-wrap: wrap; gap: 24px; }\ncanvas { border: 1px solid #bbb; cursor: grab; }\n"
          "button { margin: 2px 4px 6px 0; }\npre { font-size: 12px; }\n</style>\n" + error_trap_script() +
          "</head>\n<body>\n";
  page += "<h1>" + markup_escaped(title) + "</h1>\n";
  page += "<p>Drag to rotate, wheel to zoom; the buttons return to the contact frame's views. "
          "The static picture (SVG) follows.</p>\n";
  page += "<div class=\"case-views\" data-case-views=\"0\"></div>\n";
  page += "<script type=\"application/json\" class=\"case-data\">" + script_safe(json.str()) + "</script>\n";
  page += "<h2>Static picture</h2>\n" + svg_of(runs);
  page += "<script>\n" + case_viewer_script() + "\n</script>\n</body>\n</html>\n";
  return page;
}

}  // namespace mfz

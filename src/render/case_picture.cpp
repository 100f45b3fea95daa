#include "render/case_picture.h"

#include <cmath>
#include <cstdio>

#include "generator/clipping_generator.h"

namespace mfz {
namespace {

DrawnHull drawn(const Hull& hull, const std::vector<Vec3>& world) {
  DrawnHull d;
  d.vertices = world;
  for (int f = 0; f < hull.face_count(); ++f) {
    std::vector<int> loop;
    for (int k = 0; k < hull.face_size(f); ++k) loop.push_back(hull.face_vertex(f, k));
    d.faces.push_back(std::move(loop));
  }
  return d;
}

std::string line(const char* format, double x) {
  char text[160];
  std::snprintf(text, sizeof text, format, x);
  return text;
}

std::string vec_line(const char* what, const Vec3& v) {
  char text[200];
  std::snprintf(text, sizeof text, "%s (%.6g, %.6g, %.6g)", what, v.x(), v.y(), v.z());
  return text;
}

// The clipping method's faces and clipped polygon on this geometry, from the
// built-in run with a trace; an edge-edge axis or a separated pair has none.
void add_clipping(CasePicture& picture, const Scene& scene) {
  ClipTrace trace;
  mfz_manifold ignored;
  generate_clipping_manifold(scene.hull_a.view(), scene.abi_pose_a(), scene.hull_b.view(), scene.abi_pose_b(),
                             ignored, &trace);
  if (trace.sat.separated || trace.edge_contact || trace.face_a < 0 || trace.face_b < 0) return;
  picture.reference_hull = trace.flipped ? 'B' : 'A';
  picture.reference_face = trace.flipped ? trace.face_b : trace.face_a;
  picture.incident_face = trace.flipped ? trace.face_a : trace.face_b;
  // The polygon after the last side plane, before the points above the
  // reference plane go: what Sutherland-Hodgman made of the incident face.
  for (const ClipTrace::Step& step : trace.steps)
    if (step.what.rfind("clipped against", 0) == 0 || picture.clipped_polygon.empty())
      picture.clipped_polygon = step.polygon;
}

void add_legend(CasePicture& p, const Scene& scene, const Verdict* verdict, const ExactDepth* exact,
                const std::string& generator) {
  p.legend.push_back("generator " + generator);
  p.legend.push_back(line("L (the larger diameter) %.6g", scene.scale));
  if (!p.manifold) {
    p.legend.push_back("no manifold: the generator gave no answer");
  } else if (p.manifold->colliding != 1) {
    p.legend.push_back("colliding 0 (no contacts expected)");
  } else {
    p.legend.push_back(vec_line("normal n", to_vec(p.manifold->normal)));
    p.legend.push_back(line("penetration %.9g", p.manifold->penetration));
    p.legend.push_back("contacts " + std::to_string(p.manifold->contact_count));
    for (int i = 0; i < p.manifold->contact_count && i < 8; ++i)
      p.legend.push_back("  contact " + std::to_string(i) + line(": penetration %.6g", p.manifold->contacts[i].penetration));
    if (p.manifold->contact_count > 8) p.legend.push_back("  ...");
  }
  if (exact)
    p.legend.push_back(exact->colliding ? line("exact depth %.9g", exact->signed_depth)
                                        : line("exact gap %.9g", -exact->signed_depth));
  if (p.reference_face >= 0)
    p.legend.push_back(std::string("reference face: ") + p.reference_hull + "'s face " + std::to_string(p.reference_face) +
                       "; incident face: " + (p.reference_hull == 'A' ? 'B' : 'A') + "'s face " +
                       std::to_string(p.incident_face) + " (the built-in clipping method's choice)");
  if (verdict) {
    int failed = 0;
    for (const InvariantCheck& c : verdict->checks) failed += c.status == CheckStatus::fail;
    p.legend.push_back(verdict->refused() ? std::string("refused") : "checks failed: " + std::to_string(failed));
  }
}

}  // namespace

void frame_across(const Vec3& normal, Vec3& across_1, Vec3& across_2) {
  // The world axis least along n, made perpendicular: no special case, and
  // the same n always gives the same frame.
  const Vec3 a = normal.cwiseAbs();
  const Vec3 seed = a.x() <= a.y() && a.x() <= a.z() ? Vec3::UnitX() : (a.y() <= a.z() ? Vec3::UnitY() : Vec3::UnitZ());
  across_1 = (seed - normal.dot(seed) * normal).normalized();
  across_2 = normal.cross(across_1);
}

CasePicture picture_of_run(const Scene& scene, const mfz_manifold* manifold, const Verdict* verdict,
                           const ExactDepth* exact, const std::string& title, const std::string& generator) {
  CasePicture p;
  p.title = title;
  p.a = drawn(scene.hull_a, scene.world_a);
  p.b = drawn(scene.hull_b, scene.world_b);
  if (manifold) p.manifold = *manifold;
  p.scale = scene.scale;
  Vec3 n = exact ? exact->normal : Vec3::UnitZ();
  if (manifold && manifold->colliding == 1 && to_vec(manifold->normal).allFinite() && to_vec(manifold->normal).norm() > 0.5)
    n = to_vec(manifold->normal);
  p.normal = n.allFinite() && n.norm() > 0 ? n.normalized() : Vec3::UnitZ();
  frame_across(p.normal, p.across_1, p.across_2);
  add_clipping(p, scene);
  add_legend(p, scene, verdict, exact, generator);
  if (verdict)
    if (const InvariantCheck* bad = verdict->first_violation())
      mark_broken_check(p, bad->name, bad->detail, bad->error, bad->tolerance);
  return p;
}

void mark_broken_check(CasePicture& picture, const std::string& name, const std::string& detail, double error,
                       double tolerance) {
  BrokenCheck broken{name, detail, error, tolerance, contact_named_in(detail)};
  const int count = picture.manifold ? picture.manifold->contact_count : 0;
  if (broken.contact >= count) broken.contact = -1;
  picture.broken = broken;
}

}  // namespace mfz

#include "geometry/qhull_facets.h"

#include <cstdio>

extern "C" {
#include <libqhull_r/qhull_ra.h>
}

namespace mfz {
namespace {

// Qhull writes its diagnostics to a FILE*; keep the first line as the reason.
std::string first_line_of(FILE* file) {
  std::fflush(file);
  std::rewind(file);
  char line[512] = {0};
  if (!std::fgets(line, sizeof line, file)) return "qhull failed";
  std::string text(line);
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
  return text;
}

}  // namespace

std::vector<QhullFacet> qhull_facets(const std::vector<Vec3>& points, bool triangulate,
                                     std::string& error) {
  std::vector<QhullFacet> facets;
  std::vector<coordT> coords;
  coords.reserve(points.size() * 3);
  for (const Vec3& p : points) coords.insert(coords.end(), {p.x(), p.y(), p.z()});

  // An in-memory stream: a temporary file per hull would cost a syscall each.
  char message[1024] = {0};
  FILE* errors = fmemopen(message, sizeof message, "w+");
  qhT qh_storage;
  qhT* qh = &qh_storage;
  qh_zero(qh, errors);
  char options[] = "qhull Qt";
  if (!triangulate) options[5] = '\0';
  const int status = qh_new_qhull(qh, 3, static_cast<int>(points.size()), coords.data(),
                                  False, options, nullptr, errors);
  if (status != 0) {
    error = errors ? first_line_of(errors) : "qhull failed";
  } else {
    facetT* facet;
    vertexT *vertex, **vertexp;
    facets.reserve(static_cast<size_t>(qh->num_facets));
    FORALLfacets {
      QhullFacet out;
      out.point_ids.reserve(static_cast<size_t>(qh_setsize(qh, facet->vertices)));
      out.normal = Vec3(facet->normal[0], facet->normal[1], facet->normal[2]);
      // Qhull's plane is normal . x + offset = 0, with the inside negative.
      out.offset = -facet->offset;
      FOREACHvertex_(facet->vertices) out.point_ids.push_back(qh_pointid(qh, vertex->point));
      facets.push_back(std::move(out));
    }
  }
  qh_freeqhull(qh, !qh_ALL);
  int still_long = 0, total_long = 0;
  qh_memfreeshort(qh, &still_long, &total_long);
  if (errors) std::fclose(errors);
  return facets;
}

}  // namespace mfz

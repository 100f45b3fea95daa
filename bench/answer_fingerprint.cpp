// Whether a change to a generator changed any of its answers: every pair of
// the generator benchmark's families, in both orders (A, B and B, A), through
// each plugin named, and per family a SHA-256 of the answers' bytes (the
// verdict, the normal, the penetration, and each contact in order). With two
// plugins it also counts the calls whose answers differ, shows the first,
// and how far the answers moved (points, depth, normal; Change below).
// A speed change that claims to keep every answer is checked with it against
// the plugin built before the change, on the same pairs the timings use. A
// change meant to alter some answers names a folder too: each call whose
// answers differ (the first 100) is written there as a case file
// (FAMILY-PAIR[-swapped].case), for `manifuzz replay` to judge both answers.
//
//   answer_fingerprint PLUGIN [BASELINE [CASE_FOLDER]]   (`builtin` names the built-in)
//
// Exits 0 when the answers are the same bytes (or with one plugin), 1 when
// two plugins differ, 2 on bad arguments or a library that is no generator.
#include <openssl/evp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bench_families.h"
#include "case/case_file.h"
#include "harness/generator.h"

namespace mfz {
namespace {

// The bytes of an answer that a generator decides; the rest of the
// manifold is the harness's poison.
std::vector<unsigned char> answer_bytes(int32_t status, const mfz_manifold& m) {
  std::vector<unsigned char> bytes;
  bytes.reserve(sizeof status + sizeof m);
  const auto put = [&bytes](const void* data, size_t size) {
    const auto* p = static_cast<const unsigned char*>(data);
    bytes.insert(bytes.end(), p, p + size);
  };
  put(&status, sizeof status);
  if (status != 0) return bytes;
  put(&m.colliding, sizeof m.colliding);
  put(&m.normal, sizeof m.normal);
  put(&m.penetration, sizeof m.penetration);
  put(&m.contact_count, sizeof m.contact_count);
  const int count = m.contact_count < 0 || m.contact_count > MFZ_MAX_CONTACTS ? 0 : m.contact_count;
  put(m.contacts, sizeof(mfz_contact) * static_cast<size_t>(count));
  return bytes;
}

struct Answer {
  int32_t status = 0;
  mfz_manifold manifold{};
  std::vector<unsigned char> bytes;
};

Answer answer(const Generator& g, const Scene& s, bool swapped) {
  const mfz_hull a = s.hull_a.view(), b = s.hull_b.view();
  const mfz_pose pa = s.abi_pose_a(), pb = s.abi_pose_b();
  Answer out;
  out.status = swapped ? g.generate(b, pb, a, pa, out.manifold) : g.generate(a, pa, b, pb, out.manifold);
  out.bytes = answer_bytes(out.status, out.manifold);
  return out;
}

// How far two answers of one call are apart, where they have the same shape
// (status, verdict and contact count): the largest move of a contact point
// and of the depth, in units of the case's L, and of the normal. A change
// that fixes rounding moves them by rounding; `shape` counts the rest.
struct Change {
  double point = 0, depth = 0, normal = 0;
  long long shape = 0;
  void add(const Answer& x, const Answer& y, double scale) {
    const mfz_manifold &m = x.manifold, &n = y.manifold;
    if (x.status != y.status || x.status != 0 || m.colliding != n.colliding || m.contact_count != n.contact_count) {
      ++shape;
      return;
    }
    normal = std::max(normal, (to_vec(m.normal) - to_vec(n.normal)).norm());
    depth = std::max(depth, std::abs(m.penetration - n.penetration) / scale);
    for (int i = 0; i < m.contact_count && i < MFZ_MAX_CONTACTS; ++i)
      point = std::max({point, (to_vec(m.contacts[i].point_on_a) - to_vec(n.contacts[i].point_on_a)).norm() / scale,
                        (to_vec(m.contacts[i].point_on_b) - to_vec(n.contacts[i].point_on_b)).norm() / scale});
  }
};

struct Digest {
  std::unique_ptr<EVP_MD_CTX, decltype(&EVP_MD_CTX_free)> context{EVP_MD_CTX_new(), EVP_MD_CTX_free};
  Digest() { EVP_DigestInit_ex(context.get(), EVP_sha256(), nullptr); }
  void add(const std::vector<unsigned char>& bytes) { EVP_DigestUpdate(context.get(), bytes.data(), bytes.size()); }
  std::string hex() {
    unsigned char digest[EVP_MAX_MD_SIZE];
    unsigned int length = 0;
    EVP_DigestFinal_ex(context.get(), digest, &length);
    std::string text;
    char two[3];
    for (unsigned int i = 0; i < length; ++i) std::snprintf(two, sizeof two, "%02x", digest[i]), text += two;
    return text.substr(0, 16);
  }
};

// A folder gets the first this many differing calls: a change meant to
// alter a few answers is judged on all of them, and another generator's
// thousands of answers do not fill the disk.
constexpr long long kWrittenCalls = 100;

// The call as a case file: the hulls' vertices and poses, in the call's order.
bool write_call(const std::string& folder, const std::string& family, size_t pair, bool swapped, const Scene& s) {
  CaseFile c;
  const auto vertices = [](const Hull& hull) {
    std::vector<Vec3> points;
    for (int i = 0; i < hull.vertex_count(); ++i) points.push_back(hull.vertex(i));
    return points;
  };
  c.points_a = vertices(swapped ? s.hull_b : s.hull_a);
  c.points_b = vertices(swapped ? s.hull_a : s.hull_b);
  c.pose_a = swapped ? s.pose_b : s.pose_a;
  c.pose_b = swapped ? s.pose_a : s.pose_b;
  c.extensions.push_back("note answer_fingerprint: " + family + ", pair " + std::to_string(pair) +
                         (swapped ? " (B, A)" : ""));
  // A case file holds points: its hulls are built with merged faces.
  if (family.find("triangulated") != std::string::npos)
    c.extensions.push_back("note the call's faces were triangulated: replay --strict runs them so too "
                           "(triangulated-faces)");
  std::string name = family + "-" + std::to_string(pair) + (swapped ? "-swapped" : "") + ".case", error;
  std::replace(name.begin(), name.end(), ' ', '-');
  if (write_case_file(folder + "/" + name, c, error)) return true;
  std::fprintf(stderr, "answer_fingerprint: %s\n", error.c_str());
  return false;
}

std::optional<Generator> open_generator(const char* spec) {
  if (std::strcmp(spec, "builtin") == 0) return Generator::builtin();
  std::string error;
  auto generator = Generator::open(spec, error);
  if (!generator) std::fprintf(stderr, "answer_fingerprint: %s: %s\n", spec, error.c_str());
  return generator;
}

int run(int argc, char** argv) {
  if (argc < 2 || argc > 4) {
    std::fprintf(stderr, "usage: answer_fingerprint PLUGIN [BASELINE [CASE_FOLDER]]\n");
    return 2;
  }
  const std::string case_folder = argc == 4 ? argv[3] : "";
  const std::optional<Generator> plugin = open_generator(argv[1]);
  const std::optional<Generator> baseline = argc >= 3 ? open_generator(argv[2]) : std::nullopt;
  if (!plugin || (argc >= 3 && !baseline)) return 2;
  long long calls = 0, differing = 0;
  for (const bench::BenchFamily& family : bench::bench_families()) {
    Digest digest;
    long long family_differing = 0;
    Change change;
    for (size_t i = 0; i < family.scenes.size(); ++i)
      for (const bool swapped : {false, true}) {
        const Answer mine = answer(*plugin, family.scenes[i], swapped);
        digest.add(mine.bytes);
        ++calls;
        if (!baseline) continue;
        const Answer before = answer(*baseline, family.scenes[i], swapped);
        if (before.bytes == mine.bytes) continue;
        if (differing == 0)
          std::printf("first difference: %s, pair %zu%s\n", family.name.c_str(), i, swapped ? " (B, A)" : "");
        if (!case_folder.empty() && differing < kWrittenCalls &&
            !write_call(case_folder, family.name, i, swapped, family.scenes[i]))
          return 2;
        ++differing, ++family_differing;
        change.add(mine, before, family.scenes[i].scale);
      }
    std::printf("%-20s %s", family.name.c_str(), digest.hex().c_str());
    if (baseline) std::printf("  %lld of %zu calls differ", family_differing, 2 * family.scenes.size());
    if (family_differing > 0)
      std::printf(" (points moved up to %.3g L, depth %.3g L, normal %.3g; %lld of another shape)", change.point,
                  change.depth, change.normal, change.shape);
    std::printf("\n");
  }
  if (baseline) std::printf("%lld of %lld calls differ\n", differing, calls);
  return differing == 0 ? 0 : 1;
}

}  // namespace
}  // namespace mfz

int main(int argc, char** argv) { return mfz::run(argc, argv); }

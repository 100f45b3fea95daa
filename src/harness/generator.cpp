#include "harness/generator.h"

#include <dlfcn.h>

#include <limits>

#include "generator/builtin_generator.h"

namespace mfz {

void poison(mfz_manifold& out) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  out.colliding = -1;
  out.normal = {nan, nan, nan};
  out.penetration = nan;
  out.contact_count = -1;
  for (mfz_contact& c : out.contacts) c = {{nan, nan, nan}, {nan, nan, nan}, nan};
}

Generator Generator::builtin() {
  Generator g;
  g.generate_ = mfz_builtin_generate;
  g.name_ = mfz_builtin_generator_name();
  return g;
}

namespace {

std::string one_line(const char* text) {
  std::string s = text ? text : "unknown error";
  for (char& c : s)
    if (c == '\n') c = ' ';
  return s;
}

}  // namespace

// dlopen searches the system's library path for a name without a slash.
std::string Generator::library_path(const std::string& spec) {
  return spec.find('/') == std::string::npos ? "./" + spec : spec;
}

std::optional<Generator> Generator::open(const std::string& spec, std::string& error) {
  if (spec == "builtin") return builtin();
  if (spec.find('/') == std::string::npos && spec.find(".so") == std::string::npos) {
    error = "unknown generator '" + spec + "': expected 'builtin', a generator that comes with manifuzz and was built here (manifuzz --help lists them) or a path to a plugin .so";
    return std::nullopt;
  }
  void* handle = dlopen(library_path(spec).c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    error = "cannot load generator: " + one_line(dlerror());
    return std::nullopt;
  }
  std::shared_ptr<void> library(handle, [](void* h) { dlclose(h); });
  const auto symbol = [&](const char* name) { return dlsym(handle, name); };
  auto version = reinterpret_cast<mfz_abi_version_fn>(symbol("mfz_abi_version"));
  auto name = reinterpret_cast<mfz_generator_name_fn>(symbol("mfz_generator_name"));
  auto generate = reinterpret_cast<mfz_generate_fn>(symbol("mfz_generate"));
  const char* missing = !version ? "mfz_abi_version" : !name ? "mfz_generator_name" : !generate ? "mfz_generate" : nullptr;
  if (missing) {
    error = spec + " is not a manifuzz generator: it does not export " + missing;
    return std::nullopt;
  }
  if (const int32_t v = version(); v != MFZ_ABI_VERSION) {
    error = spec + " speaks generator ABI version " + std::to_string(v) + "; this harness speaks " +
            std::to_string(MFZ_ABI_VERSION);
    return std::nullopt;
  }
  Generator g;
  g.library_ = std::move(library);
  g.generate_ = generate;
  const char* reported = name();
  g.name_ = reported ? reported : spec;
  if (auto profile = reinterpret_cast<mfz_generator_profile_fn>(symbol("mfz_generator_profile")))
    if (const char* declared = profile()) g.profile_ = one_line(declared);
  return g;
}

int32_t Generator::generate(const mfz_hull& a, const mfz_pose& pose_a, const mfz_hull& b, const mfz_pose& pose_b,
                            mfz_manifold& out) const {
  poison(out);
  return generate_(&a, &pose_a, &b, &pose_b, &out);
}

}  // namespace mfz

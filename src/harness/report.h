#pragma once
/// \file
/// How manifolds and verdicts are shown: text for people, JSON for scripts.
#include <string>

#include "harness/invariants.h"

namespace mfz {

std::string vec_text(const Vec3& v);
/// The manifold, one field a line, indented by `indent`.
std::string manifold_text(const mfz_manifold& m, const std::string& indent = "  ");
/// One line a check: status, name, error and tolerance in L, detail.
std::string verdict_text(const Verdict& v, const std::string& indent = "  ");
/// "pass", "violation", "refused" or "oracle-disagreement".
const char* verdict_word(const Verdict& v);

/// A minimal JSON writer: enough for reports, with non-finite numbers as null.
class Json {
 public:
  Json& begin_object();
  Json& end_object();
  Json& begin_array();
  Json& end_array();
  Json& key(const std::string& k);
  Json& value(const std::string& s);
  Json& value(const char* s) { return value(std::string(s)); }
  Json& value(double d);
  Json& value(int i);
  Json& value(bool b);
  Json& value(const Vec3& v);
  const std::string& str() const { return out_; }

 private:
  void separate();
  std::string out_;
  bool need_comma_ = false;
};

void manifold_json(Json& j, const mfz_manifold& m);
void verdict_json(Json& j, const Verdict& v);

}  // namespace mfz

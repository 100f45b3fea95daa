#include "case_pictures.h"

#include <filesystem>
#include <fstream>

#include "oracles/oracle_answers.h"
#include "render/html_case_view.h"
#include "render/svg_picture.h"

namespace mfz::props {

std::vector<CasePicture> pictures_of_outcome(const CaseFile& c, const CaseOutcome& outcome,
                                             const std::string& generator_name) {
  SceneBuild built = make_scene(c);
  if (!built.scene) return {};
  Scene& scene = *built.scene;
  scene.precision_epsilon = outcome.profile.precision_epsilon;
  const OracleAnswers oracles = consult_oracles(scene);
  const mfz_manifold* manifold = outcome.manifold ? &*outcome.manifold : nullptr;
  const Verdict* verdict = outcome.verdict ? &*outcome.verdict : nullptr;
  std::vector<CasePicture> runs;
  runs.push_back(picture_of_run(scene, manifold, verdict, &oracles.exact, "the case", generator_name));
  const Finding* finding = outcome.finding ? &*outcome.finding : nullptr;
  if (finding && !outcome.transformed) {
    mark_broken_check(runs[0], finding->name, finding->detail, finding->error, finding->tolerance);
    if (!manifold) runs[0].legend.push_back("no answer: " + finding->name + " (" + finding->detail + ")");
  }
  if (outcome.transformed) {
    const TransformedRun& t = *outcome.transformed;
    const OracleAnswers moved = consult_oracles(t.scene);
    runs.push_back(picture_of_run(t.scene, t.manifold ? &*t.manifold : nullptr, nullptr, &moved.exact,
                                  "the " + t.relation + " run", generator_name));
    if (finding) {
      mark_broken_check(runs[1], finding->name, finding->detail, finding->error, finding->tolerance);
      runs[0].legend.push_back("relation " + t.relation + ": the run beside this one");
    }
  }
  return runs;
}

std::vector<CasePicture> pictures_of_case(const CaseFile& c, GeneratorSession& session, Selection selection,
                                          std::string& error) {
  selection.keep_transformed_run = true;
  const CaseOutcome outcome = check_case(c, session, selection);
  if (outcome.invalid || outcome.interrupted) {
    error = outcome.invalid ? outcome.invalid_reason : "interrupted";
    return {};
  }
  std::vector<CasePicture> runs = pictures_of_outcome(c, outcome, session.name());
  if (runs.empty()) error = "the case's hulls cannot be built";
  return runs;
}

bool write_case_pictures(const std::string& dir, const std::string& stem, const std::vector<CasePicture>& runs,
                         const std::string& title, std::string& error) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  const std::filesystem::path base = std::filesystem::path(dir) / stem;
  for (const auto& [extension, text] : {std::pair<std::string, std::string>{".svg", svg_of(runs)},
                                        std::pair<std::string, std::string>{".html", html_case_view(runs, title)}}) {
    std::ofstream out(base.string() + extension, std::ios::binary);
    out << text;
    out.close();
    if (!out) {
      error = "cannot write " + base.string() + extension;
      return false;
    }
  }
  return true;
}

std::string file_stem(const std::string& path) {
  const std::string stem = std::filesystem::path(path).stem().string();
  return stem.empty() ? "case" : stem;
}

}  // namespace mfz::props

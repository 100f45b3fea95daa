#include "fuzz_campaign.h"

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iterator>
#include <limits>
#include <map>
#include <memory>
#include <ostream>
#include <set>
#include <sstream>
#include <thread>

#include <fcntl.h>
#include <sys/prctl.h>
#include <sys/statvfs.h>
#include <sys/wait.h>
#include <unistd.h>

#include "finding_file.h"
#include "finding_minimiser.h"
#include "fuzz_input.h"
#include "geometric_mutator.h"
#include "harness/interruption.h"
#include "input_name.h"
#include "process_memory.h"

namespace mfz::props {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

/// libFuzzer's limits for one input: a hang is the plugin's call limit's
/// business (the worker reports it as `hang`), so the engine's own timeout is
/// only for the built-in, in process; memory per job is bounded.
constexpr int kInputTimeoutSeconds = 30;
constexpr int kMemoryLimitMb = 2048;
/// A feature counts as rare to libFuzzer's entropic schedule until it has
/// been hit this often (its default: 255). Each job of a campaign starts
/// with every feature rare, and every feature an execution hits is looked
/// up in the rare list, which grows to thousands of entries before any
/// feature passes 255 hits: on a campaign's jobs that bookkeeping took a
/// third of the time (perf, 40 s of `manifuzz fuzz --generator builtin`).
/// At 16 the list stays short: in 120-s campaigns of the built-in on one
/// core, six at 16 made 138,000 executions and reached 19,533 features on
/// average, four at 255 made 92,000 and reached 19,030.
constexpr int kRareFeatureHits = 16;
/// How long libFuzzer's own minimiser may take before the case shrinker.
constexpr double kEngineMinimiseSeconds = 10;
/// How often the corpus and the artefacts are looked at.
constexpr double kSyncEvery = 2;

double since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

std::vector<std::string> fuzzer_environment(const FuzzOptions& o) {
  return {"MANIFUZZ_GENERATOR=" + o.generator, "MANIFUZZ_LEVEL=" + std::string(o.level == Level::strict ? "strict" : "contract"),
          "MANIFUZZ_CALL_TIMEOUT=" + std::to_string(o.call_timeout), "MANIFUZZ_PROFILE=" + o.profile.text()};
}

// ---- the engine's process ----

// libFuzzer in its own process group (its fork-mode jobs with it), writing
// to a log file, not a pipe: a pipe left unread while a finding is minimised
// would stall the fuzzer.
class EngineProcess {
 public:
  EngineProcess(const std::string& program, const std::vector<std::string>& arguments,
                const std::vector<std::string>& environment, const std::string& log_path) {
    pid_ = fork();
    if (pid_ != 0) return;
    setpgid(0, 0);
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    const int log = open(log_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int null = open("/dev/null", O_RDONLY);
    if (log < 0 || null < 0) _exit(127);
    dup2(null, 0);
    dup2(log, 1);
    dup2(log, 2);
    for (const std::string& variable : environment) putenv(const_cast<char*>(variable.c_str()));
    std::vector<char*> argv{const_cast<char*>(program.c_str())};
    for (const std::string& a : arguments) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    execv(program.c_str(), argv.data());
    _exit(127);
  }
  EngineProcess(const EngineProcess&) = delete;
  EngineProcess& operator=(const EngineProcess&) = delete;
  ~EngineProcess() { stop(); }

  bool started() const { return pid_ > 0; }
  /// True while it runs; reaps it once it has ended.
  bool running() {
    if (pid_ <= 0 || exited_) return false;
    if (waitpid(pid_, &status_, WNOHANG) == pid_) exited_ = true;
    return !exited_;
  }
  /// SIGINT (libFuzzer's clean stop, which ends its jobs), then SIGKILL to
  /// the whole group if it has not ended within `grace` seconds.
  void stop(double grace = 10) {
    if (!running()) return;
    kill(-pid_, SIGINT);
    const auto asked = Clock::now();
    while (running() && since(asked) < grace) std::this_thread::sleep_for(std::chrono::milliseconds(50));
    if (running()) {
      kill(-pid_, SIGKILL);
      waitpid(pid_, &status_, 0);
      exited_ = true;
    }
    kill(-pid_, SIGKILL);  // any job left behind
  }
  /// The exit status once it has ended by itself (not stopped), else -1.
  int exit_status() const { return exited_ && WIFEXITED(status_) ? WEXITSTATUS(status_) : -1; }
  /// Resident memory of the engine and its jobs, in MiB.
  double resident_mb() const { return group_resident_mb(pid_); }

 private:
  pid_t pid_ = -1;
  bool exited_ = false;
  int status_ = 0;
};

// Runs the fuzzer program once to its end (libFuzzer's minimiser), output
// discarded; false when it could not be run.
bool run_to_end(const std::string& program, const std::vector<std::string>& arguments,
                const std::vector<std::string>& environment, double seconds) {
  EngineProcess p(program, arguments, environment, "/dev/null");
  if (!p.started()) return false;
  const auto started = Clock::now();
  while (p.running()) {
    if (since(started) > seconds + 10 || interrupted()) p.stop(1);
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return true;
}

// ---- what libFuzzer says ----

// New complete lines of a growing log file.
class LogTail {
 public:
  explicit LogTail(std::string path) : path_(std::move(path)) {}
  std::vector<std::string> new_lines() {
    std::ifstream in(path_, std::ios::binary);
    in.seekg(static_cast<std::streamoff>(offset_));
    std::string chunk((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::vector<std::string> lines;
    size_t start = 0;
    for (size_t end; (end = chunk.find('\n', start)) != std::string::npos; start = end + 1)
      lines.push_back(chunk.substr(start, end - start));
    offset_ += start;
    return lines;
  }

 private:
  std::string path_;
  size_t offset_ = 0;
};

struct EngineStats {
  long long execs = 0;
  int coverage = 0, features = 0, corpus = 0;
};

// A fork-mode status line: "#60029: cov: 10 ft: 8 corp: 5 exec/s 0 ...".
void read_status(const std::string& line, EngineStats& stats) {
  if (line.empty() || line[0] != '#') return;
  long long execs = 0;
  int cov = 0, ft = 0, corp = 0;
  if (std::sscanf(line.c_str(), "#%lld%*[: A-Z]cov: %d ft: %d corp: %d", &execs, &cov, &ft, &corp) == 4) {
    stats.execs = std::max(stats.execs, execs);
    stats.coverage = cov;
    stats.features = ft;
    stats.corpus = corp;
  }
}

// ---- the user's corpus ----

bool is_input_name(const std::string& name) {
  return name.size() == 40 && std::all_of(name.begin(), name.end(), [](char c) { return std::isxdigit(c); });
}

std::string read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {(std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>()};
}

// Copies libFuzzer's new inputs into the corpus. An input is copied only
// when its bytes hash to its name (libFuzzer names inputs by their SHA-1,
// so a file caught mid-write is left for the next pass), and it lands under
// its name by a rename: a campaign killed at any moment leaves only whole
// inputs in the corpus.
int sync_corpus(const fs::path& from, const fs::path& corpus, std::set<std::string>& known) {
  int added = 0;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(from, ec)) {
    const std::string name = entry.path().filename().string();
    if (!is_input_name(name) || known.count(name)) continue;
    const std::string bytes = read_bytes(entry.path());
    if (input_name(bytes) != name) continue;
    const fs::path temporary = corpus / (".incoming-" + name);
    {
      std::ofstream out(temporary, std::ios::binary);
      out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
      if (!out.flush()) continue;
    }
    fs::rename(temporary, corpus / name, ec);
    if (ec) continue;
    known.insert(name);
    ++added;
  }
  return added;
}

std::set<std::string> corpus_names(const fs::path& corpus) {
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(corpus)) names.insert(entry.path().filename().string());
  return names;
}

// A corpus folder that is empty starts from the seed inputs. Inputs a
// killed campaign left half copied (never under an input's name) go first.
void seed_if_empty(const fs::path& corpus) {
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(corpus, ec))
    if (entry.path().filename().string().rfind(".incoming-", 0) == 0) fs::remove(entry.path(), ec);
  if (!fs::is_empty(corpus)) return;
  for (const auto& [name, bytes] : seed_inputs()) {
    std::ofstream out(corpus / name, std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  }
}

// ---- findings ----

// The artefact's kind from libFuzzer's prefix: crash-, timeout-, oom-, leak-.
std::string artefact_kind(const std::string& name) {
  for (const char* kind : {"crash", "timeout", "oom", "leak", "slow-unit"})
    if (name.rfind(std::string(kind) + "-", 0) == 0) return kind;
  return {};
}

class Campaign {
 public:
  Campaign(const FuzzOptions& o, GeneratorSession& g, GeneratorSession* confirmer, const Profile& confirmer_profile,
           const fs::path& work, std::ostream& log, std::ostream& out)
      : options_(o), generator_(g), confirmer_(confirmer), confirmer_profile_(confirmer_profile), work_(work), log_(log),
        findings_out_(out), started_(Clock::now()) {}

  // Looks at libFuzzer's new artefacts; a finding not seen before is
  // minimised and written.
  void scan_artefacts(double elapsed, FuzzResult& result) {
    std::error_code ec;
    std::vector<fs::path> fresh;
    for (const auto& entry : fs::directory_iterator(work_ / "artefacts", ec)) {
      const std::string name = entry.path().filename().string();
      if (artefact_kind(name).empty() || entry.path().extension() == ".case" || seen_.count(name)) continue;
      fresh.push_back(entry.path());
    }
    std::sort(fresh.begin(), fresh.end());
    for (const fs::path& artefact : fresh) {
      seen_.insert(artefact.filename().string());
      take(artefact, elapsed, result);
    }
  }

 private:
  void take(const fs::path& artefact, double elapsed, FuzzResult& result) {
    const std::string kind = artefact_kind(artefact.filename().string());
    const std::string bytes = read_bytes(artefact);
    const auto decoded = decode_fuzz_input(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
    if (!decoded) return;  // not a case: nothing this harness can show
    FuzzFinding found{kind == "timeout" ? "hang" : (kind == "oom" ? "out-of-memory" : "crash"), kind, {}, 1, elapsed};
    std::optional<Finding> finding;
    // A violation is replayed here (the generator returned on it, so the
    // call is safe in process); a crash or a hang of the built-in is not.
    if (fs::exists(artefact.string() + ".case") || options_.generator != "builtin") {
      const CaseOutcome o = check_case(decoded->file, generator_, selection());
      if (o.finding) {
        finding = o.finding;
        found.name = o.finding->name;
        found.kind = o.tags.contact_kind.empty() ? kind : o.tags.contact_kind;
        found.error = o.finding->error;
        found.tolerance = o.finding->tolerance;
      }
    }
    const std::string key = found.name + " / " + found.kind;
    if (const auto known = index_.find(key); known != index_.end()) {
      ++result.findings[known->second].artefacts;
      return;
    }
    if (rounding_.count(key)) return;
    // The same logic in double must fail alike, or this is rounding.
    if (finding && confirmer_) {
      const CaseOutcome again = check_case(decoded->file, *confirmer_, {{}, options_.level, confirmer_profile_, true});
      if (!again.invalid && !(again.finding && same_failure(*finding, *again.finding))) {
        rounding_.insert(key);
        ++result.rounding_only;
        log_ << "rounding only: " << key << " after " << static_cast<long long>(elapsed) << " s ("
             << finding->detail << "), which " << confirmer_->name() << " does not make\n";
        return;
      }
    }
    CaseFile smallest = decoded->file;
    std::string minimised = "then minimised";
    if (finding && time_left() > 1) {
      smallest = engine_minimised(artefact, *finding, std::min(kEngineMinimiseSeconds, time_left() / 2))
                     .value_or(smallest);
      const Minimised m = minimise_finding(smallest, *finding, generator_, selection(),
                                           std::min(options_.minimise_seconds, time_left()),
                                           [] { return interrupted(); });
      smallest = m.file;
      finding = m.finding;
    } else if (finding) {
      minimised = "not minimised: --seconds was up";
    } else {
      finding = Finding{found.name, "libFuzzer's " + kind + " artefact " + artefact.filename().string()};
    }
    std::ostringstream how;
    how << "found by: manifuzz fuzz --generator " << options_.generator
        << (options_.level == Level::strict ? " --strict" : "") << " (after " << static_cast<long long>(elapsed)
        << " s, input " << artefact.filename().string() << ", " << minimised << ")";
    std::string text, error;
    found.case_path = write_finding(options_.out_dir, smallest, *finding, selection(), {how.str()}, text, error);
    if (found.case_path.empty()) {
      log_ << "manifuzz fuzz: " << error << "\n";
      return;
    }
    // The raw input too: what libFuzzer itself replays.
    std::error_code ec;
    fs::copy_file(artefact, found.case_path.substr(0, found.case_path.size() - 5) + ".input",
                  fs::copy_options::overwrite_existing, ec);
    index_[key] = result.findings.size();
    result.findings.push_back(found);
    log_ << "found " << found.name << " (" << found.kind << ") after " << static_cast<long long>(elapsed) << " s: "
         << finding->detail << "\n";
    findings_out_ << "VIOLATION " << found.name << " " << found.case_path << std::endl;
  }

  // libFuzzer's minimiser, kept only when its smallest input still fails
  // the same check by the same order.
  // The time --seconds leaves (minimising included); unbounded without it.
  double time_left() const {
    return options_.seconds ? *options_.seconds - since(started_) : std::numeric_limits<double>::infinity();
  }

  std::optional<CaseFile> engine_minimised(const fs::path& artefact, const Finding& original, double seconds) {
    const fs::path smallest = work_ / ("minimised-" + artefact.filename().string());
    const fs::path scratch = work_ / "minimising";
    fs::create_directories(scratch);
    const std::vector<std::string> arguments = {
        "-minimize_crash=1", "-max_total_time=" + std::to_string(std::max(1, static_cast<int>(seconds))),
        "-exact_artifact_path=" + smallest.string(), "-artifact_prefix=" + scratch.string() + "/",
        "-timeout=" + std::to_string(kInputTimeoutSeconds), artefact.string()};
    if (!run_to_end(options_.fuzzer, arguments, fuzzer_environment(options_), seconds)) return {};
    const std::string bytes = read_bytes(smallest);
    const auto decoded = decode_fuzz_input(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
    if (!decoded) return {};
    const CaseOutcome o = check_case(decoded->file, generator_, selection());
    if (o.invalid || !o.finding || !same_failure(original, *o.finding)) return {};
    return decoded->file;
  }

  const FuzzOptions& options_;
  // What the fuzzer checks, as the harness checks it again: the level and
  // the profile in force, from the command line.
  Selection selection() const { return {{}, options_.level, options_.profile, true}; }
  GeneratorSession& generator_;
  GeneratorSession* confirmer_;
  Profile confirmer_profile_;
  std::set<std::string> rounding_;
  fs::path work_;
  std::ostream& log_;
  std::ostream& findings_out_;
  std::set<std::string> seen_;
  std::map<std::string, size_t> index_;
  Clock::time_point started_;
};

// ---- the campaign's folders ----

// Removes the folders `prefix`<pid> in `parent` whose run has died.
void remove_folders_of_dead_runs(const fs::path& parent, const std::string& prefix) {
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(parent, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(prefix, 0) != 0) continue;
    const pid_t owner = static_cast<pid_t>(std::atoll(name.c_str() + prefix.size()));
    if (owner > 0 && kill(owner, 0) != 0 && errno == ESRCH) fs::remove_all(entry.path(), ec);
  }
}

// The work folder of this run, inside --out; those of runs that died
// (SIGKILL) are removed first.
fs::path make_work_folder(const fs::path& out) {
  remove_folders_of_dead_runs(out, ".fuzz-");
  std::error_code ec;
  const fs::path work = out / (".fuzz-" + std::to_string(getpid()));
  fs::remove_all(work, ec);
  fs::create_directories(work / "new");
  fs::create_directories(work / "artefacts");
  return work;
}

// The engine's scratch folder, its TMPDIR, removed with this object. In
// fork mode libFuzzer writes each job's seeds, new inputs, features and log
// to files there, and deletes them as the job ends: in memory (/dev/shm)
// where the system has it, else in the work folder. In /tmp, on this
// machine's ext4, creating those files took a fifth of a campaign's time
// (perf: the kernel's inode allocation), and a campaign stopped with
// Ctrl-C left libFuzzer's folder behind (15 MB after a minute). The
// folders of runs that died are removed first. A small /dev/shm (a
// container's is 64 MB) is passed by: a job's files and its log, which
// holds whatever the plugin prints, can outgrow it.
class EngineScratch {
 public:
  explicit EngineScratch(const fs::path& work) {
    std::error_code ec;
    const fs::path memory = "/dev/shm";
    struct statvfs room {};
    if (fs::is_directory(memory, ec) && access(memory.c_str(), W_OK) == 0 && statvfs(memory.c_str(), &room) == 0 &&
        static_cast<double>(room.f_bavail) * static_cast<double>(room.f_frsize) >= kLeastMemoryBytes) {
      remove_folders_of_dead_runs(memory, kPrefix);
      path_ = memory / (kPrefix + std::to_string(getpid()));
      fs::remove_all(path_, ec);
      if (fs::create_directory(path_, ec)) return;
    }
    path_ = work / "tmp";
    fs::create_directories(path_, ec);
  }
  EngineScratch(const EngineScratch&) = delete;
  EngineScratch& operator=(const EngineScratch&) = delete;
  ~EngineScratch() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  const fs::path& path() const { return path_; }

 private:
  static constexpr const char* kPrefix = "manifuzz-fuzz-";
  static constexpr double kLeastMemoryBytes = 1 << 30;
  fs::path path_;
};

void print_progress(std::ostream& log, double elapsed, const EngineStats& s, const FuzzResult& r, double rss_mb) {
  int artefacts = 0;
  for (const FuzzFinding& f : r.findings) artefacts += f.artefacts;
  log << "  " << std::setw(6) << static_cast<long long>(elapsed) << " s  " << s.execs << " execs, "
      << static_cast<long long>(s.execs / std::max(elapsed, 1e-9)) << " exec/s, cov " << s.coverage << " ft "
      << s.features << ", corpus " << r.corpus_inputs << " (+" << r.corpus_added << "), findings "
      << r.findings.size() << " (" << artefacts << " artefacts), rss " << static_cast<long long>(rss_mb) << " MiB"
      << std::endl;
}

void print_summary(std::ostream& log, const FuzzOptions& o, const FuzzResult& r) {
  log << "manifuzz fuzz: " << r.execs << " execs in " << std::setprecision(3) << r.seconds << " s ("
      << static_cast<long long>(r.execs / std::max(r.seconds, 1e-9)) << " exec/s on " << o.jobs << " job"
      << (o.jobs > 1 ? "s" : "") << "), coverage " << r.coverage << " ft " << r.features << ", corpus "
      << r.corpus_inputs << " inputs (" << r.corpus_added << " new) in " << o.corpus_dir << ", "
      << r.findings.size() << " distinct finding" << (r.findings.size() == 1 ? "" : "s");
  if (o.confirm_with) log << ", " << r.rounding_only << " of rounding only passed over";
  log << "\n";
  for (const FuzzFinding& f : r.findings)
    log << "  " << f.name << " (" << f.kind << "): " << f.artefacts << " artefact" << (f.artefacts == 1 ? "" : "s")
        << ", first after " << static_cast<long long>(f.after_seconds) << " s: " << f.case_path << "\n";
}

// The caps of a growing campaign's phases (FuzzOptions::least_points): from
// the least, doubling, to the most; one phase of the most without it.
std::vector<int> phase_caps(const FuzzOptions& o) {
  std::vector<int> caps;
  if (o.least_points > 0)
    for (int cap = o.least_points; cap < o.max_points; cap *= 2) caps.push_back(cap);
  caps.push_back(o.max_points);
  return caps;
}

// What one run of the engine leaves besides the result it adds to.
struct PhaseEnd {
  bool started = false;  ///< false: the engine did not start, and `error` says why
  int exit_status = 0;
  std::string first_error;  ///< the engine's first error line, if any
};

// One run of libFuzzer in fork mode on hulls of at most `cap` points, for
// `seconds` (0: until Ctrl-C): new inputs into the work folder, the
// user's corpus read from where it is, every crash, hang and OOM kept going,
// its status, corpus and artefacts watched. Its executions add to the
// result's, counted from `before` (the phases run so far); its coverage,
// read from the shared corpus, stands for all of them.
PhaseEnd run_phase(const FuzzOptions& options, int cap, double seconds, int phase,
                   const fs::path& work, const EngineScratch& scratch, Campaign& campaign, Clock::time_point started,
                   std::set<std::string>& known, FuzzResult& result, std::ostream& log, std::string& error) {
  PhaseEnd end;
  std::vector<std::string> arguments = {
      "-fork=" + std::to_string(options.jobs), "-ignore_crashes=1", "-ignore_timeouts=1", "-ignore_ooms=1",
      "-artifact_prefix=" + (work / "artefacts").string() + "/", "-timeout=" + std::to_string(kInputTimeoutSeconds),
      "-rss_limit_mb=" + std::to_string(kMemoryLimitMb), "-max_len=" + std::to_string(fuzz_input_size(cap, cap)),
      "-entropic_feature_frequency_threshold=" + std::to_string(kRareFeatureHits), "-print_final_stats=1"};
  if (seconds > 0) arguments.push_back("-max_total_time=" + std::to_string(std::max(1LL, std::llround(seconds))));
  arguments.push_back((work / "new").string());
  arguments.push_back(options.corpus_dir);
  std::vector<std::string> environment = fuzzer_environment(options);
  environment.push_back("TMPDIR=" + scratch.path().string());
  const fs::path engine_log = work / ("engine-" + std::to_string(phase) + ".log");
  EngineProcess engine(options.fuzzer, arguments, environment, engine_log.string());
  if (!engine.started()) {
    error = "cannot start " + quoted(options.fuzzer, 4096);
    return end;
  }
  end.started = true;
  LogTail tail(engine_log.string());
  EngineStats stats;
  const long long before = result.execs;
  const auto so_far = [&](const EngineStats& now) {
    EngineStats all = now;
    all.execs += before;
    return all;
  };
  double last_sync = since(started), last_progress = since(started), last_sample = since(started);
  while (engine.running() && !interrupted()) {
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    for (const std::string& line : tail.new_lines()) {
      read_status(line, stats);
      if (end.first_error.empty() &&
          (line.find("ERROR") != std::string::npos || line.rfind("manifold_fuzzer:", 0) == 0))
        end.first_error = line;
    }
    const double now = since(started);
    if (now - last_sample >= 1) last_sample = now, result.statistics.sample(now, before + stats.execs, stats.coverage);
    if (now - last_sync >= kSyncEvery) {
      last_sync = now;
      result.corpus_added += sync_corpus(work / "new", options.corpus_dir, known);
      result.corpus_inputs = static_cast<int>(known.size());
      campaign.scan_artefacts(now, result);
    }
    if (options.progress_every > 0 && now - last_progress >= options.progress_every) {
      last_progress = now;
      print_progress(log, now, so_far(stats), result, engine.resident_mb());
    }
  }
  // Stop cleanly and keep what was found.
  end.exit_status = engine.exit_status();
  engine.stop();
  for (const std::string& line : tail.new_lines()) read_status(line, stats);
  result.corpus_added += sync_corpus(work / "new", options.corpus_dir, known);
  result.corpus_inputs = static_cast<int>(known.size());
  if (!interrupted()) campaign.scan_artefacts(since(started), result);
  result.execs = before + stats.execs;
  result.coverage = stats.coverage;
  result.features = stats.features;
  return end;
}

}  // namespace

std::optional<FuzzResult> run_fuzz(const FuzzOptions& given, std::ostream& log, std::ostream& findings_out,
                                   std::string& error) {
  FuzzOptions options = given;
  // 1. Everything that can fail fails before the fuzzer starts.
  if (options.least_points > 0 && !options.seconds) {
    error = "a campaign that grows its hulls needs --seconds";
    return std::nullopt;
  }
  if (!prepare_out_dir(options.out_dir, error)) return std::nullopt;
  std::error_code ec;
  fs::create_directories(options.corpus_dir, ec);
  if (ec || !fs::is_directory(options.corpus_dir)) {
    error = "cannot create --corpus folder " + quoted(options.corpus_dir, 4096);
    return std::nullopt;
  }
  auto generator = open_session(options.generator, options.call_timeout, error);
  if (!generator) return std::nullopt;
  const auto profile = profile_in_force(generator->declared_profile(), options.profile_override, error);
  if (!profile) return std::nullopt;
  options.profile = *profile;
  seed_if_empty(options.corpus_dir);
  const fs::path work = make_work_folder(options.out_dir);
  const EngineScratch scratch(work);
  std::unique_ptr<GeneratorSession> confirmer;
  Profile confirmer_profile;
  if (options.confirm_with) {
    confirmer = open_session(*options.confirm_with, options.call_timeout, error);
    if (!confirmer) return std::nullopt;
    const auto own = profile_in_force(confirmer->declared_profile(), std::nullopt, error);
    if (!own) return std::nullopt;
    confirmer_profile = *own;
  }
  const std::vector<int> caps = phase_caps(options);

  // 2. Say what runs, and from what.
  catch_interruptions();
  log << "manifuzz fuzz: generator " << generator->name() << ", " << options.jobs << " job"
      << (options.jobs > 1 ? "s" : "") << ", hulls of at most " << caps.front() << " points";
  if (caps.size() > 1) log << ", growing to " << options.max_points << " in " << caps.size() << " phases";
  log << ", profile " << options.profile.text() << ", corpus " << options.corpus_dir << ", findings into "
      << options.out_dir << (options.seconds ? "" : "; Ctrl-C stops") << "\n";
  FuzzResult result;
  std::set<std::string> known = corpus_names(options.corpus_dir);
  result.corpus_inputs = static_cast<int>(known.size());
  log << "  resuming from " << known.size() << " inputs in " << options.corpus_dir << "\n";
  if (confirmer) log << "  each finding is confirmed against " << confirmer->name() << "; one it does not make is rounding\n";
  Campaign campaign(options, *generator, confirmer.get(), confirmer_profile, work, log, findings_out);

  // 3. The phases, each a run of the engine on the corpus the last grew: hulls
  // of a few points first, where a campaign runs three times as many cases a
  // second and met F62 and O29 to O35 within seconds, then larger ones. Each
  // takes an equal share of the time left, so that one that overran its
  // share (an engine takes a few seconds to start and stop) is made up.
  const auto started = Clock::now();
  result.statistics.sample(0, 0, 0);
  PhaseEnd last;
  for (size_t phase = 0; phase < caps.size() && !interrupted(); ++phase) {
    if (caps.size() > 1 && phase > 0)
      log << "  " << static_cast<long long>(since(started)) << " s  phase " << phase + 1 << " of " << caps.size()
          << ": hulls of at most " << caps[phase] << " points\n";
    const double share =
        options.seconds ? std::max(1.0, (*options.seconds - since(started)) / static_cast<double>(caps.size() - phase))
                        : 0;
    last = run_phase(options, caps[phase], share, static_cast<int>(phase), work, scratch, campaign, started, known,
                     result, log, error);
    if (!last.started) {
      release_interruptions();
      return std::nullopt;
    }
  }

  // 4. Say what happened. An engine that ended by itself, with an error,
  // before fuzzing: not a campaign that found nothing.
  result.interrupted = interrupted();
  result.seconds = since(started);
  release_interruptions();
  result.statistics.sample(result.seconds, result.execs, result.coverage);
  if (result.execs == 0 && !result.interrupted && last.exit_status != 0) {
    error = quoted(options.fuzzer, 4096) + " stopped before fuzzing (exit " + std::to_string(last.exit_status) + ")" +
            (last.first_error.empty() ? "" : ": " + printable(last.first_error, 300));
    fs::remove_all(work, ec);
    return std::nullopt;
  }
  if (result.interrupted) log << "manifuzz fuzz: interrupted; the summary so far:\n";
  print_summary(log, options, result);
  fs::remove_all(work, ec);
  return result;
}

}  // namespace mfz::props

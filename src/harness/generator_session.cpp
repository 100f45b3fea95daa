#include "harness/generator_session.h"

#include "harness/interruption.h"
#include "harness/plugin_coverage.h"

#include <dlfcn.h>
#include <poll.h>
#include <sys/prctl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace mfz {
namespace {

class InProcessSession final : public GeneratorSession {
 public:
  explicit InProcessSession(Generator g) : generator_(std::move(g)) {}
  const std::string& name() const override { return generator_.name(); }
  const std::string& declared_profile() const override { return generator_.declared_profile(); }
  CallOutcome generate(const mfz_hull& a, const mfz_pose& pa, const mfz_hull& b, const mfz_pose& pb, mfz_manifold& out,
                       int32_t& status, std::string&) override {
    status = generator_.generate(a, pa, b, pb, out);
    return CallOutcome::done;
  }

 private:
  Generator generator_;
};

// ---- the wire format between harness and worker: raw native-endian bytes ----

void put(std::string& buffer, const void* data, size_t size) { buffer.append(static_cast<const char*>(data), size); }

void put_hull(std::string& buffer, const mfz_hull& h) {
  const int32_t loop_total = h.face_offsets[h.face_count];
  put(buffer, &h.vertex_count, sizeof(int32_t));
  put(buffer, &h.face_count, sizeof(int32_t));
  put(buffer, &loop_total, sizeof(int32_t));
  put(buffer, h.vertices, sizeof(mfz_vec3) * h.vertex_count);
  put(buffer, h.face_offsets, sizeof(int32_t) * (h.face_count + 1));
  put(buffer, h.face_vertices, sizeof(int32_t) * loop_total);
  put(buffer, h.face_normals, sizeof(mfz_vec3) * h.face_count);
}

struct OwnedHull {
  std::vector<mfz_vec3> vertices, normals;
  std::vector<int32_t> offsets, loops;
  mfz_hull view() const {
    return {static_cast<int32_t>(vertices.size()), vertices.data(), static_cast<int32_t>(normals.size()),
            offsets.data(), loops.data(), normals.data()};
  }
};

bool read_all(int fd, void* data, size_t size) {
  char* p = static_cast<char*>(data);
  while (size > 0) {
    const ssize_t n = read(fd, p, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    p += n;
    size -= static_cast<size_t>(n);
  }
  return true;
}

bool write_all(int fd, const void* data, size_t size) {
  const char* p = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t n = write(fd, p, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    p += n;
    size -= static_cast<size_t>(n);
  }
  return true;
}

template <class T>
bool read_vector(int fd, std::vector<T>& v, int32_t count) {
  if (count < 0 || count > (1 << 24)) return false;
  v.resize(static_cast<size_t>(count));
  return read_all(fd, v.data(), sizeof(T) * v.size());
}

bool read_hull(int fd, OwnedHull& h) {
  int32_t counts[3];
  return read_all(fd, counts, sizeof counts) && read_vector(fd, h.vertices, counts[0]) &&
         read_vector(fd, h.offsets, counts[1] + 1) && read_vector(fd, h.loops, counts[2]) &&
         read_vector(fd, h.normals, counts[1]);
}

// The worker: loads the generator, says hello, then answers requests until
// its input closes. Asked to share its coverage, it says in its hello how
// many counters the plugin keeps (harness/plugin_coverage.h), and sends
// after each answer the counters the call set.
[[noreturn]] void serve(const std::string& spec, bool share_coverage, int in, int out) {
  // The worker dies with the harness (a SIGKILL included), and what a plugin
  // prints goes to the harness's stderr, never into its stdout, where
  // scripts read VIOLATION lines and JSON.
  prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (getppid() == 1) _exit(0);  // the harness died before the line above
  dup2(STDERR_FILENO, STDOUT_FILENO);
  std::string error;
  const auto generator = Generator::open(spec, error);
  CoverageCounters counters;
  if (generator && share_coverage) {
    counters = coverage_counters_at(reinterpret_cast<const void*>(generator->entry_point()));
    std::string loading;
    take_coverage_hits(counters, loading);  // what loading it counted is no call's
  }
  // The name, then the declared profile after a NUL (neither holds one),
  // then, when asked, the number of counters after another.
  std::string hello =
      generator ? "ok " + generator->name() + std::string(1, '\0') + generator->declared_profile() : "error " + error;
  if (generator && share_coverage) hello += std::string(1, '\0') + std::to_string(counters.size);
  const uint32_t length = static_cast<uint32_t>(hello.size());
  write_all(out, &length, sizeof length);
  write_all(out, hello.data(), hello.size());
  if (!generator) _exit(0);
  OwnedHull a, b;
  mfz_pose pa, pb;
  mfz_manifold manifold;
  std::string answer;
  while (read_hull(in, a) && read_all(in, &pa, sizeof pa) && read_hull(in, b) && read_all(in, &pb, sizeof pb)) {
    const mfz_hull va = a.view(), vb = b.view();
    const int32_t status = generator->generate(va, pa, vb, pb, manifold);
    answer.clear();
    put(answer, &status, sizeof status);
    put(answer, &manifold, sizeof manifold);
    if (counters.size > 0) take_coverage_hits(counters, answer);
    if (!write_all(out, answer.data(), answer.size())) break;
  }
  _exit(0);
}

class WorkerSession final : public GeneratorSession {
 public:
  WorkerSession(std::string spec, double timeout, bool share_coverage)
      : spec_(std::move(spec)), timeout_ms_(static_cast<int>(timeout * 1000)), share_coverage_(share_coverage) {}
  ~WorkerSession() override { stop(); }

  const std::string& name() const override { return name_; }
  const std::string& declared_profile() const override { return profile_; }

  // Starts the worker; empty on success, else why not.
  std::string start() {
    int to_worker[2], from_worker[2];
    if (pipe(to_worker) != 0 || pipe(from_worker) != 0) return "cannot create pipes for the worker";
    pid_ = fork();
    if (pid_ < 0) return "cannot fork the worker";
    if (pid_ == 0) {
      setpgid(0, 0);  // its own group: stopping it stops whatever the plugin forked
      close(to_worker[1]);
      close(from_worker[0]);
      serve(spec_, share_coverage_, to_worker[0], from_worker[1]);
    }
    close(to_worker[0]);
    close(from_worker[1]);
    to_ = to_worker[1];
    from_ = from_worker[0];
    uint32_t length = 0;
    std::string hello;
    if (wait_readable(10000) && read_all(from_, &length, sizeof length) && length < 4096) {
      hello.resize(length);
      if (!read_all(from_, hello.data(), length)) hello.clear();
    }
    if (hello.rfind("ok ", 0) == 0) {
      const size_t nul = hello.find('\0');
      name_ = hello.substr(3, nul == std::string::npos ? std::string::npos : nul - 3);
      const size_t second = nul == std::string::npos ? nul : hello.find('\0', nul + 1);
      if (nul != std::string::npos) profile_ = hello.substr(nul + 1, second == std::string::npos ? second : second - nul - 1);
      worker_counters_ = second == std::string::npos ? 0 : std::strtoull(hello.c_str() + second + 1, nullptr, 10);
      if (worker_counters_ > 0) load_counters_here();
      return {};
    }
    stop();
    return hello.rfind("error ", 0) == 0 ? hello.substr(6) : "the generator's worker died while loading " + spec_;
  }

  CallOutcome generate(const mfz_hull& a, const mfz_pose& pa, const mfz_hull& b, const mfz_pose& pb, mfz_manifold& out,
                       int32_t& status, std::string& failure) override {
    poison(out);
    if (pid_ <= 0) {
      if (std::string why = start(); !why.empty()) {
        failure = "restarting the worker failed: " + why;
        return CallOutcome::crashed;
      }
    }
    std::string request;
    put_hull(request, a);
    put(request, &pa, sizeof pa);
    put_hull(request, b);
    put(request, &pb, sizeof pb);
    const bool sent = write_all(to_, request.data(), request.size());
    if (sent && !wait_readable(timeout_ms_)) {
      stop();
      if (interrupted()) return CallOutcome::interrupted;
      failure = "no answer within " + std::to_string(timeout_ms_) + " ms";
      return CallOutcome::hung;
    }
    if (sent && read_all(from_, &status, sizeof status) && read_all(from_, &out, sizeof out) && read_coverage_hits())
      return CallOutcome::done;
    failure = "the worker died: " + reap();
    return CallOutcome::crashed;
  }

 private:
  bool wait_readable(int timeout_ms) {
    pollfd p{from_, POLLIN, 0};
    int r;
    do r = poll(&p, 1, timeout_ms);
    while (r < 0 && errno == EINTR && !interrupted());
    return r > 0;
  }

  // Waits for the dead worker and says how it ended.
  std::string reap() {
    int wstatus = 0;
    std::string how = "unknown";
    if (pid_ > 0) kill(-pid_, SIGKILL);  // the plugin's own children
    if (pid_ > 0 && waitpid(pid_, &wstatus, 0) == pid_) {
      if (WIFSIGNALED(wstatus)) how = std::string("signal ") + strsignal(WTERMSIG(wstatus));
      else if (WIFEXITED(wstatus)) how = "exit status " + std::to_string(WEXITSTATUS(wstatus));
    }
    pid_ = -1;
    close_pipes();
    return how;
  }

  void stop() {
    if (pid_ > 0) {
      kill(-pid_, SIGKILL);
      kill(pid_, SIGKILL);
      waitpid(pid_, nullptr, 0);
      pid_ = -1;
    }
    close_pipes();
  }

  void close_pipes() {
    if (to_ >= 0) close(to_);
    if (from_ >= 0) close(from_);
    to_ = from_ = -1;
  }

  // This process loads the plugin too, once, and never calls it: so that
  // libFuzzer, which reads the counters of the modules loaded here, knows
  // the plugin's. Its counters must be the worker's, counter for counter;
  // they are by size, being the same file's. The library stays loaded: the
  // fuzzer keeps pointers into it.
  void load_counters_here() {
    if (!here_.begin) {
      if (void* library = dlopen(Generator::library_path(spec_).c_str(), RTLD_NOW | RTLD_LOCAL))
        if (void* entry = dlsym(library, "mfz_generate")) here_ = coverage_counters_at(entry);
    }
    if (here_.size != worker_counters_) here_ = {};
  }

  // The counters the call set, when the worker shares them; false when the
  // message breaks off (the worker died) or names more counters than there are.
  bool read_coverage_hits() {
    if (worker_counters_ == 0) return true;
    uint32_t count = 0;
    if (!read_all(from_, &count, sizeof count) || count > std::min(worker_counters_, kMaxSharedCounters)) return false;
    hits_.resize(count);
    if (!read_all(from_, hits_.data(), sizeof(uint32_t) * count)) return false;
    return !here_.begin || apply_coverage_hits(here_, hits_.data(), count);
  }

  std::string spec_, name_, profile_;
  int timeout_ms_;
  bool share_coverage_;
  size_t worker_counters_ = 0;  // how many the worker's plugin keeps (0: none sent)
  CoverageCounters here_;  // the same plugin's, loaded here
  std::vector<uint32_t> hits_;
  pid_t pid_ = -1;
  int to_ = -1, from_ = -1;
};

}  // namespace

std::unique_ptr<GeneratorSession> in_process_session(Generator generator) {
  return std::make_unique<InProcessSession>(std::move(generator));
}

std::unique_ptr<GeneratorSession> open_session(const std::string& spec, double call_timeout_seconds,
                                               std::string& error, bool share_plugin_coverage) {
  if (spec == "builtin") return in_process_session(Generator::builtin());
  // A dead worker must not kill the harness with SIGPIPE on the next write.
  signal(SIGPIPE, SIG_IGN);
  auto worker = std::make_unique<WorkerSession>(spec, call_timeout_seconds, share_plugin_coverage);
  if (std::string why = worker->start(); !why.empty()) {
    error = why;
    return nullptr;
  }
  return worker;
}

}  // namespace mfz

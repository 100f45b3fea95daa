#include "harness/interruption.h"

#include <csignal>

namespace mfz {
namespace {

volatile std::sig_atomic_t flag = 0;

extern "C" void on_interruption(int) { flag = 1; }

void handle(int signal, void (*handler)(int)) {
  struct sigaction action {};
  action.sa_handler = handler;
  sigemptyset(&action.sa_mask);
  action.sa_flags = 0;  // no SA_RESTART: poll() returns EINTR
  sigaction(signal, &action, nullptr);
}

}  // namespace

void catch_interruptions() {
  flag = 0;
  handle(SIGINT, on_interruption);
  handle(SIGTERM, on_interruption);
}

void release_interruptions() {
  handle(SIGINT, SIG_DFL);
  handle(SIGTERM, SIG_DFL);
}

bool interrupted() { return flag != 0; }

}  // namespace mfz

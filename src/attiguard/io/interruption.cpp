#include "attiguard/io/interruption.hpp"

#include <csignal>

namespace attiguard::io {

namespace {

std::atomic<bool> g_stop{false};
std::atomic<int> g_signal{0};
static_assert(std::atomic<bool>::is_always_lock_free && std::atomic<int>::is_always_lock_free,
              "the signal handler may only store to lock-free atomics");

extern "C" void on_interruption(int sig) {
  if (g_stop.load()) {  // the second signal: end now, by that signal
    std::signal(sig, SIG_DFL);
    std::raise(sig);
    return;
  }
  g_signal.store(sig);
  g_stop.store(true);
}

}  // namespace

void install_interruption_handlers() noexcept {
  struct sigaction action {};
  action.sa_handler = on_interruption;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;  // reads, writes and waits in progress go on
  for (int sig : {SIGINT, SIGTERM}) sigaction(sig, &action, nullptr);
}

bool interrupted() noexcept { return g_stop.load(); }

const std::atomic<bool>& interruption_flag() noexcept { return g_stop; }

std::string interruption_signal_name() {
  switch (g_signal.load()) {
    case SIGINT:
      return "SIGINT";
    case SIGTERM:
      return "SIGTERM";
    default:
      return g_stop.load() ? "a signal" : "";
  }
}

void throw_if_interrupted(const std::string& what) {
  if (g_stop.load()) throw Interrupted("interrupted by " + interruption_signal_name() + what);
}

}  // namespace attiguard::io

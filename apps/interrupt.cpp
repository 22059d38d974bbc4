// SPDX-License-Identifier: Apache-2.0
#include "interrupt.hpp"

#include <atomic>
#include <csignal>
#include <thread>

#include <pthread.h>
#include <unistd.h>

namespace alphapocket {
namespace {

std::atomic<int> g_signal{0};

sigset_t interrupt_signals() {
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGTERM);
  return set;
}

}  // namespace

molecule::TemporaryPaths& temporaries() {
  static auto* paths = new molecule::TemporaryPaths;  // never destroyed: the thread may use it during exit
  return *paths;
}

void install_interrupt_handlers(int abandon_at) {
  const sigset_t set = interrupt_signals();
  pthread_sigmask(SIG_BLOCK, &set, nullptr);
  temporaries();
  std::thread([set, abandon_at] {
    for (int count = 1;; ++count) {
      int sig = 0;
      if (sigwait(&set, &sig) != 0) continue;
      int none = 0;
      g_signal.compare_exchange_strong(none, sig);
      if (count >= abandon_at) {
        temporaries().abandon();
        _exit(128 + g_signal.load());
      }
    }
  }).detach();
}

bool interrupted() { return g_signal.load() != 0; }

int interrupt_signal() { return g_signal.load(); }

}  // namespace alphapocket

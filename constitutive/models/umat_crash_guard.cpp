#include "constitutive/models/umat_crash_guard.h"

#include <setjmp.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <vector>

namespace soilsph {

namespace {

constexpr std::array kGuardedSignals{SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT};

/// The call this thread is in, and where its crash returns to; null outside a UMAT call.
thread_local sigjmp_buf* t_return = nullptr;
thread_local const UmatCallSite* t_site = nullptr;

/// The handlers that were there before, for signals outside a UMAT call.
std::array<struct sigaction, kGuardedSignals.size()> g_previous{};

std::size_t slot_of(int signal) {
  return static_cast<std::size_t>(std::find(kGuardedSignals.begin(), kGuardedSignals.end(), signal) -
                                  kGuardedSignals.begin());
}

void on_crash(int signal, siginfo_t*, void*) {
  if (t_return) siglongjmp(*t_return, signal);
  // Not a UMAT's: as if the guard were not there. The signal is blocked while this handler runs, so
  // the raise is delivered, to the previous disposition, when it returns.
  sigaction(signal, &g_previous[slot_of(signal)], nullptr);
  raise(signal);
}

/// An exit() from inside a UMAT call: say which call, and end with status 1 (Fortran's STOP exits
/// with 0, which would pass for success).
void on_exit() {
  if (!t_site) return;
  const UmatCallSite& s = *t_site;
  std::fprintf(stderr,
               "error: %s: %s (CMNAME \"%s\") ended the process (Fortran STOP, exit or a runtime error) in "
               "call KINC = %d, NOEL = %d, TIME = %g, DTIME = %g; soilsph stops (frames and checkpoints "
               "written before this call are kept)\n",
               s.library, s.symbol, s.name, s.increment, s.element, s.time, s.time_increment);
  std::fflush(stderr);
  _exit(1);
}

/// A stack for the handler on each thread that calls a UMAT, so that a UMAT's stack overflow
/// (SIGSEGV on the exhausted stack) can still be handled.
struct AlternateStack {
  std::vector<char> memory = std::vector<char>(std::max<std::size_t>(64 * 1024, 4 * SIGSTKSZ));
  AlternateStack() {
    stack_t s{};
    s.ss_sp = memory.data();
    s.ss_size = memory.size();
    sigaltstack(&s, nullptr);
  }
  ~AlternateStack() {
    stack_t s{};
    s.ss_flags = SS_DISABLE;
    sigaltstack(&s, nullptr);
  }
  AlternateStack(const AlternateStack&) = delete;
  AlternateStack& operator=(const AlternateStack&) = delete;
};

}  // namespace

void install_umat_crash_guard() {
  static std::mutex mutex;
  static bool exit_handler = false;
  const std::lock_guard lock(mutex);
  if (!exit_handler) exit_handler = std::atexit(on_exit) == 0;
  for (std::size_t k = 0; k < kGuardedSignals.size(); ++k) {
    struct sigaction now {};
    sigaction(kGuardedSignals[k], nullptr, &now);
    if ((now.sa_flags & SA_SIGINFO) && now.sa_sigaction == on_crash) continue;
    struct sigaction guard {};
    guard.sa_sigaction = on_crash;
    guard.sa_flags = SA_SIGINFO | SA_ONSTACK;
    sigemptyset(&guard.sa_mask);
    sigaction(kGuardedSignals[k], &guard, &g_previous[k]);
  }
}

int guarded_umat_call(const UmatCallSite& site, void (*call)(void*), void* context) {
  thread_local AlternateStack stack;
  sigjmp_buf back;
  // Without the signal mask (a system call per call): a crash unblocks its signal below instead.
  if (const int signal = sigsetjmp(back, 0); signal != 0) {
    t_return = nullptr;
    t_site = nullptr;
    sigset_t crashed;
    sigemptyset(&crashed);
    sigaddset(&crashed, signal);
    pthread_sigmask(SIG_UNBLOCK, &crashed, nullptr);
    return signal;
  }
  t_site = &site;
  t_return = &back;
  call(context);
  t_return = nullptr;
  t_site = nullptr;
  return 0;
}

std::string describe_signal(int signal) {
  switch (signal) {
    case SIGSEGV:
      return "SIGSEGV (a segmentation fault: memory it may not touch)";
    case SIGBUS:
      return "SIGBUS (a bus error)";
    case SIGFPE:
      return "SIGFPE (a floating-point or integer arithmetic trap)";
    case SIGILL:
      return "SIGILL (an illegal instruction)";
    case SIGABRT:
      return "SIGABRT (it called abort)";
    default:
      return "signal " + std::to_string(signal);
  }
}

}  // namespace soilsph

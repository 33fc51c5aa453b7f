#pragma once
/// @file
/// A UMAT plug-in runs in soilsph's own process: a segmentation fault, a floating-point trap, an
/// abort() or a Fortran STOP inside it would end soilsph with no word of which call did it. The
/// guard turns each into a message that names the library, the symbol and the call:
///   - a fault (SIGSEGV, SIGBUS, SIGFPE, SIGILL) or an abort (SIGABRT) while this thread is inside a
///     UMAT call jumps back to the call (siglongjmp from the handler, on a per-thread alternate stack
///     so that a stack overflow is caught too), where it becomes a UmatError: `point` stops with it,
///     `collapse` fails the step as for any failed stress update (the last good frame and a
///     checkpoint are kept), and the stress test counts it as a failure.
///   - an exit() from inside a call (Fortran STOP or ERROR STOP, a runtime error of gfortran's
///     checks, XIT stubs) cannot return into the call: an exit handler says which call ended the
///     process and ends it with status 1 (frames and checkpoints written before stay).
/// A signal outside a UMAT call goes to the handler that was there before (the default: the process
/// ends as it would without the guard). Why not a child process per call: a fork per particle and
/// step costs more than the call itself by three orders of magnitude, and a probe in a child at load
/// time sees only the first call, not the state where a model breaks.
#include <string>

namespace soilsph {

/// What the exit handler says of a call in progress.
struct UmatCallSite {
  const char* library = "";
  const char* symbol = "";
  const char* name = "";  ///< CMNAME
  int increment = 0;      ///< KINC
  int element = 0;        ///< NOEL
  double time = 0.0;      ///< TIME at the start of the increment
  double time_increment = 0.0;
};

/// Installs the signal and exit handlers (once per process, and again if another handler has
/// replaced them since: a test framework's, for instance). Called when a UMAT model is made.
void install_umat_crash_guard();

/// Runs call(context) as a UMAT call at `site`; returns 0, or the signal that ended the call.
int guarded_umat_call(const UmatCallSite& site, void (*call)(void*), void* context);

/// "SIGSEGV (segmentation fault)" and the like.
std::string describe_signal(int signal);

}  // namespace soilsph

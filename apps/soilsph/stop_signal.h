#pragma once
/// @file
/// SIGINT and SIGTERM as a request to stop cleanly: while a StopSignal lives, either signal only
/// sets a flag, which the time loop polls after every step (RunControl::stop_requested); the run
/// then writes its final frame, checkpoint and summary and exits with 128 + the signal (130, 143).
/// A second signal while the first is handled also only sets the flag; kill -9 cannot be caught.
namespace soilsph::cli {

class StopSignal {
 public:
  StopSignal();   ///< installs the handlers
  ~StopSignal();  ///< restores the previous ones
  StopSignal(const StopSignal&) = delete;
  StopSignal& operator=(const StopSignal&) = delete;

  /// The signal received (SIGINT or SIGTERM), or 0.
  int received() const;
  /// "SIGINT", "SIGTERM" or "no signal".
  static const char* name(int signal);
};

}  // namespace soilsph::cli

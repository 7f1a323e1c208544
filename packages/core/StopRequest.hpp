#pragma once
// Stopping a run cleanly on SIGINT, SIGTERM or SIGUSR1 (Ctrl-C, kill, a batch system's
// warning before its time limit).  The handler only records the signal; the run looks at it
// at points where every rank can agree to stop: after each accepted step and before each
// evaluation of a Newton iteration.  It then writes a checkpoint of the last accepted step
// and ends with exit status kStoppedExit.  A second signal of the same kind ends the process
// at once (the handler is reset after the first).
//
// Under Open MPI's mpirun, SIGUSR1 reaches every rank at once and mpirun then exits with the
// ranks' status.  SIGINT and SIGTERM make mpirun end the job instead: it sends the ranks
// SIGTERM after odls_base_sigkill_timeout seconds (default 1) and SIGKILL as long again
// after that, which is the time a rank has to finish its step and its checkpoint.

#include <stdexcept>
#include <string>

#include "core/TpetraTypes.hpp"

namespace impm {

// The driver's exit status after a clean stop.
constexpr int kStoppedExit = 5;

// Installs the handlers of SIGINT, SIGTERM and SIGUSR1.  Call once, after MPI and Kokkos
// started, so that no handler of theirs replaces impm's.
void installStopHandlers();

// Ignores SIGXFSZ, so that a write past the file size limit (ulimit -f) fails with an error
// that names the file (EFBIG) instead of killing the process.  Call first in main.
void ignoreFileSizeSignal();

// Collective: true on every rank when a stop signal reached any rank.
bool stopAgreed(const Comm& comm);

// The name of the signal received ("SIGTERM"), or "" when none was.
std::string stopSignalName();

// Thrown on every rank at once when stopAgreed() said so: the run abandons the step it is in
// (nothing of that step was committed) and unwinds to the place that writes the checkpoint.
class StopRequest : public std::runtime_error {
 public:
  StopRequest() : std::runtime_error("stop requested by " + stopSignalName()) {}
};

// A run that stopped cleanly: after which step, at what time, and the checkpoint written.
class RunStopped : public std::runtime_error {
 public:
  // abandoned: the signal came in the middle of step + 1, which was given up.
  RunStopped(int step, double time, bool abandoned, std::string checkpoint);
  int step() const { return step_; }
  double time() const { return time_; }
  bool abandoned() const { return abandoned_; }
  const std::string& checkpoint() const { return checkpoint_; }

 private:
  int step_;
  double time_;
  bool abandoned_;
  std::string checkpoint_;
};

// For tests: forget a received signal.
void clearStopRequest();

}  // namespace impm

#include "core/StopRequest.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <csignal>

namespace impm {

namespace {

volatile std::sig_atomic_t received = 0;  // the signal's number, 0: none
int agreed = 0;                           // the largest number any rank received

extern "C" void recordStop(int signal) {
  received = signal;
}

}  // namespace

void installStopHandlers() {
  struct sigaction action {};
  action.sa_handler = recordStop;
  sigemptyset(&action.sa_mask);
  // SA_RESETHAND: a second Ctrl-C ends the process at once.  SA_RESTART: a system call the
  // signal interrupts (a write, an MPI wait) goes on.
  action.sa_flags = SA_RESETHAND | SA_RESTART;
  for (int signal : {SIGINT, SIGTERM, SIGUSR1})
    sigaction(signal, &action, nullptr);
}

void ignoreFileSizeSignal() {
  std::signal(SIGXFSZ, SIG_IGN);
}

bool stopAgreed(const Comm& comm) {
  const int mine = received;
  agreed = mine;
  if (comm.getSize() > 1)
    Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, mine, Teuchos::outArg(agreed));
  return agreed != 0;
}

std::string stopSignalName() {
  switch (agreed ? agreed : static_cast<int>(received)) {
    case 0:
      return "";
    case SIGINT:
      return "SIGINT";
    case SIGTERM:
      return "SIGTERM";
    case SIGUSR1:
      return "SIGUSR1";
    default:
      return "signal " + std::to_string(received);
  }
}

RunStopped::RunStopped(int step, double time, bool abandoned, std::string checkpoint)
    : std::runtime_error("stopped by " + stopSignalName() + " after step " + std::to_string(step)),
      step_(step),
      time_(time),
      abandoned_(abandoned),
      checkpoint_(std::move(checkpoint)) {}

void clearStopRequest() {
  received = 0;
  agreed = 0;
}

}  // namespace impm

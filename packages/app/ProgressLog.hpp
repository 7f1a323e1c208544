#pragma once
// How much a run tells while it runs.  quiet: nothing but errors, warnings and the final
// summary; verbose: every step and every Newton iteration; normal: a step line while steps
// are slow (a second or more each), otherwise one every few seconds, always the first and
// the last, each with the elapsed time and an estimate of the time left (from the fraction
// of the load or of the final time done so far).  Every step is in the history CSV anyway.

#include <chrono>
#include <string>

namespace impm {

enum class Verbosity { quiet, normal, verbose };

class ProgressLog {
 public:
  // `fraction`: how much of the run is done at its start (a restart continues a run).
  ProgressLog(Verbosity verbosity, double fraction);

  // Whether the step that has just ended gets a line (`last`: the run's last step).  Call
  // once per step.
  bool due(bool last);
  // "  elapsed 12.3 s  left 4.5 s" for the run at `fraction`.
  std::string timing(double fraction) const;

 private:
  using Clock = std::chrono::steady_clock;
  double seconds(Clock::time_point since) const;

  Verbosity verbosity_;
  double startFraction_;
  Clock::time_point start_, lastStep_, lastLine_;
  bool printedAny_ = false;
};

}  // namespace impm

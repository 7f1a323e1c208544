#include "app/ProgressLog.hpp"

#include <cstdio>

namespace impm {

namespace {
constexpr double slowStep = 1.0;      // [s]: slower steps get a line each
constexpr double lineInterval = 3.0;  // [s]: otherwise one line this often
}  // namespace

ProgressLog::ProgressLog(Verbosity verbosity, double fraction)
    : verbosity_(verbosity),
      startFraction_(fraction),
      start_(Clock::now()),
      lastStep_(start_),
      lastLine_(start_) {}

double ProgressLog::seconds(Clock::time_point since) const {
  return std::chrono::duration<double>(Clock::now() - since).count();
}

bool ProgressLog::due(bool last) {
  const double stepTime = seconds(lastStep_);
  lastStep_ = Clock::now();
  if (verbosity_ == Verbosity::quiet)
    return false;
  const bool print = verbosity_ == Verbosity::verbose || last || !printedAny_ ||
                     stepTime >= slowStep || seconds(lastLine_) >= lineInterval;
  if (print)
    lastLine_ = lastStep_, printedAny_ = true;
  return print;
}

std::string ProgressLog::timing(double fraction) const {
  const double elapsed = seconds(start_);
  const double done = fraction - startFraction_;
  char text[64];
  if (done > 0 && fraction < 1.0 - 1e-9)
    std::snprintf(text, sizeof text, "  elapsed %.1f s  left %.1f s", elapsed,
                  elapsed * (1.0 - fraction) / done);
  else
    std::snprintf(text, sizeof text, "  elapsed %.1f s", elapsed);
  return text;
}

}  // namespace impm

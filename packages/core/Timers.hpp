#pragma once
// Named wall-clock timers of the phases of a run (Teuchos::TimeMonitor), summarised at the
// end when Output/Timers is on: the per-phase breakdown that performance work reads.

#include <Teuchos_TimeMonitor.hpp>

namespace impm {

// Times the enclosing scope under "impm: <phase>".
#define IMPM_TIMER(phase)                                  \
  static const Teuchos::RCP<Teuchos::Time> impmTimer_ =    \
      Teuchos::TimeMonitor::getNewCounter("impm: " phase); \
  Teuchos::TimeMonitor impmTimerMonitor_(*impmTimer_)

}  // namespace impm

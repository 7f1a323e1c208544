#pragma once
// One writer per output directory.  Two runs writing the same directory (a restart started
// while the first run still writes, a job resubmitted twice) would both report success over
// files that interleave their steps.  Rank 0 takes an exclusive advisory lock (flock) on
// "<directory>/.impm.lock", holding the process id, host and start time, for the life of the
// run; the system releases it when the process ends, however it ends.  The file is removed at
// a normal end; a run that finds the lock file replaced after locking it (removed by the
// previous holder meanwhile) locks the new one.

#include <string>

#include "core/TpetraTypes.hpp"

namespace impm {

class OutputLock {
 public:
  // Creates the directory if needed and takes the lock.  Collective; throws FileError(directory,
  // "is in use by another impm run (...)") on every rank when another process holds it.
  OutputLock(const std::string& directory, const Comm& comm);
  ~OutputLock();
  OutputLock(const OutputLock&) = delete;
  OutputLock& operator=(const OutputLock&) = delete;

  // The lock file's path.
  static std::string pathIn(const std::string& directory);

 private:
  std::string path_;
  int fd_ = -1;
};

}  // namespace impm

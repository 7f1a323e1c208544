#include "io/OutputLock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "core/Collective.hpp"
#include "core/Errors.hpp"

namespace impm {

namespace {

// What the holder wrote into the lock file, one line.
std::string holder(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  return line.empty() ? "a process that has not written its name yet" : line;
}

std::string whoAmI() {
  char host[256] = "";
  gethostname(host, sizeof host - 1);
  const std::time_t now = std::time(nullptr);
  char when[32] = "";
  std::strftime(when, sizeof when, "%Y-%m-%d %H:%M:%S", std::localtime(&now));
  std::ostringstream s;
  s << "process " << getpid() << " on " << host << ", started " << when;
  return s.str();
}

// Whether fd still is the file at path (not removed or replaced since it was opened).
bool stillThere(int fd, const std::string& path) {
  struct stat open {
  }, named{};
  return fstat(fd, &open) == 0 && stat(path.c_str(), &named) == 0 && open.st_ino == named.st_ino &&
         open.st_dev == named.st_dev;
}

}  // namespace

std::string OutputLock::pathIn(const std::string& directory) {
  return directory + "/.impm.lock";
}

OutputLock::OutputLock(const std::string& directory, const Comm& comm) : path_(pathIn(directory)) {
  collectively(comm, [&] {
    if (comm.getRank() != 0)
      return;
    std::error_code error;
    std::filesystem::create_directories(directory, error);
    if (error)
      throw FileError(directory, "cannot create the output directory (" + error.message() + ")");
    while (true) {
      fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
      if (fd_ < 0)
        throw FileError(path_, std::string("cannot create the output directory's lock file (") +
                                   std::strerror(errno) + ")");
      if (flock(fd_, LOCK_EX | LOCK_NB) != 0) {
        const int why = errno;
        ::close(fd_);
        fd_ = -1;
        if (why == EWOULDBLOCK)
          throw FileError(directory, "is in use by another impm run (" + holder(path_) +
                                         "); wait for it to end or choose another --output-dir");
        // A file system without locks (some network ones): the run goes on unguarded.
        ::unlink(path_.c_str());
        std::cout << "impm: warning: " << directory << ": cannot lock the output directory ("
                  << std::strerror(why) << "); nothing stops another run from writing it too\n";
        return;
      }
      if (stillThere(fd_, path_))
        break;
      ::close(fd_);  // the holder removed it as we opened it: lock the file there now
      fd_ = -1;
    }
    const std::string me = whoAmI() + "\n";
    if (ftruncate(fd_, 0) != 0 || write(fd_, me.data(), me.size()) < 0) {
      // The lock holds all the same; only the other run's message would lack the name.
    }
  });
}

OutputLock::~OutputLock() {
  if (fd_ < 0)
    return;
  ::unlink(path_.c_str());  // before the release, so that a waiting run locks a new file
  ::close(fd_);
}

}  // namespace impm

#include "core/Errors.hpp"

#include <cerrno>
#include <cstring>
#include <sstream>

namespace impm {

std::string systemReason() {
  return systemReason(errno);
}

std::string systemReason(int error) {
  return error ? std::strerror(error) : "unknown reason";
}

std::string trilinosMessage(const std::string& what) {
  // The first line that reports an error with the lines of its paragraph (Teuchos says
  // which sublist and why on the next lines), else the last line that is not a source
  // location or a throw count (some messages end with a list of valid values).
  std::istringstream in(what);
  std::string line, last, error;
  int paragraph = 0;
  while (std::getline(in, line)) {
    const auto start = line.find_first_not_of(" \t");
    if (start == std::string::npos) {
      if (!error.empty())
        return error;
      continue;
    }
    line = line.substr(start);
    if (!error.empty()) {
      if (++paragraph > 4)  // a dump that has no blank line after the message
        return error;
      error += " " + line;
      continue;
    }
    if (line.rfind("Throw", 0) == 0 || line.find(".hpp:") != std::string::npos ||
        line.find(".cpp:") != std::string::npos)
      continue;
    if (line.find("rror") != std::string::npos)
      error = line;
    last = line;
  }
  if (!error.empty())
    return error;
  return last.empty() ? what : last;
}

}  // namespace impm

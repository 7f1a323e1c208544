#include "core/Errors.hpp"

#include <sstream>

namespace impm {

std::string trilinosMessage(const std::string& what) {
  // The first line that reports an error, else the last line that is not a source
  // location or a throw count (some messages end with a list of valid values).
  std::istringstream in(what);
  std::string line, last;
  while (std::getline(in, line)) {
    const auto start = line.find_first_not_of(" \t");
    if (start == std::string::npos)
      continue;
    line = line.substr(start);
    if (line.rfind("Throw", 0) == 0 || line.find(".hpp:") != std::string::npos ||
        line.find(".cpp:") != std::string::npos)
      continue;
    if (line.find("rror") != std::string::npos)
      return line;
    last = line;
  }
  return last.empty() ? what : last;
}

}  // namespace impm

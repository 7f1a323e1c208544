#include "io/InputFile.hpp"

#include <cerrno>
#include <filesystem>
#include <system_error>

namespace impm {

std::string notAnInputFile(const std::string& path, const std::string& missing) {
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::file_status status = fs::status(path, error);  // follows links, as open() would
  if (error == std::errc::too_many_symbolic_link_levels)
    return "is a loop of symbolic links";
  if (status.type() == fs::file_type::not_found)
    return missing;
  if (error)
    return "cannot be read (" + error.message() + ")";
  if (status.type() == fs::file_type::directory)
    return "is a directory, not a file";
  if (status.type() != fs::file_type::regular)
    return "is a FIFO, socket or device, not a regular file";
  return "";
}

}  // namespace impm

#pragma once
// What an input file (a deck, an image, a mesh, a checkpoint) must be before impm opens it: a
// regular file, reached through at most a finite chain of symbolic links.  A FIFO or device
// would block open() until another process writes to it (no signal ends that wait), and a
// loop of symbolic links made the library's filesystem_error reach the catch-all handler,
// naming the deck instead of the file.

#include <string>

namespace impm {

// Why `path` cannot be read as an input file ("" when it can): `missing` when nothing is
// there, otherwise "is a loop of symbolic links", "is a directory, not a file", "is a FIFO,
// socket or device, not a regular file" or the system's reason.
std::string notAnInputFile(const std::string& path, const std::string& missing);

}  // namespace impm

#pragma once
// The kinds of failure a user can cause or meet, each with a one-line message.
//
// InputError: the deck is wrong (unknown name, wrong type, value out of range).  It names
// the parameter path; the driver adds the file name.  Raised before any output is written.
// FileError: another input file (a checkpoint) is missing, unreadable or of another run, or
// an output file cannot be written.  It names the file.
// NumericalError: the computation cannot go on (Newton diverged, a particle left the grid,
// a non-positive Jacobian).  It says what, where and when.

#include <stdexcept>
#include <string>

namespace impm {

class InputError : public std::runtime_error {
 public:
  InputError(const std::string& path, const std::string& what)
      : std::runtime_error(path.empty() ? what : path + ": " + what), path_(path) {}
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

// A file other than the deck that cannot be used (a checkpoint to restart from: raised before
// any output) or written (an output, with the system's reason): it names the file; the driver
// prints it instead of the deck's name.
class FileError : public std::runtime_error {
 public:
  FileError(const std::string& file, const std::string& what)
      : std::runtime_error(what), file_(file) {}
  const std::string& file() const { return file_; }

 private:
  std::string file_;
};

class NumericalError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The system's text for errno (or for `error`): "No space left on device".
std::string systemReason();
std::string systemReason(int error);

// The line of a Trilinos exception's text that says what went wrong (the text also lists
// source files, line numbers and throw counts).
std::string trilinosMessage(const std::string& what);

}  // namespace impm

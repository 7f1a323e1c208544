#pragma once
// Some libraries print when a call fails (netCDF prints "Error 27: File too large" on
// standard output under a file size limit, HDF5 its error stacks on standard error), before
// they return the error code that impm turns into its own one-line message.  While a
// CapturedOutput lives, what is written to file descriptors 1 and 2 goes to a temporary file
// instead of the terminal; firstLine() gives it back, for the message.  For the one thread
// that writes files, around library calls only: the descriptors are the process's.

#include <cstdio>
#include <string>

namespace impm {

class CapturedOutput {
 public:
  CapturedOutput();
  ~CapturedOutput();  // standard output and error are what they were again
  CapturedOutput(const CapturedOutput&) = delete;
  CapturedOutput& operator=(const CapturedOutput&) = delete;

  // The first line written so far that is not blank (without its newline), "" when none.
  std::string firstLine() const;

 private:
  std::FILE* sink_ = nullptr;  // null: the capture could not be set up, nothing is redirected
  int saved_[2] = {-1, -1};    // the original standard output and error
};

}  // namespace impm

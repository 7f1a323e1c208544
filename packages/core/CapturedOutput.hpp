#pragma once
// Some libraries print when a call fails (netCDF prints "Error 27: File too large" on
// standard output under a file size limit, Open MPI's file layer the failed write on standard
// error, Ifpack2 a zero pivot on standard error), besides returning the error that impm turns
// into its own one-line message.  While a CapturedOutput lives, what is written to file
// descriptor 2 (and 1, when asked) goes to a temporary file instead of the terminal;
// firstLine() gives it back, for the message.  Around library calls only, on the thread that
// makes them: the descriptors are the process's.

#include <cstdio>
#include <string>

namespace impm {

class CapturedOutput {
 public:
  enum class Streams { error, outputAndError };
  explicit CapturedOutput(Streams streams = Streams::outputAndError);
  ~CapturedOutput();  // standard output and error are what they were again
  CapturedOutput(const CapturedOutput&) = delete;
  CapturedOutput& operator=(const CapturedOutput&) = delete;

  // The first line written so far that is not blank (without its newline), "" when none.
  std::string firstLine() const;

 private:
  std::FILE* sink_ = nullptr;  // null: the capture could not be set up, nothing is redirected
  int count_ = 0;              // descriptors redirected: standard error first
  int saved_[2] = {-1, -1};    // the originals
};

}  // namespace impm

#include "core/CapturedOutput.hpp"

#include <unistd.h>

namespace impm {

namespace {

constexpr int kDescriptors[2] = {STDERR_FILENO, STDOUT_FILENO};

}  // namespace

CapturedOutput::CapturedOutput(Streams streams)
    : count_(streams == Streams::outputAndError ? 2 : 1) {
  std::fflush(stdout);
  std::fflush(stderr);
  sink_ = std::tmpfile();
  if (!sink_)
    return;
  for (int k = 0; k < count_; ++k) {
    saved_[k] = ::dup(kDescriptors[k]);
    if (saved_[k] < 0 || ::dup2(::fileno(sink_), kDescriptors[k]) < 0) {
      for (int j = 0; j <= k; ++j)
        if (saved_[j] >= 0) {
          ::dup2(saved_[j], kDescriptors[j]);
          ::close(saved_[j]);
        }
      std::fclose(sink_);
      sink_ = nullptr;
      return;
    }
  }
}

CapturedOutput::~CapturedOutput() {
  if (!sink_)
    return;
  std::fflush(stdout);
  std::fflush(stderr);
  for (int k = 0; k < count_; ++k) {
    ::dup2(saved_[k], kDescriptors[k]);
    ::close(saved_[k]);
  }
  std::fclose(sink_);
}

std::string CapturedOutput::firstLine() const {
  if (!sink_)
    return "";
  std::fflush(stdout);
  std::fflush(stderr);
  std::string line;
  char buffer[512];
  std::rewind(sink_);
  while (std::fgets(buffer, sizeof buffer, sink_)) {
    line = buffer;
    const auto start = line.find_first_not_of(" \t\r\n");
    if (start == std::string::npos) {
      line.clear();
      continue;  // blank lines before the message
    }
    line = line.substr(start);
    break;
  }
  std::fseek(sink_, 0, SEEK_END);
  while (!line.empty() && (line.back() == '\n' || line.back() == '\r'))
    line.pop_back();
  return line;
}

}  // namespace impm

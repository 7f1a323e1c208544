#include "io/CsvFile.hpp"

#include <cstdio>
#include <stdexcept>

namespace impm {

namespace {

FILE* openOrThrow(const std::string& path, const char* mode) {
  FILE* f = std::fopen(path.c_str(), mode);
  if (!f)
    throw std::runtime_error("cannot write " + path);
  return f;
}

void writeHeader(FILE* f, const std::vector<std::string>& columns) {
  for (std::size_t c = 0; c < columns.size(); ++c)
    std::fprintf(f, "%s%s", c ? "," : "", columns[c].c_str());
  std::fputc('\n', f);
}

}  // namespace

CsvHistory::CsvHistory(const std::string& path, const std::vector<std::string>& columns)
    : path_(path), columns_(columns) {
  FILE* f = openOrThrow(path, "w");
  writeHeader(f, columns);
  std::fclose(f);
}

void CsvHistory::append(const std::vector<double>& row) const {
  if (row.size() != columns_.size())
    throw std::logic_error("history row has the wrong length");
  FILE* f = openOrThrow(path_, "a");
  for (std::size_t c = 0; c < row.size(); ++c)
    std::fprintf(f, "%s%.17g", c ? "," : "", row[c]);
  std::fputc('\n', f);
  std::fclose(f);
}

void writeCsvTable(const std::string& path, const std::vector<std::string>& columns,
                   const std::vector<std::vector<double>>& values) {
  FILE* f = openOrThrow(path, "w");
  writeHeader(f, columns);
  const std::size_t rows = values.empty() ? 0 : values[0].size();
  for (std::size_t r = 0; r < rows; ++r) {
    for (std::size_t c = 0; c < values.size(); ++c)
      std::fprintf(f, "%s%.17g", c ? "," : "", values[c][r]);
    std::fputc('\n', f);
  }
  std::fclose(f);
}

}  // namespace impm

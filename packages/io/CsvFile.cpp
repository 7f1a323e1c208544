#include "io/CsvFile.hpp"

#include <charconv>
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

// Writes x in the shortest form that reads back to the same double (std::to_chars without a
// precision): exact like "%.17g", several times faster, and shorter.
void writeNumber(FILE* f, double x) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, x).ptr;
  std::fwrite(text, 1, end - text, f);
}

template <class Value>
void writeRow(FILE* f, std::size_t n, const Value& value) {
  for (std::size_t c = 0; c < n; ++c) {
    if (c)
      std::fputc(',', f);
    writeNumber(f, value(c));
  }
  std::fputc('\n', f);
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
  writeRow(f, row.size(), [&](std::size_t c) { return row[c]; });
  std::fclose(f);
}

void writeCsvTable(const std::string& path, const std::vector<std::string>& columns,
                   const std::vector<std::vector<double>>& values) {
  FILE* f = openOrThrow(path, "w");
  writeHeader(f, columns);
  const std::size_t rows = values.empty() ? 0 : values[0].size();
  for (std::size_t r = 0; r < rows; ++r)
    writeRow(f, values.size(), [&](std::size_t c) { return values[c][r]; });
  std::fclose(f);
}

}  // namespace impm

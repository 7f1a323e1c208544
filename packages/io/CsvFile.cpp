#include "io/CsvFile.hpp"

#include "core/MpiComm.hpp"

#include <algorithm>
#include <charconv>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <stdexcept>

namespace impm {

namespace {

void writeOrThrow(const std::string& path, const char* mode, const std::string& text) {
  FILE* f = std::fopen(path.c_str(), mode);
  const bool written = f && std::fwrite(text.data(), 1, text.size(), f) == text.size();
  if (f)
    std::fclose(f);
  if (!written)
    throw std::runtime_error("cannot write " + path);
}

// Appends x in the shortest form that reads back to the same double (std::to_chars without
// a precision): exact like "%.17g", several times faster, and shorter.
void appendNumber(std::string& out, double x) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, x).ptr;
  out.append(text, end);
}

std::string header(const std::vector<std::string>& columns) {
  std::string out;
  for (std::size_t c = 0; c < columns.size(); ++c)
    out += (c ? "," : "") + columns[c];
  return out + "\n";
}

// Appends one row: value(0), ..., value(n - 1).
template <class Value>
void appendRow(std::string& out, std::size_t n, const Value& value) {
  for (std::size_t c = 0; c < n; ++c) {
    if (c)
      out += ',';
    appendNumber(out, value(c));
  }
  out += '\n';
}

}  // namespace

std::string formatCsvRows(const std::vector<std::vector<double>>& values) {
  const std::size_t rows = values.empty() ? 0 : values[0].size();
  std::string out;
  out.reserve(rows * values.size() * 20);
  for (std::size_t r = 0; r < rows; ++r)
    appendRow(out, values.size(), [&](std::size_t c) { return values[c][r]; });
  return out;
}

CsvHistory::CsvHistory(const std::string& path, const std::vector<std::string>& columns,
                       int keepThrough)
    : path_(path), columns_(columns) {
  std::string text = header(columns);
  if (keepThrough >= 0) {
    std::ifstream in(path);
    std::string line;
    if (in && std::getline(in, line) && line + "\n" == text) {
      continued_ = true;
      while (std::getline(in, line)) {
        char* end = nullptr;
        const double step = std::strtod(line.c_str(), &end);
        if (end == line.c_str() || *end != ',' || step > keepThrough)
          break;  // rows are in step order; a torn last row ends the file too
        text += line + "\n";
      }
    }
  }
  // Replaced in one rename, so a crash leaves the old file or the new one.
  writeOrThrow(path + ".tmp", "w", text);
  if (std::rename((path + ".tmp").c_str(), path.c_str()) != 0)
    throw std::runtime_error("cannot write " + path);
}

void CsvHistory::append(const std::vector<double>& row) const {
  if (row.size() != columns_.size())
    throw std::logic_error("history row has the wrong length");
  std::string text;
  appendRow(text, row.size(), [&](std::size_t c) { return row[c]; });
  writeOrThrow(path_, "a", text);
}

void writeCsvTable(const std::string& path, const std::vector<std::string>& columns,
                   const std::vector<std::vector<double>>& values) {
  writeOrThrow(path, "w", header(columns) + formatCsvRows(values));
}

void writeCsvTableCollectively(const std::string& path, const Teuchos::Comm<int>& comm,
                               const std::vector<std::string>& columns,
                               const std::vector<std::vector<double>>& localValues) {
  const std::string text =
      (comm.getRank() == 0 ? header(columns) : std::string()) + formatCsvRows(localValues);
  // Each rank's bytes go right after those of the ranks before it.
  long long size = static_cast<long long>(text.size()), offset = 0;
  MPI_Comm raw = rawComm(comm);
  MPI_Exscan(&size, &offset, 1, MPI_LONG_LONG, MPI_SUM, raw);
  if (comm.getRank() == 0)
    offset = 0;  // MPI_Exscan leaves rank 0's result undefined
  MPI_File file;
  int error =
      MPI_File_open(raw, path.c_str(), MPI_MODE_CREATE | MPI_MODE_WRONLY, MPI_INFO_NULL, &file);
  if (error != MPI_SUCCESS)  // collective: every rank sees the failure
    throw std::runtime_error("cannot write " + path);
  error = MPI_File_set_size(file, 0);  // an older, longer file must not leave a tail
  for (std::size_t done = 0; error == MPI_SUCCESS && done < text.size();) {
    const int chunk = static_cast<int>(std::min<std::size_t>(text.size() - done, INT_MAX / 2));
    error = MPI_File_write_at(file, offset + static_cast<MPI_Offset>(done), text.data() + done,
                              chunk, MPI_CHAR, MPI_STATUS_IGNORE);
    done += static_cast<std::size_t>(chunk);
  }
  int failed = error != MPI_SUCCESS, anyFailed = 0;
  MPI_Allreduce(&failed, &anyFailed, 1, MPI_INT, MPI_MAX, raw);
  MPI_File_close(&file);
  if (anyFailed)
    throw std::runtime_error("cannot write " + path);
}

}  // namespace impm

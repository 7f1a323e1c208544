#include "io/CsvFile.hpp"

#include "core/CapturedOutput.hpp"
#include "core/Collective.hpp"
#include "core/Errors.hpp"
#include "core/MpiComm.hpp"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <stdexcept>

namespace impm {

namespace {

// FileError(path, "cannot write (<the system's reason>)") unless the whole text reached the
// file (fclose too can fail: the last block is written there).
void writeOrThrow(const std::string& path, const char* mode, const std::string& text) {
  errno = 0;
  FILE* f = std::fopen(path.c_str(), mode);
  if (!f)
    throw FileError(path, "cannot write (" + systemReason() + ")");
  const bool written = std::fwrite(text.data(), 1, text.size(), f) == text.size();
  const int reason = errno;
  if (std::fclose(f) != 0 || !written)
    throw FileError(path, "cannot write (" + systemReason(written ? errno : reason) + ")");
}

std::string header(const std::vector<std::string>& columns) {
  std::string out;
  for (std::size_t c = 0; c < columns.size(); ++c)
    out += (c ? "," : "") + columns[c];
  return out + "\n";
}

// Appends one row: value(0), ..., value(n - 1), each in the shortest form that reads back to
// the same double (std::to_chars without a precision): exact like "%.17g", several times
// faster, and shorter.  The numbers go straight into the string, in room for the longest
// form, which is then cut to the row's length.
template <class Value>
void appendRow(std::string& out, std::size_t n, const Value& value) {
  constexpr std::size_t widest = 25;  // "-2.2250738585072014e-308" and a separator
  const std::size_t start = out.size();
  out.resize(start + n * widest + 1);
  char* const end = out.data() + out.size();
  char* p = out.data() + start;
  for (std::size_t c = 0; c < n; ++c) {
    if (c)
      *p++ = ',';
    p = std::to_chars(p, end, value(c)).ptr;
  }
  *p++ = '\n';
  out.resize(static_cast<std::size_t>(p - out.data()));
}

// The system's reason of the failed MPI-IO call: errno when the MPI library left one (Open
// MPI's file layer does), otherwise MPI's own text for the error code.
std::string mpiReason(int error) {
  if (errno != 0)
    return systemReason();
  char text[MPI_MAX_ERROR_STRING];
  int length = 0;
  MPI_Error_string(error, text, &length);
  return std::string(text, length);
}

// Why MPI_File_open failed.  Open MPI's file layer may leave errno from its own clean-up
// (EBADF was seen when the directory had vanished), so the directory is asked first: the
// system's reason when it cannot be written into, else errno or MPI's text as above.
std::string openFailureReason(const std::string& file, int error) {
  const int left = errno;
  const std::filesystem::path parent = std::filesystem::path(file).parent_path();
  errno = 0;
  if (::access(parent.empty() ? "." : parent.c_str(), W_OK | X_OK) != 0)
    return systemReason();
  errno = left;
  return mpiReason(error);
}

std::size_t rowCount(const std::vector<std::vector<double>>& values) {
  return values.empty() ? 0 : values[0].size();
}

// Row r of the table whose column c is values[c].
void appendTableRow(std::string& out, const std::vector<std::vector<double>>& values,
                    std::size_t r) {
  appendRow(out, values.size(), [&](std::size_t c) { return values[c][r]; });
}

// The bytes that formatCsvRows would return, without holding them.
long long formattedSize(const std::vector<std::vector<double>>& values) {
  long long size = 0;
  std::string row;
  for (std::size_t r = 0; r < rowCount(values); ++r) {
    row.clear();
    appendTableRow(row, values, r);
    size += static_cast<long long>(row.size());
  }
  return size;
}

// Writes text at offset, again from where a write that ends short without an error stopped
// (Open MPI's file layer at a file size limit); a write that makes no progress is a failure.
int writeAllAt(MPI_File file, MPI_Offset offset, const std::string& text) {
  int error = MPI_SUCCESS;
  for (std::size_t done = 0; error == MPI_SUCCESS && done < text.size();) {
    const int chunk = static_cast<int>(std::min<std::size_t>(text.size() - done, INT_MAX / 2));
    MPI_Status status;
    errno = 0;
    error = MPI_File_write_at(file, offset + static_cast<MPI_Offset>(done), text.data() + done,
                              chunk, MPI_CHAR, &status);
    int written = 0;
    if (error == MPI_SUCCESS)
      MPI_Get_count(&status, MPI_CHAR, &written);
    if (error == MPI_SUCCESS && written <= 0)
      error = MPI_ERR_IO;
    done += static_cast<std::size_t>(std::max(written, 0));
  }
  return error;
}

// The rows that the ranks after this one hold: all rows less those of this rank and the ranks
// before it (two reductions, O(log P) each).  Collective.
long long rowsAfterThisRank(MPI_Comm comm, std::size_t rows) {
  const long long mine = static_cast<long long>(rows);
  long long throughThisRank = 0, all = 0;
  MPI_Scan(&mine, &throughThisRank, 1, MPI_LONG_LONG, MPI_SUM, comm);
  MPI_Allreduce(&mine, &all, 1, MPI_LONG_LONG, MPI_SUM, comm);
  return all - throughThisRank;
}

}  // namespace

std::string formatCsvRows(const std::vector<std::vector<double>>& values) {
  std::string out;
  out.reserve(rowCount(values) * values.size() * 20);
  for (std::size_t r = 0; r < rowCount(values); ++r)
    appendTableRow(out, values, r);
  return out;
}

CsvHistory::CsvHistory(const std::string& path, const std::vector<std::string>& columns,
                       int keepThrough, const std::vector<std::string>& notes)
    : path_(path), columns_(columns) {
  std::string text = header(columns);
  if (keepThrough >= 0) {
    std::ifstream in(path);
    std::string line;
    if (in && std::getline(in, line) && line + "\n" == text) {
      continued_ = true;
      while (std::getline(in, line)) {
        if (line.rfind("# ", 0) == 0) {  // an earlier restart's note
          text += line + "\n";
          continue;
        }
        char* end = nullptr;
        const double step = std::strtod(line.c_str(), &end);
        if (end == line.c_str() || *end != ',' || step > keepThrough)
          break;  // rows are in step order; a torn last row ends the file too
        text += line + "\n";
      }
    }
  }
  for (std::string note : notes) {
    std::replace(note.begin(), note.end(), '\n', ' ');  // one line each
    text += "# " + note + "\n";
  }
  // Replaced in one rename, so a crash leaves the old file or the new one.
  try {
    writeOrThrow(path + ".tmp", "w", text);
  } catch (const FileError& e) {  // named by the file it was to become
    std::remove((path + ".tmp").c_str());
    throw FileError(path, e.what());
  }
  if (std::rename((path + ".tmp").c_str(), path.c_str()) != 0)
    throw FileError(path, "cannot rename " + path + ".tmp into place (" + systemReason() + ")");
}

void CsvHistory::append(const std::vector<double>& row) const {
  if (row.size() != columns_.size())
    throw std::logic_error("history row has the wrong length");
  std::string text;
  appendRow(text, row.size(), [&](std::size_t c) { return row[c]; });
  std::error_code error;
  const auto before = std::filesystem::file_size(path_, error);
  try {
    writeOrThrow(path_, "a", text);
  } catch (const FileError&) {
    if (!error)  // a row written in part (up to a file size limit) is taken back
      std::filesystem::resize_file(path_, before, error);
    throw;
  }
}

void writeCsvTable(const std::string& path, const std::vector<std::string>& columns,
                   const std::vector<std::vector<double>>& values) {
  const std::string temporary = path + ".tmp";  // renamed into place once complete
  try {
    writeOrThrow(temporary, "w", header(columns) + formatCsvRows(values));
    if (std::rename(temporary.c_str(), path.c_str()) != 0)
      throw FileError(path, "cannot rename " + temporary + " into place (" + systemReason() + ")");
  } catch (const FileError& e) {
    std::remove(temporary.c_str());
    throw FileError(path, e.what());
  }
}

void writeCsvTableCollectively(const std::string& path, const Teuchos::Comm<int>& comm,
                               const std::vector<std::string>& columns,
                               const std::vector<std::vector<double>>& localValues) {
  // The rows are formatted twice, once to count their bytes and once in blocks that are
  // written as they fill: a table of 10^6 particles is about 0.5 GB of text, which would
  // otherwise be held whole (and its pages faulted in) for the write.  A rank's bytes are
  // the offset of the ranks after it only where one of those has rows: the last rank's rows,
  // and rank 0's when it holds the whole table, are not counted.
  MPI_Comm raw = rawComm(comm);
  const std::string head = comm.getRank() == 0 ? header(columns) : std::string();
  const bool counted = rowsAfterThisRank(raw, rowCount(localValues)) > 0;
  long long size = counted ? static_cast<long long>(head.size()) + formattedSize(localValues) : 0;
  long long offset = 0;
  // Each rank's bytes go right after those of the ranks before it.
  MPI_Exscan(&size, &offset, 1, MPI_LONG_LONG, MPI_SUM, raw);
  if (comm.getRank() == 0)
    offset = 0;  // MPI_Exscan leaves rank 0's result undefined
  // Into a new file renamed into place once complete, so that a failed write leaves the
  // table of the last output step.
  const std::string temporary = path + ".tmp";
  MPI_File file;
  errno = 0;  // mpiReason reads it
  int error = MPI_File_open(raw, temporary.c_str(), MPI_MODE_CREATE | MPI_MODE_WRONLY,
                            MPI_INFO_NULL, &file);
  if (error != MPI_SUCCESS)  // collective: every rank sees the failure
    throw FileError(path, "cannot write (" + openFailureReason(temporary, error) + ")");
  std::string failure;  // this rank's, with the reason taken when it happened
  std::optional<CapturedOutput> quiet(std::in_place);  // Open MPI's file layer prints failures
  error = MPI_File_set_size(file, 0);  // an older, longer file must not leave a tail
  constexpr std::size_t block = 8 << 20;
  std::string text = head;
  text.reserve(block + 4096);
  MPI_Offset at = offset;
  const auto flush = [&] {
    if (error == MPI_SUCCESS)
      error = writeAllAt(file, at, text);
    at += static_cast<MPI_Offset>(text.size());
    text.clear();
  };
  for (std::size_t r = 0; r < rowCount(localValues) && error == MPI_SUCCESS; ++r) {
    appendTableRow(text, localValues, r);
    if (text.size() >= block)
      flush();
  }
  flush();
  if (error != MPI_SUCCESS)
    failure = mpiReason(error);
  else if (counted && at != offset + size)  // a defect, reported like a failed write
    failure = "the rows' text changed between counting and writing";
  error = MPI_File_close(&file);  // collective; the last bytes may be written here
  if (error != MPI_SUCCESS && failure.empty())
    failure = mpiReason(error);
  quiet.reset();
  try {
    collectively(comm, [&] {
      if (!failure.empty())
        throw FileError(path, "cannot write (" + failure + ")");
      if (comm.getRank() == 0 && std::rename(temporary.c_str(), path.c_str()) != 0)
        throw FileError(path,
                        "cannot rename " + temporary + " into place (" + systemReason() + ")");
    });
  } catch (const FileError&) {
    if (comm.getRank() == 0)
      std::remove(temporary.c_str());
    throw;
  }
}

}  // namespace impm

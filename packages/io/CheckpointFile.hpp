#pragma once
// A checkpoint on disk: a netCDF file (the classic CDF-5 format) of named attributes and 2-D
// variables (rows x columns of doubles or 64-bit integers), with a checksum per variable
// (the sum over rows of a hash of the row's index and bytes, so that it can be checked
// while the rows are read in pieces) and, from format version 2 on, one per attribute (a
// hash of its name and bytes, in the attribute "<name>_checksum"): every byte a restart
// reads is checked.
// Serial: one process writes it, any number read it.  doc/design.md gives the layout.
//
// Writing goes to "<path>.tmp", which commit() renames to <path> after the data reached the
// disk, so a crash while writing leaves the previous checkpoint as it was.  Reading checks
// the format version and every checksum it reads; a truncated or corrupted file, a missing
// attribute or variable, each throws FileError(path, reason).

#include <cstdint>
#include <string>
#include <vector>

namespace impm {

// The version this code writes; it reads this one and older ones (version 1: the attributes
// without checksums).
constexpr int kCheckpointVersion = 2;

class CheckpointWriter {
 public:
  explicit CheckpointWriter(const std::string& path);
  ~CheckpointWriter();  // an uncommitted file is removed
  CheckpointWriter(const CheckpointWriter&) = delete;
  CheckpointWriter& operator=(const CheckpointWriter&) = delete;

  void attribute(const std::string& name, const std::string& value);
  void attribute(const std::string& name, const std::vector<double>& values);
  void attribute(const std::string& name, const std::vector<long long>& values);
  // Declares a variable of rows x columns (before any data is written).
  void declare(const std::string& name, std::size_t rows, std::size_t columns, bool integer);
  // Its values, row-major (all of them at once).
  void write(const std::string& name, const std::vector<double>& values);
  void write(const std::string& name, const std::vector<long long>& values);
  // Closes, flushes to disk and renames the file into place.
  void commit();

 private:
  int variable(const std::string& name) const;
  // FileError(path, "cannot write the checkpoint (what: netCDF's reason)") on an error.
  void require(int status, const std::string& what) const;
  void endDefinitions();
  template <class T>
  void writeValues(const std::string& name, const std::vector<T>& values);
  // The attribute's checksum beside it.
  void attributeChecksum(const std::string& name, const void* data, std::size_t bytes);
  std::string path_, temporary_;
  int id_ = -1;
  bool defining_ = true;
};

class CheckpointReader {
 public:
  // Opens and checks the format version.  Throws FileError.
  explicit CheckpointReader(const std::string& path);
  ~CheckpointReader();
  CheckpointReader(const CheckpointReader&) = delete;
  CheckpointReader& operator=(const CheckpointReader&) = delete;

  const std::string& path() const { return path_; }
  int version() const { return version_; }
  bool has(const std::string& variable) const;
  bool hasAttribute(const std::string& attribute) const;
  std::string text(const std::string& attribute) const;
  std::vector<double> numbers(const std::string& attribute) const;
  std::vector<long long> integers(const std::string& attribute) const;
  // Rows and columns of a variable.
  std::pair<std::size_t, std::size_t> shape(const std::string& variable) const;
  // Rows [first, first + count) of a variable, row-major, as doubles; `checked`: they count
  // towards the checksum (rows read twice must count once).
  std::vector<double> rows(const std::string& variable, std::size_t first, std::size_t count,
                           bool checked = true) const;
  std::vector<long long> integerRows(const std::string& variable, std::size_t first,
                                     std::size_t count) const;
  // Compares the checksum of every variable whose rows have all been read; throws FileError
  // naming the first that differs.
  void checkSums() const;

 private:
  int variable(const std::string& name) const;
  // The bytes of all the variables' values.
  std::uintmax_t dataBytes() const;
  template <class T>
  std::vector<T> readRows(const std::string& name, std::size_t first, std::size_t count,
                          bool checked) const;
  void account(const std::string& name, std::size_t first, std::size_t count, std::size_t rowBytes,
               const void* data) const;
  // FileError naming the first attribute whose checksum differs (format version 2 on).
  void verifyAllAttributes() const;
  // FileError unless the attribute's checksum matches its bytes (format version 2 on).
  void verifyAttribute(const std::string& name, const void* data, std::size_t bytes) const;
  struct Sum {
    std::uint64_t sum = 0;
    std::size_t rows = 0;
  };
  std::string path_;
  int id_ = -1;
  int version_ = 0;
  mutable std::vector<std::pair<std::string, Sum>> sums_;
};

// The checksum contribution of one row (exposed for tests).
std::uint64_t rowHash(std::size_t row, const void* data, std::size_t bytes);

}  // namespace impm

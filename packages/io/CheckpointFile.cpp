#include "io/CheckpointFile.hpp"

#include <fcntl.h>
#include <netcdf.h>
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <filesystem>

#include "core/CapturedOutput.hpp"
#include "core/Errors.hpp"
#include "io/InputFile.hpp"

namespace impm {

namespace {

const char* const kVersion = "impm_checkpoint_version";
const char* const kChecksum = "checksum";

// Throws FileError(path, what + netCDF's reason) when status is an error.
void check(int status, const std::string& path, const std::string& what) {
  if (status != NC_NOERR)
    throw FileError(path, what + " (" + nc_strerror(status) + ")");
}

// The data reaches the disk before the rename that makes it the checkpoint.
void syncFile(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY);
  if (fd >= 0) {
    ::fsync(fd);
    ::close(fd);
  }
}

template <class T>
std::uint64_t checksum(const std::vector<T>& values, std::size_t columns) {
  std::uint64_t sum = 0;
  const std::size_t rows = columns ? values.size() / columns : 0;
  for (std::size_t r = 0; r < rows; ++r)
    sum += rowHash(r, values.data() + r * columns, columns * sizeof(T));
  return sum;
}

// The name of an attribute's checksum, and the checksum of its name and value bytes.
std::string checksumName(const std::string& attribute) {
  return attribute + "_checksum";
}

std::uint64_t attributeHash(const std::string& name, const void* data, std::size_t bytes) {
  std::vector<unsigned char> all(name.begin(), name.end());
  all.push_back(0);
  all.insert(all.end(), static_cast<const unsigned char*>(data),
             static_cast<const unsigned char*>(data) + bytes);
  return rowHash(0, all.data(), all.size());
}

}  // namespace

std::uint64_t rowHash(std::size_t row, const void* data, std::size_t bytes) {
  std::uint64_t h = 1469598103934665603ull;  // FNV-1a over the row index, then the bytes
  const auto mix = [&h](const unsigned char* p, std::size_t n) {
    for (std::size_t k = 0; k < n; ++k)
      h = (h ^ p[k]) * 1099511628211ull;
  };
  const std::uint64_t index = row;
  mix(reinterpret_cast<const unsigned char*>(&index), sizeof index);
  mix(static_cast<const unsigned char*>(data), bytes);
  return h;
}

CheckpointWriter::CheckpointWriter(const std::string& path)
    : path_(path), temporary_(path + ".tmp") {
  // CDF-5, not netCDF-4: a write that fails (a full disk, ulimit -f) inside HDF5 leaves it a
  // file that it crashes on at exit (HDF5 1.10.8); the classic format has no such state, and
  // the checksums find a truncated file as HDF5 would.
  require(nc_create(temporary_.c_str(), NC_CLOBBER | NC_64BIT_DATA, &id_), "create");
  const int version = kCheckpointVersion;
  require(nc_put_att_int(id_, NC_GLOBAL, kVersion, NC_INT, 1, &version), "version");
}

void CheckpointWriter::require(int status, const std::string& what) const {
  if (status != NC_NOERR)  // named by the checkpoint it was to become; the .tmp file goes
    throw FileError(path_,
                    "cannot write the checkpoint (" + what + ": " + nc_strerror(status) + ")");
}

CheckpointWriter::~CheckpointWriter() {
  if (id_ >= 0) {
    // Abandoned (a failed write): dropped without another attempt to write it.
    const CapturedOutput quiet;
    nc_abort(id_);
    std::remove(temporary_.c_str());
  }
}

void CheckpointWriter::attributeChecksum(const std::string& name, const void* data,
                                         std::size_t bytes) {
  const unsigned long long sum = attributeHash(name, data, bytes);
  require(nc_put_att_ulonglong(id_, NC_GLOBAL, checksumName(name).c_str(), NC_UINT64, 1, &sum),
          "attribute " + checksumName(name));
}

void CheckpointWriter::attribute(const std::string& name, const std::string& value) {
  require(nc_put_att_text(id_, NC_GLOBAL, name.c_str(), value.size(), value.c_str()),
          "attribute " + name);
  attributeChecksum(name, value.data(), value.size());
}

void CheckpointWriter::attribute(const std::string& name, const std::vector<double>& values) {
  require(nc_put_att_double(id_, NC_GLOBAL, name.c_str(), NC_DOUBLE, values.size(), values.data()),
          "attribute " + name);
  attributeChecksum(name, values.data(), values.size() * sizeof(double));
}

void CheckpointWriter::attribute(const std::string& name, const std::vector<long long>& values) {
  require(nc_put_att_longlong(id_, NC_GLOBAL, name.c_str(), NC_INT64, values.size(), values.data()),
          "attribute " + name);
  attributeChecksum(name, values.data(), values.size() * sizeof(long long));
}

void CheckpointWriter::declare(const std::string& name, std::size_t rows, std::size_t columns,
                               bool integer) {
  if (!defining_)
    throw std::logic_error("checkpoint variable " + name + " declared after data");
  int dims[2];
  require(nc_def_dim(id_, (name + "_rows").c_str(), rows, &dims[0]), name);
  require(nc_def_dim(id_, (name + "_columns").c_str(), columns, &dims[1]), name);
  int var = 0;
  require(nc_def_var(id_, name.c_str(), integer ? NC_INT64 : NC_DOUBLE, 2, dims, &var), name);
  // The checksum's place, filled in with the data: the classic format takes a new attribute
  // only while defining, and a changed value of the same size at any time.
  const unsigned long long none = 0;
  require(nc_put_att_ulonglong(id_, var, kChecksum, NC_UINT64, 1, &none), name);
}

void CheckpointWriter::endDefinitions() {
  if (defining_)
    require(nc_enddef(id_), "definitions");
  defining_ = false;
}

int CheckpointWriter::variable(const std::string& name) const {
  int var = 0;
  require(nc_inq_varid(id_, name.c_str(), &var), "variable " + name);
  return var;
}

namespace {

int put(int id, int var, const std::vector<double>& v) {
  return nc_put_var_double(id, var, v.data());
}
int put(int id, int var, const std::vector<long long>& v) {
  return nc_put_var_longlong(id, var, v.data());
}
int get(int id, int var, const std::size_t* start, const std::size_t* count, double* v) {
  return nc_get_vara_double(id, var, start, count, v);
}
int get(int id, int var, const std::size_t* start, const std::size_t* count, long long* v) {
  return nc_get_vara_longlong(id, var, start, count, v);
}

}  // namespace

template <class T>
void CheckpointWriter::writeValues(const std::string& name, const std::vector<T>& values) {
  endDefinitions();
  const int var = variable(name);
  int dims[2];
  std::size_t columns = 0;
  nc_inq_vardimid(id_, var, dims);
  nc_inq_dimlen(id_, dims[1], &columns);
  require(put(id_, var, values), "variable " + name);
  const unsigned long long sum = checksum(values, columns);
  require(nc_put_att_ulonglong(id_, var, kChecksum, NC_UINT64, 1, &sum), name);
}

void CheckpointWriter::write(const std::string& name, const std::vector<double>& values) {
  writeValues(name, values);
}

void CheckpointWriter::write(const std::string& name, const std::vector<long long>& values) {
  writeValues(name, values);
}

void CheckpointWriter::commit() {
  require(nc_close(id_), "close");
  id_ = -1;
  syncFile(temporary_);
  std::error_code error;
  std::filesystem::rename(temporary_, path_, error);
  if (error)
    throw FileError(path_, "cannot rename " + temporary_ + " into place: " + error.message());
  syncFile(std::filesystem::path(path_).parent_path().empty()
               ? "."
               : std::filesystem::path(path_).parent_path().string());
}

CheckpointReader::CheckpointReader(const std::string& path) : path_(path) {
  if (const std::string why = notAnInputFile(path, "no such checkpoint file"); !why.empty())
    throw FileError(path, why);
  const int status = nc_open(path.c_str(), NC_NOWRITE, &id_);
  if (status != NC_NOERR) {
    id_ = -1;
    throw FileError(path, std::string("is not a readable checkpoint (truncated or not one: ") +
                              nc_strerror(status) + ")");
  }
  nc_type type;
  std::size_t length = 0;
  if (nc_inq_att(id_, NC_GLOBAL, kVersion, &type, &length) != NC_NOERR || length != 1 ||
      nc_get_att_int(id_, NC_GLOBAL, kVersion, &version_) != NC_NOERR)
    throw FileError(path, "is a netCDF file but not an impm checkpoint (no format version)");
  if (version_ > kCheckpointVersion || version_ < 1)
    throw FileError(path, "has checkpoint format version " + std::to_string(version_) +
                              "; this impm reads format versions up to " +
                              std::to_string(kCheckpointVersion));
  verifyAllAttributes();
  // A classic netCDF file cut short still opens (and reads zeros where its data is missing):
  // its variables must fit in it.
  const auto size = std::filesystem::file_size(path);
  if (size < dataBytes())
    throw FileError(path, "is not a readable checkpoint (truncated: its variables hold " +
                              std::to_string(dataBytes()) + " bytes, the file has " +
                              std::to_string(size) + ")");
}

std::uintmax_t CheckpointReader::dataBytes() const {
  int variables = 0;
  nc_inq_nvars(id_, &variables);
  std::uintmax_t bytes = 0;
  for (int var = 0; var < variables; ++var) {
    int ndims = 0, dims[NC_MAX_VAR_DIMS];
    nc_type type;
    std::size_t typeSize = 0, count = 1;
    nc_inq_var(id_, var, nullptr, &type, &ndims, dims, nullptr);
    nc_inq_type(id_, type, nullptr, &typeSize);
    for (int d = 0; d < ndims; ++d) {
      std::size_t length = 0;
      nc_inq_dimlen(id_, dims[d], &length);
      count *= length;
    }
    bytes += count * typeSize;
  }
  return bytes;
}

CheckpointReader::~CheckpointReader() {
  if (id_ >= 0)
    nc_close(id_);
}

bool CheckpointReader::has(const std::string& name) const {
  int var = 0;
  return nc_inq_varid(id_, name.c_str(), &var) == NC_NOERR;
}

bool CheckpointReader::hasAttribute(const std::string& name) const {
  nc_type type;
  std::size_t length = 0;
  return nc_inq_att(id_, NC_GLOBAL, name.c_str(), &type, &length) == NC_NOERR;
}

int CheckpointReader::variable(const std::string& name) const {
  int var = 0;
  if (nc_inq_varid(id_, name.c_str(), &var) != NC_NOERR)
    throw FileError(path_, "has no variable '" + name + "'");
  return var;
}

std::string CheckpointReader::text(const std::string& name) const {
  std::size_t length = 0;
  nc_type type;
  if (nc_inq_att(id_, NC_GLOBAL, name.c_str(), &type, &length) != NC_NOERR || type != NC_CHAR)
    throw FileError(path_, "has no attribute '" + name + "'");
  std::string value(length, '\0');
  check(nc_get_att_text(id_, NC_GLOBAL, name.c_str(), value.data()), path_, name);
  verifyAttribute(name, value.data(), value.size());
  return value;
}

void CheckpointReader::verifyAllAttributes() const {
  // Every attribute, whether this restart reads it or not (a partition's, say, is read only
  // with its table of cell owners).
  int count = 0;
  nc_inq_natts(id_, &count);
  for (int k = 0; k < count; ++k) {
    char name[NC_MAX_NAME + 1] = "";
    nc_inq_attname(id_, NC_GLOBAL, k, name);
    const std::string attribute = name;
    if (attribute == kVersion ||
        (attribute.size() > 9 && attribute.compare(attribute.size() - 9, 9, "_checksum") == 0))
      continue;
    nc_type type;
    std::size_t length = 0, size = 0;
    check(nc_inq_att(id_, NC_GLOBAL, name, &type, &length), path_, attribute);
    check(nc_inq_type(id_, type, nullptr, &size), path_, attribute);
    std::vector<unsigned char> bytes(length * size);
    check(nc_get_att(id_, NC_GLOBAL, name, bytes.data()), path_, attribute);
    verifyAttribute(attribute, bytes.data(), bytes.size());
  }
}

void CheckpointReader::verifyAttribute(const std::string& name, const void* data,
                                       std::size_t bytes) const {
  if (version_ < 2)
    return;  // written before the attributes had checksums
  unsigned long long stored = 0;
  nc_type type;
  std::size_t length = 0;
  const std::string sumName = checksumName(name);
  if (nc_inq_att(id_, NC_GLOBAL, sumName.c_str(), &type, &length) != NC_NOERR ||
      type != NC_UINT64 || length != 1 ||
      nc_get_att_ulonglong(id_, NC_GLOBAL, sumName.c_str(), &stored) != NC_NOERR)
    throw FileError(path_, "attribute '" + name + "' has no checksum");
  if (stored != attributeHash(name, data, bytes))
    throw FileError(path_, "attribute '" + name + "' is corrupted (its checksum differs)");
}

std::vector<double> CheckpointReader::numbers(const std::string& name) const {
  std::size_t length = 0;
  nc_type type;
  if (nc_inq_att(id_, NC_GLOBAL, name.c_str(), &type, &length) != NC_NOERR || type != NC_DOUBLE)
    throw FileError(path_, "has no attribute '" + name + "'");
  std::vector<double> values(length);
  check(nc_get_att_double(id_, NC_GLOBAL, name.c_str(), values.data()), path_, name);
  verifyAttribute(name, values.data(), values.size() * sizeof(double));
  return values;
}

std::vector<long long> CheckpointReader::integers(const std::string& name) const {
  std::size_t length = 0;
  nc_type type;
  if (nc_inq_att(id_, NC_GLOBAL, name.c_str(), &type, &length) != NC_NOERR || type != NC_INT64)
    throw FileError(path_, "has no attribute '" + name + "'");
  std::vector<long long> values(length);
  check(nc_get_att_longlong(id_, NC_GLOBAL, name.c_str(), values.data()), path_, name);
  verifyAttribute(name, values.data(), values.size() * sizeof(long long));
  return values;
}

std::pair<std::size_t, std::size_t> CheckpointReader::shape(const std::string& name) const {
  const int var = variable(name);
  int ndims = 0, dims[2];
  check(nc_inq_varndims(id_, var, &ndims), path_, name);
  if (ndims != 2)
    throw FileError(path_, "variable '" + name + "' is not a table");
  check(nc_inq_vardimid(id_, var, dims), path_, name);
  std::size_t rows = 0, columns = 0;
  nc_inq_dimlen(id_, dims[0], &rows);
  nc_inq_dimlen(id_, dims[1], &columns);
  return {rows, columns};
}

void CheckpointReader::account(const std::string& name, std::size_t first, std::size_t count,
                               std::size_t rowBytes, const void* data) const {
  auto it = sums_.begin();
  while (it != sums_.end() && it->first != name)
    ++it;
  if (it == sums_.end())
    it = sums_.insert(sums_.end(), {name, Sum{}});
  const char* bytes = static_cast<const char*>(data);
  for (std::size_t r = 0; r < count; ++r)
    it->second.sum += rowHash(first + r, bytes + r * rowBytes, rowBytes);
  it->second.rows += count;
}

template <class T>
std::vector<T> CheckpointReader::readRows(const std::string& name, std::size_t first,
                                          std::size_t count, bool checked) const {
  const auto [rows, columns] = shape(name);
  if (first + count > rows)
    throw FileError(path_, "variable '" + name + "' has " + std::to_string(rows) + " rows, not " +
                               std::to_string(first + count));
  std::vector<T> values(count * columns);
  const std::size_t start[2] = {first, 0}, extent[2] = {count, columns};
  if (count)
    check(get(id_, variable(name), start, extent, values.data()), path_,
          "cannot read variable " + name);
  if (checked)
    account(name, first, count, columns * sizeof(T), values.data());
  return values;
}

std::vector<double> CheckpointReader::rows(const std::string& name, std::size_t first,
                                           std::size_t count, bool checked) const {
  return readRows<double>(name, first, count, checked);
}

std::vector<long long> CheckpointReader::integerRows(const std::string& name, std::size_t first,
                                                     std::size_t count) const {
  return readRows<long long>(name, first, count, true);
}

void CheckpointReader::checkSums() const {
  for (const auto& [name, sum] : sums_) {
    if (sum.rows != shape(name).first)
      continue;  // not read whole
    unsigned long long stored = 0;
    if (nc_get_att_ulonglong(id_, variable(name), kChecksum, &stored) != NC_NOERR)
      throw FileError(path_, "variable '" + name + "' has no checksum");
    if (stored != sum.sum)
      throw FileError(path_, "variable '" + name + "' is corrupted (its checksum differs)");
  }
}

}  // namespace impm

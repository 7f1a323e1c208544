#include "io/ExodusFile.hpp"

#include <exodusII.h>
#include <netcdf.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <filesystem>
#include <stdexcept>

#include "core/CapturedOutput.hpp"
#include "core/Errors.hpp"
#include "io/Version.hpp"

namespace impm {

namespace {

// FileError naming the file, the step of the writing that failed and the reason: the
// system's (errno; netCDF also passes it on as a positive code), netCDF's or exodusII's, or
// what the libraries printed (`said`, which keeps it off the terminal).
void check(int status, const std::string& path, const char* what, const CapturedOutput& said) {
  if (status >= 0)
    return;
  const int system = errno;
  const char *message = nullptr, *function = nullptr;
  int code = 0;
  ex_get_err(&message, &function, &code);
  const std::string printed = said.firstLine();
  const std::string reason = code > 0              ? systemReason(code)
                             : system != 0         ? systemReason(system)
                             : code < 0            ? std::string(nc_strerror(code))
                             : !printed.empty()    ? printed
                             : message && *message ? std::string(message)
                                                   : std::string("unknown reason");
  throw FileError(path, std::string("cannot write the Exodus file (") + what + ": " + reason + ")");
}

// Closes an open file when a failed write leaves the function early (a file closed by the
// normal path is released first).
struct OpenFile {
  int id;
  ~OpenFile() {
    if (id >= 0)
      ex_close(id);
  }
  int release() {
    const int open = id;
    id = -1;
    return open;
  }
};

std::vector<char*> cStrings(const std::vector<std::string>& names) {
  std::vector<char*> out;
  for (const auto& n : names)
    out.push_back(const_cast<char*>(n.c_str()));
  return out;
}

int openForAppend(const std::string& path, const CapturedOutput& said) {
  int cpuWordSize = sizeof(double), ioWordSize = 0;
  float version = 0;
  const int id = ex_open(path.c_str(), EX_WRITE, &cpuWordSize, &ioWordSize, &version);
  check(id, path, "open", said);
  return id;
}

void putVariableNames(int id, ex_entity_type type, const std::vector<std::string>& names,
                      const std::string& path, const CapturedOutput& said) {
  if (names.empty())
    return;
  check(ex_put_variable_param(id, type, static_cast<int>(names.size())), path, "variable count",
        said);
  auto c = cStrings(names);
  check(ex_put_variable_names(id, type, static_cast<int>(names.size()), c.data()), path,
        "variable names", said);
}

// Everything the file's header holds, defined before any bulk data is written.  A netCDF-3
// file whose header grows after data was written moves all of it behind the header (and a new
// record variable reshuffles every record), in the library's 8 kB blocks; the element
// variables that exodusII would define one by one at their first write moved the whole file
// once each.  `variables`: the nodal, element and global variables' names.
void defineContents(int id, const ExodusMesh& mesh,
                    const std::array<std::vector<std::string>, 3>& variables,
                    const std::string& path, const CapturedOutput& said) {
  // 16 kB of room in the header for the definitions to come (exodusII 6.02's file id is the
  // netCDF id).  Asked for here, it moves the coordinates' still unwritten extent once and
  // the definitions after it move nothing; asked for right after ex_create, it was not kept.
  int status = nc_redef(id);
  if (status == NC_NOERR)
    status = nc__enddef(id, 16 << 10, 4, 0, 4);
  if (status != NC_NOERR)
    throw FileError(path, std::string("cannot write the Exodus file (header space: ") +
                              nc_strerror(status) + ")");
  check(ex_put_block(id, EX_ELEM_BLOCK, 1, mesh.elementType.c_str(),
                     static_cast<int64_t>(mesh.numElements()), mesh.nodesPerElement, 0, 0, 0),
        path, "element block", said);
  putVariableNames(id, EX_NODAL, variables[0], path, said);
  putVariableNames(id, EX_ELEM_BLOCK, variables[1], path, said);
  putVariableNames(id, EX_GLOBAL, variables[2], path, said);
  if (!variables[1].empty()) {  // defines the block's element variables, all at once
    std::vector<int> everyVariable(variables[1].size(), 1);
    check(ex_put_truth_table(id, EX_ELEM_BLOCK, 1, static_cast<int>(everyVariable.size()),
                             everyVariable.data()),
          path, "element variables", said);
  }
  std::vector<std::string> axes = {"x", "y", "z"};
  axes.resize(mesh.dimension);
  auto axisNames = cStrings(axes);
  check(ex_put_coord_names(id, axisNames.data()), path, "coordinate names", said);
  if (!mesh.elementIds.empty())  // defines its variable as it writes it
    check(ex_put_id_map(id, EX_ELEM_MAP, mesh.elementIds.data()), path, "element ids", said);
}

void writeMesh(int id, const ExodusMesh& mesh, const std::string& path,
               const CapturedOutput& said) {
  const double* c[3] = {nullptr, nullptr, nullptr};
  for (int d = 0; d < mesh.dimension; ++d)
    c[d] = mesh.coords[d].data();
  check(ex_put_coord(id, c[0], c[1], c[2]), path, "coordinates", said);
  check(ex_put_conn(id, EX_ELEM_BLOCK, 1, mesh.connectivity.data(), nullptr, nullptr), path,
        "connectivity", said);
}

}  // namespace

ExodusFile::ExodusFile(const std::string& path, const std::string& title, const ExodusMesh& mesh,
                       const std::vector<std::string>& nodalVariables,
                       const std::vector<std::string>& elementVariables,
                       const std::vector<std::string>& globalVariables, int keepSteps)
    : path_(path),
      numNodes_(mesh.numNodes()),
      numElements_(mesh.numElements()),
      numNodal_(nodalVariables.size()),
      numElement_(elementVariables.size()),
      numGlobal_(globalVariables.size()) {
  if (keepSteps > 0 && std::filesystem::exists(path)) {
    // Into a new file beside the old one, then in its place: a crash leaves one of them.
    const std::string old = path + ".old";
    std::error_code error;
    std::filesystem::rename(path, old, error);
    if (!error) {
      create(path, title, mesh, nodalVariables, elementVariables, globalVariables);
      continued_ = copySteps(old, keepSteps);
      std::filesystem::remove(old, error);
      if (continued_) {
        steps_ = keepSteps;
        return;
      }
    }
  }
  create(path, title, mesh, nodalVariables, elementVariables, globalVariables);
}

void ExodusFile::create(const std::string& path, const std::string& title, const ExodusMesh& mesh,
                        const std::vector<std::string>& nodalVariables,
                        const std::vector<std::string>& elementVariables,
                        const std::vector<std::string>& globalVariables) const {
  const CapturedOutput said;
  errno = 0;
  int cpuWordSize = sizeof(double), ioWordSize = sizeof(double);
  const int id = ex_create(path.c_str(), EX_CLOBBER, &cpuWordSize, &ioWordSize);
  check(id, path, "create", said);
  try {
    OpenFile file{id};
    check(ex_put_init(id, title.c_str(), mesh.dimension, static_cast<int64_t>(numNodes_),
                      static_cast<int64_t>(numElements_), 1, 0, 0),
          path, "init", said);
    // Which impm wrote it, in the file's info records (ParaView shows them, ncdump prints them).
    std::string made = versionLine().substr(0, MAX_LINE_LENGTH);
    char* records[] = {made.data()};
    check(ex_put_info(id, 1, records), path, "info", said);
    defineContents(id, mesh, {nodalVariables, elementVariables, globalVariables}, path, said);
    writeMesh(id, mesh, path, said);
    check(ex_close(file.release()), path, "close", said);
  } catch (const FileError&) {
    // A file half made (a full disk, ulimit -f) opens in no reader: it is not left behind.
    std::error_code ignored;
    std::filesystem::remove(path, ignored);
    throw;
  }
}

bool ExodusFile::copySteps(const std::string& from, int steps) const {
  const CapturedOutput said;
  errno = 0;
  int cpuWordSize = sizeof(double), ioWordSize = 0;
  float version = 0;
  const int in = ex_open(from.c_str(), EX_READ, &cpuWordSize, &ioWordSize, &version);
  if (in < 0)
    return false;
  const OpenFile input{in};
  ex_init_params p{};
  int nodal = 0, element = 0, global = 0;
  const bool fits =
      ex_get_init_ext(in, &p) >= 0 && static_cast<std::size_t>(p.num_nodes) == numNodes_ &&
      static_cast<std::size_t>(p.num_elem) == numElements_ &&
      ex_get_variable_param(in, EX_NODAL, &nodal) >= 0 &&
      ex_get_variable_param(in, EX_ELEM_BLOCK, &element) >= 0 &&
      ex_get_variable_param(in, EX_GLOBAL, &global) >= 0 &&
      static_cast<std::size_t>(nodal) == numNodal_ &&
      static_cast<std::size_t>(element) == numElement_ &&
      static_cast<std::size_t>(global) == numGlobal_ && ex_inquire_int(in, EX_INQ_TIME) >= steps;
  bool copied = fits;
  if (fits) {
    const int out = openForAppend(path_, said);
    OpenFile output{out};
    std::vector<double> values(std::max({numNodes_, numElements_, numGlobal_, std::size_t(1)}));
    const auto copy = [&](int step, ex_entity_type type, std::size_t variables, std::size_t n) {
      for (std::size_t v = 0; v < variables && copied; ++v)
        copied = ex_get_var(in, step, type, static_cast<int>(v + 1), 1, static_cast<int64_t>(n),
                            values.data()) >= 0 &&
                 ex_put_var(out, step, type, static_cast<int>(v + 1), 1, static_cast<int64_t>(n),
                            values.data()) >= 0;
    };
    for (int step = 1; step <= steps && copied; ++step) {
      double time = 0.0;
      copied = ex_get_time(in, step, &time) >= 0 && ex_put_time(out, step, &time) >= 0;
      copy(step, EX_NODAL, numNodal_, numNodes_);
      copy(step, EX_ELEM_BLOCK, numElement_, numElements_);
      if (numGlobal_ && copied)
        copied = ex_get_var(in, step, EX_GLOBAL, 1, 0, static_cast<int64_t>(numGlobal_),
                            values.data()) >= 0 &&
                 ex_put_var(out, step, EX_GLOBAL, 1, 0, static_cast<int64_t>(numGlobal_),
                            values.data()) >= 0;
    }
    check(ex_close(output.release()), path_, "close", said);
  }
  return copied;
}

void ExodusFile::append(double time, const std::vector<std::vector<double>>& nodal,
                        const std::vector<std::vector<double>>& element,
                        const std::vector<double>& global) {
  if (nodal.size() != numNodal_ || element.size() != numElement_ || global.size() != numGlobal_)
    throw std::logic_error("Exodus output: wrong number of variables for " + path_);
  const CapturedOutput said;
  errno = 0;
  const int id = openForAppend(path_, said);
  OpenFile file{id};
  const int step = steps_ + 1;
  check(ex_put_time(id, step, &time), path_, "time", said);
  for (std::size_t v = 0; v < numNodal_; ++v)
    check(ex_put_var(id, step, EX_NODAL, static_cast<int>(v + 1), 1,
                     static_cast<int64_t>(numNodes_), nodal[v].data()),
          path_, "nodal variable", said);
  for (std::size_t v = 0; v < numElement_; ++v)
    check(ex_put_var(id, step, EX_ELEM_BLOCK, static_cast<int>(v + 1), 1,
                     static_cast<int64_t>(numElements_), element[v].data()),
          path_, "element variable", said);
  if (numGlobal_)
    check(ex_put_var(id, step, EX_GLOBAL, 1, 0, static_cast<int64_t>(numGlobal_), global.data()),
          path_, "global variables", said);
  check(ex_close(file.release()), path_, "close", said);
  steps_ = step;
}

}  // namespace impm

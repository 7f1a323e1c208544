#include "solver/MumpsFactorization.hpp"

#include <dmumps_c.h>

#include <Teuchos_CommHelpers.hpp>

#include <algorithm>
#include <limits>
#include <map>

#include "core/Collective.hpp"
#include "core/Errors.hpp"
#include "core/MpiComm.hpp"

namespace impm {

namespace {

// MUMPS's control and information arrays are 1-based in its documentation.
constexpr int icntl(int k) {
  return k - 1;
}
constexpr int info(int k) {
  return k - 1;
}

// MUMPS's phases (JOB).
constexpr int kInitialize = -1, kTerminate = -2, kAnalyse = 1, kFactor = 2, kSolve = 3;
// INFOG(1) when the working space ran out (ICNTL(14) too small).
constexpr int kWorkspace = -9;
// INFOG(1) for a matrix that is singular: numerically (a zero pivot) or structurally.
constexpr int kNumericallySingular = -10, kStructurallySingular = -6;

int orderingCode(const std::string& name) {
  static const std::map<std::string, int> codes{{"amd", 0},      {"amf", 2},   {"scotch", 3},
                                                {"pord", 4},     {"metis", 5}, {"qamd", 6},
                                                {"automatic", 7}};
  const auto it = codes.find(name);
  if (it == codes.end())
    throw std::invalid_argument("MUMPS: unknown ordering '" + name + "'");
  return it->second;
}

// Every rank's entries, concatenated in rank order, on rank 0.  Collective.
template <class T>
std::vector<T> gatherOnRoot(const Comm& comm, const std::vector<T>& mine, MPI_Datatype type) {
  const MPI_Comm raw = rawComm(comm);
  const int count = static_cast<int>(mine.size()), ranks = comm.getSize();
  std::vector<int> counts(comm.getRank() == 0 ? ranks : 0), offsets(counts.size() + 1, 0);
  MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, raw);
  for (std::size_t r = 0; r < counts.size(); ++r)
    offsets[r + 1] = offsets[r] + counts[r];
  std::vector<T> all(comm.getRank() == 0 ? offsets.back() : 0);
  MPI_Gatherv(mine.data(), count, type, all.data(), counts.data(), offsets.data(), type, 0, raw);
  return all;
}

}  // namespace

struct MumpsFactorization::Instance {
  DMUMPS_STRUC_C id{};
  MPI_Comm comm = MPI_COMM_NULL;  // rank 0 alone: MUMPS's messages never meet impm's
};

MumpsFactorization::MumpsFactorization(const Teuchos::RCP<const Comm>& comm,
                                       const MumpsOptions& options)
    : comm_(comm), options_(options), mumps_(std::make_unique<Instance>()) {
  const bool root = comm->getRank() == 0;
  MPI_Comm_split(rawComm(*comm), root ? 0 : MPI_UNDEFINED, 0, &mumps_->comm);
  if (!root)
    return;
  auto& id = mumps_->id;
  id.comm_fortran = static_cast<MUMPS_INT>(MPI_Comm_c2f(mumps_->comm));
  id.par = 1;  // the host factorises
  id.sym = options.symmetric ? 2 : 0;
  id.job = kInitialize;
  dmumps_c(&id);
  // Quiet: failures come back through INFOG and become impm's messages.
  id.icntl[icntl(1)] = -1;
  id.icntl[icntl(2)] = -1;
  id.icntl[icntl(3)] = -1;
  id.icntl[icntl(4)] = 0;
  id.icntl[icntl(18)] = 0;  // the matrix assembled on rank 0
  id.icntl[icntl(20)] = 0;  // dense right-hand sides on rank 0
  id.icntl[icntl(21)] = 0;  // the solution on rank 0
  id.icntl[icntl(7)] = orderingCode(options.ordering);
  id.icntl[icntl(14)] = options.workspaceIncrease;
}

MumpsFactorization::~MumpsFactorization() {
  if (mumps_->comm == MPI_COMM_NULL)
    return;  // not rank 0
  mumps_->id.job = kTerminate;
  dmumps_c(&mumps_->id);
  MPI_Comm_free(&mumps_->comm);
}

void MumpsFactorization::run(int job, const std::string& what) const {
  auto& id = mumps_->id;
  id.job = job;
  dmumps_c(&id);
  const int status = id.infog[info(1)];
  if (status >= 0)
    return;
  if (status == kNumericallySingular || status == kStructurallySingular)
    throw NumericalError(
        "linear solver failure: the matrix is singular (MUMPS found a zero pivot "
        "in its " +
        what + ", INFOG(1) = " + std::to_string(status) + ")");
  throw NumericalError("linear solver failure: MUMPS's " + what +
                       " failed with INFOG(1) = " + std::to_string(status) + ", INFOG(2) = " +
                       std::to_string(id.infog[info(2)]) + " (MUMPS users' guide, section 8)");
}

void MumpsFactorization::entries(const CrsMatrix& A, std::vector<int>& rows,
                                 std::vector<int>& columns, std::vector<double>& values) const {
  // Each column's MUMPS index: the owning rank's offset plus its local row there.
  Vector index(A.getRowMap());
  {
    const GO offset = contiguous_->getMinGlobalIndex();
    auto own = index.getLocalViewHost(Tpetra::Access::OverwriteAll);
    for (size_t k = 0; k < own.extent(0); ++k)
      own(k, 0) = static_cast<double>(offset + GO(k) + 1);
  }
  Vector columnIndex(A.getColMap());
  const auto importer = A.getGraph()->getImporter();
  if (importer.is_null())
    Tpetra::deep_copy(columnIndex, index);
  else
    columnIndex.doImport(index, *importer, Tpetra::INSERT);

  const auto rowIndex = index.getLocalViewHost(Tpetra::Access::ReadOnly);
  const auto colIndex = columnIndex.getLocalViewHost(Tpetra::Access::ReadOnly);
  const auto local = A.getLocalMatrixHost();
  const auto& offsets = local.graph.row_map;
  rows.clear();
  columns.clear();
  values.clear();
  rows.reserve(local.nnz());
  columns.reserve(local.nnz());
  values.reserve(local.nnz());
  for (LO r = 0; r < LO(local.numRows()); ++r) {
    const int i = static_cast<int>(rowIndex(r, 0));
    for (auto k = offsets(r); k < offsets(r + 1); ++k) {
      const int j = static_cast<int>(colIndex(local.graph.entries(k), 0));
      if (options_.symmetric && j > i)
        continue;  // LDL^T reads the lower triangle; MUMPS would add the upper one to it
      rows.push_back(i);
      columns.push_back(j);
      values.push_back(local.values(k));
    }
  }
}

void MumpsFactorization::factor(const CrsMatrix& A) {
  const GO n = A.getGlobalNumRows();
  if (n > std::numeric_limits<MUMPS_INT>::max())
    throw NumericalError(
        "linear solver failure: MUMPS takes at most 2^31 - 1 unknowns, the "
        "system has " +
        std::to_string(n));
  if (rowMap_.is_null() || !rowMap_->isSameAs(*A.getRowMap())) {
    rowMap_ = A.getRowMap();
    contiguous_ = Teuchos::rcp(new Map(n, A.getRowMap()->getNodeNumElements(), 0, comm_));
    root_ = Teuchos::rcp(new Map(n, comm_->getRank() == 0 ? size_t(n) : 0, 0, comm_));
    gather_ = Teuchos::rcp(new Import(contiguous_, root_));
  }

  std::vector<int> rows, columns;
  std::vector<double> values;
  entries(A, rows, columns, values);
  rows = gatherOnRoot(*comm_, rows, MPI_INT);
  columns = gatherOnRoot(*comm_, columns, MPI_INT);
  values_ = gatherOnRoot(*comm_, values, MPI_DOUBLE);
  collectively(*comm_, [&] {
    if (comm_->getRank() == 0)
      factorOnRoot(rows, columns);
  });
  Teuchos::broadcast(*comm_, 0, Teuchos::outArg(analyses_));  // counted on rank 0
  ++factorizations_;
}

void MumpsFactorization::factorOnRoot(std::vector<int>& rows, std::vector<int>& columns) {
  auto& id = mumps_->id;
  id.n = static_cast<MUMPS_INT>(rowMap_->getGlobalNumElements());
  id.a = values_.data();
  if (rows != rows_ || columns != columns_ || analyses_ == 0) {
    rows_ = std::move(rows);
    columns_ = std::move(columns);
    id.nnz = static_cast<MUMPS_INT8>(rows_.size());
    id.irn = rows_.data();
    id.jcn = columns_.data();
    run(kAnalyse, "analysis");
    ++analyses_;
  }
  for (int retry = 0;; ++retry) {
    try {
      run(kFactor, "factorisation");
      return;
    } catch (const NumericalError&) {
      if (id.infog[info(1)] != kWorkspace || retry == 2)
        throw;
      id.icntl[icntl(14)] = 2 * std::max(id.icntl[icntl(14)], 10);
    }
  }
}

void MumpsFactorization::solve(const MultiVector& B, MultiVector& X) const {
  const size_t nrhs = B.getNumVectors();
  // B's rows renumbered contiguously, gathered on rank 0, solved there, and scattered back.
  MultiVector local(contiguous_, nrhs, false), onRoot(root_, nrhs, false);
  for (size_t c = 0; c < nrhs; ++c) {
    const auto from = B.getData(c);
    auto to = local.getDataNonConst(c);
    std::copy(from.begin(), from.end(), to.begin());
  }
  onRoot.doImport(local, *gather_, Tpetra::INSERT);
  {
    auto& id = mumps_->id;
    auto values = onRoot.get1dViewNonConst();
    id.rhs = values.getRawPtr();
    id.nrhs = static_cast<MUMPS_INT>(nrhs);
    id.lrhs = static_cast<MUMPS_INT>(std::max<size_t>(onRoot.getStride(), 1));
    collectively(*comm_, [&] {
      if (comm_->getRank() == 0)
        run(kSolve, "solve");
    });
  }
  local.doExport(onRoot, *gather_, Tpetra::INSERT);
  for (size_t c = 0; c < nrhs; ++c) {
    const auto from = local.getData(c);
    auto to = X.getDataNonConst(c);
    std::copy(from.begin(), from.end(), to.begin());
  }
}

}  // namespace impm

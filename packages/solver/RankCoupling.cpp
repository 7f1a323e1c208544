#include "solver/RankCoupling.hpp"

#include <Teuchos_BLAS.hpp>
#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_LAPACK.hpp>
#include <algorithm>

#include "core/Errors.hpp"

namespace impm {

namespace {

// Every rank's list, merged, sorted, without repeats (on every rank).
std::vector<GO> unionOverRanks(const Comm& comm, const std::vector<GO>& mine) {
  int longest = 0;
  Teuchos::reduceAll<int, int>(comm, Teuchos::REDUCE_MAX, static_cast<int>(mine.size()),
                               Teuchos::outArg(longest));
  if (longest == 0)
    return {};
  constexpr GO kNone = -1;
  std::vector<GO> padded(mine);
  padded.resize(longest, kNone);
  std::vector<GO> all(static_cast<std::size_t>(longest) * comm.getSize());
  Teuchos::gatherAll<int, GO>(comm, longest, padded.data(), static_cast<int>(all.size()),
                              all.data());
  all.erase(std::remove(all.begin(), all.end(), kNone), all.end());
  std::sort(all.begin(), all.end());
  all.erase(std::unique(all.begin(), all.end()), all.end());
  return all;
}

}  // namespace

RankCoupling::RankCoupling(const CrsMatrix& A, const std::vector<LO>& rowOfColumn,
                           const LocalSolve& solve)
    : comm_(A.getComm()), n_(static_cast<int>(A.getRowMap()->getNodeNumElements())) {
  // The columns of other ranks' unknowns in which this rank's rows hold non-zero entries:
  // one spike each.  (A graph may hold entries no particle fills: the halo's patches,
  // core/DofMap.hpp.  A zero column's spike is zero.)
  const Map& columns = *A.getColMap();
  const auto local = A.getLocalMatrixHost();
  std::vector<char> held(rowOfColumn.size(), 0);
  for (std::size_t k = 0; k < local.values.extent(0); ++k)
    if (local.values(k) != 0.0)
      held[local.graph.entries(k)] = 1;
  std::vector<int> spikeOf(rowOfColumn.size(), -1);
  std::vector<GO> coupled;
  for (std::size_t c = 0; c < rowOfColumn.size(); ++c)
    if (rowOfColumn[c] < 0 && held[c]) {
      spikeOf[c] = static_cast<int>(coupled.size());
      coupled.push_back(columns.getGlobalElement(static_cast<LO>(c)));
    }
  const auto interface = unionOverRanks(*comm_, coupled);
  m_ = static_cast<int>(interface.size());
  if (m_ == 0)
    return;  // no rank couples to another: block Jacobi is exact
  for (GO g : coupled)
    spikeColumn_.push_back(static_cast<int>(
        std::lower_bound(interface.begin(), interface.end(), g) - interface.begin()));

  // S = D^-1 U on this rank's rows.
  const int spikes = static_cast<int>(coupled.size());
  spikes_.assign(static_cast<std::size_t>(n_) * spikes, 0.0);
  for (int i = 0; i < n_; ++i)
    for (auto k = local.graph.row_map(i); k < local.graph.row_map(i + 1); ++k)
      if (const int s = spikeOf[local.graph.entries(k)]; s >= 0)
        spikes_[static_cast<std::size_t>(s) * n_ + i] += local.values(k);
  if (n_ > 0 && spikes > 0)
    solve(spikes_.data(), spikes);

  // I + V^T S: each interface row is filled by its owner, the sum brings all to every rank.
  const Map& rows = *A.getRowMap();
  for (int t = 0; t < m_; ++t)
    if (const LO r = rows.getLocalElement(interface[t]); r != Teuchos::OrdinalTraits<LO>::invalid())
      interfaceRows_.emplace_back(r, t);
  const std::size_t mm = static_cast<std::size_t>(m_) * m_;
  std::vector<double> own(mm, 0.0);
  for (const auto& [r, t] : interfaceRows_)
    for (int s = 0; s < spikes; ++s)
      own[t + static_cast<std::size_t>(m_) * spikeColumn_[s]] +=
          spikes_[static_cast<std::size_t>(s) * n_ + r];
  capacitance_.resize(mm);
  Teuchos::reduceAll<int, double>(*comm_, Teuchos::REDUCE_SUM, static_cast<int>(mm), own.data(),
                                  capacitance_.data());
  for (int t = 0; t < m_; ++t)
    capacitance_[t + static_cast<std::size_t>(m_) * t] += 1.0;
  pivots_.resize(m_);
  int info = 0;
  Teuchos::LAPACK<int, double>().GETRF(m_, m_, capacitance_.data(), m_, pivots_.data(), &info);
  if (info > 0)  // the same matrix on every rank: every rank throws
    throw NumericalError("the banded LU's coupling across ranks is singular at interface unknown " +
                         std::to_string(interface[info - 1]) + ", so is the matrix");
  if (info < 0)
    throw std::logic_error("dgetrf: argument " + std::to_string(-info) + " is invalid");
}

void RankCoupling::correct(MultiVector& Y) const {
  if (m_ == 0)
    return;
  const int vectors = static_cast<int>(Y.getNumVectors());
  const std::size_t size = static_cast<std::size_t>(m_) * vectors;
  std::vector<double> own(size, 0.0), h(size);
  for (int v = 0; v < vectors; ++v) {
    const auto y = Y.getData(v);
    for (const auto& [r, t] : interfaceRows_)
      own[t + static_cast<std::size_t>(m_) * v] = y[r];
  }
  Teuchos::reduceAll<int, double>(*comm_, Teuchos::REDUCE_SUM, static_cast<int>(size), own.data(),
                                  h.data());
  int info = 0;
  Teuchos::LAPACK<int, double>().GETRS('N', m_, vectors, capacitance_.data(), m_, pivots_.data(),
                                       h.data(), m_, &info);
  if (info != 0)
    throw std::logic_error("dgetrs: argument " + std::to_string(-info) + " is invalid");
  const int spikes = static_cast<int>(spikeColumn_.size());
  if (n_ == 0 || spikes == 0)
    return;
  std::vector<double> hOfSpikes(spikes);
  for (int v = 0; v < vectors; ++v) {
    for (int s = 0; s < spikes; ++s)
      hOfSpikes[s] = h[spikeColumn_[s] + static_cast<std::size_t>(m_) * v];
    auto y = Y.getDataNonConst(v);
    Teuchos::BLAS<int, double>().GEMV(Teuchos::NO_TRANS, n_, spikes, -1.0, spikes_.data(), n_,
                                      hOfSpikes.data(), 1, 1.0, y.getRawPtr(), 1);
  }
}

}  // namespace impm

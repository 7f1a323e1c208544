#include "core/Repartition.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Zoltan2_BasicVectorAdapter.hpp>
#include <Zoltan2_PartitioningProblem.hpp>

#include <algorithm>
#include <array>
#include <map>
#include <numeric>

#include "core/Collective.hpp"

namespace impm {

namespace {

using ZoltanTypes = Zoltan2::BasicUserTypes<double, int, GlobalId>;
using CellAdapter = Zoltan2::BasicVectorAdapter<ZoltanTypes>;

}  // namespace

double particleImbalance(std::size_t localParticles, const Comm& comm) {
  const double mine = static_cast<double>(localParticles);
  double total = 0.0, most = 0.0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, mine, Teuchos::outArg(total));
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, mine, Teuchos::outArg(most));
  return total > 0 ? most * comm.getSize() / total : 1.0;
}

template <int Dim>
CellPartition<Dim> repartitionCells(const Decomposition<Dim>& current,
                                    const ParticleSet<Dim>& particles,
                                    const Teuchos::RCP<const Comm>& comm) {
  const auto& grid = current.grid();
  // The weight of each of this rank's cells: the particles in it.
  const std::vector<GlobalId> cells = current.ownedCells(comm->getRank());
  std::map<GlobalId, std::size_t> index;
  for (std::size_t k = 0; k < cells.size(); ++k)
    index[cells[k]] = k;
  std::vector<double> weight(cells.size(), 0.0);
  const auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), particles.x);
  for (std::size_t p = 0; p < particles.size(); ++p) {
    int idx[Dim];
    for (int d = 0; d < Dim; ++d)
      idx[d] = grid.cellAlong(d, x(p, d));
    const auto found = index.find(grid.cellId(idx));
    if (found != index.end())
      weight[found->second] += 1.0;
  }
  // Their centres, the coordinates multi-jagged cuts.
  std::array<std::vector<double>, Dim> centre;
  for (GlobalId cell : cells) {
    int idx[Dim];
    grid.cellIndex(cell, idx);
    for (int d = 0; d < Dim; ++d)
      centre[d].push_back(grid.origin[d] + (idx[d] + 0.5) * grid.spacing[d]);
  }
  const double* y = Dim > 1 ? centre[Dim > 1 ? 1 : 0].data() : nullptr;
  const double* z = Dim > 2 ? centre[Dim > 2 ? 2 : 0].data() : nullptr;
  CellAdapter adapter(static_cast<int>(cells.size()), cells.data(), centre[0].data(), y, z, 1, 1, 1,
                      true, weight.data(), 1);
  Teuchos::ParameterList params;
  params.set("algorithm", "multijagged");
  params.set("num_global_parts", comm->getSize());
  params.set("imbalance_tolerance", 1.02);
  Zoltan2::PartitioningProblem<CellAdapter> problem(&adapter, &params, comm);
  problem.solve();
  const int* parts = problem.getSolution().getPartListView();
  // The particles each rank will hold.
  std::vector<double> load(comm->getSize(), 0.0), total(comm->getSize(), 0.0);
  for (std::size_t k = 0; k < cells.size(); ++k)
    load[parts[k]] += weight[k];
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, comm->getSize(), load.data(), total.data());
  const double sum = std::accumulate(total.begin(), total.end(), 0.0);
  const double imbalance =
      sum > 0 ? *std::max_element(total.begin(), total.end()) * comm->getSize() / sum : 1.0;
  // Every rank learns every cell's new owner.
  std::vector<double> mine;
  for (std::size_t k = 0; k < cells.size(); ++k)
    mine.insert(mine.end(), {static_cast<double>(cells[k]), static_cast<double>(parts[k])});
  const auto all = gatherToAll(*comm, mine);
  std::vector<int> owners(static_cast<std::size_t>(grid.numCells()), -1);
  for (std::size_t k = 0; k + 1 < all.size(); k += 2)
    owners[static_cast<std::size_t>(all[k])] = static_cast<int>(all[k + 1]);
  return {Decomposition<Dim>(grid, comm->getSize(), std::move(owners)), imbalance};
}

template CellPartition<1> repartitionCells<1>(const Decomposition<1>&, const ParticleSet<1>&,
                                              const Teuchos::RCP<const Comm>&);
template CellPartition<2> repartitionCells<2>(const Decomposition<2>&, const ParticleSet<2>&,
                                              const Teuchos::RCP<const Comm>&);
template CellPartition<3> repartitionCells<3>(const Decomposition<3>&, const ParticleSet<3>&,
                                              const Teuchos::RCP<const Comm>&);

}  // namespace impm

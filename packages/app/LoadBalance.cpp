#include "app/LoadBalance.hpp"

#include <algorithm>
#include <iomanip>
#include <ostream>

#include "core/Migration.hpp"
#include "core/Parameters.hpp"
#include "core/Repartition.hpp"
#include "core/Timers.hpp"

namespace impm {

Teuchos::ParameterList loadBalanceValidParameters() {
  Teuchos::ParameterList valid;
  declareBool(valid, "Repartition", true,
              "Repartition the grid's cells among the ranks, weighted by the particles they "
              "hold, when the particles crowd onto some ranks (updated Lagrangian runs on "
              "several ranks); the particles follow their cells");
  declareDouble(valid, "Imbalance Threshold", 1.2,
                "Repartition after a step when the rank with the most particles holds more than "
                "this times the mean number per rank",
                Bounds::atLeast(1.0));
  return valid;
}

template <int Dim>
LoadBalance<Dim>::LoadBalance(const Teuchos::ParameterList& params, bool active)
    : active_(active && params.get<bool>("Repartition")),
      threshold_(params.get<double>("Imbalance Threshold")) {}

template <int Dim>
bool LoadBalance<Dim>::afterStep(int step, NodeOwnership<Dim>& ownership,
                                 ParticleSet<Dim>& particles, GridFields<Dim>& gridFields,
                                 std::ostream* log) {
  if (!active_)
    return false;
  const Comm& comm = *ownership.comm();
  const double before = particleImbalance(particles.size(), comm);
  // A partition of whole cells may not reach the threshold (a column one cell wide on more
  // ranks than it has rows of particles): then only a worse imbalance than it left triggers
  // another.
  if (before <= std::max(threshold_, 1.05 * afterLast_))
    return false;
  IMPM_TIMER("repartition");
  auto partition = repartitionCells(ownership.decomposition(), particles, ownership.comm());
  if (partition.imbalance >= before) {  // whole cells cannot do better: keep the cells where
    afterLast_ = before;                // they are, and wait for a worse imbalance
    return false;
  }
  ownership.repartition(std::move(partition.decomposition));
  migrateToOwners(particles, ownership.decomposition(), comm);
  gridFields.redistribute(ownership.nodeMap());
  afterLast_ = particleImbalance(particles.size(), comm);
  ++repartitions_;
  if (log)
    *log << "  step " << step << ": repartitioned the cells, particle imbalance (most on a rank "
         << "over the mean) " << std::fixed << std::setprecision(2) << before << " -> "
         << afterLast_ << std::defaultfloat << "\n";
  return true;
}

template class LoadBalance<1>;
template class LoadBalance<2>;
template class LoadBalance<3>;

}  // namespace impm

#pragma once
// Keeps the ranks' work even while particles move (updated Lagrangian runs on several ranks):
// after a step, when the rank with the most particles holds more than Load Balance/Imbalance
// Threshold times the mean, the cells are repartitioned by their particle counts
// (core/Repartition), the particles migrate to their cells' new ranks, and the nodal output
// fields move to the new node map.  The log says when, and the imbalance before and after.

#include <Teuchos_ParameterList.hpp>

#include <iosfwd>
#include <vector>

#include "app/GridFields.hpp"
#include "core/NodeOwnership.hpp"
#include "core/ParticleSet.hpp"

namespace impm {

Teuchos::ParameterList loadBalanceValidParameters();

template <int Dim>
class LoadBalance {
 public:
  // `params`: the validated Load Balance sublist; `active`: the run moves its particles
  // (updated Lagrangian) on more than one rank.
  LoadBalance(const Teuchos::ParameterList& params, bool active);

  // After step `step`: repartitions when the imbalance is past the threshold (and has grown
  // since the last repartition, which a partition of whole cells cannot always cure).
  // Collective.  Returns whether it did.
  bool afterStep(int step, NodeOwnership<Dim>& ownership, ParticleSet<Dim>& particles,
                 GridFields<Dim>& gridFields, std::ostream* log);

  int repartitions() const { return repartitions_; }
  // The imbalance right after the last repartition (1 before any), which a checkpoint keeps.
  double imbalanceAfterRepartition() const { return afterLast_; }
  void restore(double imbalanceAfterRepartition) { afterLast_ = imbalanceAfterRepartition; }

 private:
  bool active_;
  double threshold_;
  double afterLast_ = 1.0;  // the imbalance right after the last repartition
  int repartitions_ = 0;
};

}  // namespace impm

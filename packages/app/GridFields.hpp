#pragma once
// The nodal fields written to the grid's Exodus file, on every grid node (zero where a node
// carries no unknown): the accumulated displacement (static runs and fixed grids), and the
// velocity and lumped mass of the last step (dynamic runs).

#include <string>
#include <vector>

#include "core/NodeOwnership.hpp"
#include "solver/StepperSetup.hpp"

namespace impm {

template <int Dim>
class GridFields {
 public:
  GridFields(const NodeOwnership<Dim>& ownership, bool displacement, bool dynamic);

  const std::vector<std::string>& names() const { return names_; }
  // The values at the last step.  The velocity and mass change wholesale every step and are
  // read only at outputs and checkpoints: they are copied in when read.
  const MultiVector& values() const;
  MultiVector& values();  // restored at a restart
  void update(const StepGrid<Dim>& step);
  // The values move to `nodeMap` (the ownership's after a repartition).  Collective.
  void redistribute(const Teuchos::RCP<const Map>& nodeMap);

 private:
  // Per local unknown of `dofs`: its node's local row in values_ times Dim plus its
  // component, or -1 for an extra unknown; kept while the maps are the same.
  const std::vector<LO>& outputSlots(const Teuchos::RCP<const Map>& dofs,
                                     const DofMap<Dim>& dofMap);

  // Copies the last step's velocity and mass into values_, once.
  void copyPending() const;

  int displacement_ = -1, velocity_ = -1, mass_ = -1;  // first column of each, or -1
  std::vector<std::string> names_;
  mutable MultiVector values_;
  // The last step's velocity and mass (on slotsDofs_) while not yet copied into values_.
  mutable Teuchos::RCP<const Vector> pendingVelocity_, pendingMass_;
  Teuchos::RCP<const Map> slotsDofs_, slotsNodes_;  // the maps slots_ was made for
  std::vector<LO> slots_;
};

}  // namespace impm

#include "app/GridFields.hpp"

#include "core/Axes.hpp"

namespace impm {

namespace {

std::vector<std::string> fieldNames(bool displacement, bool dynamic, int dim) {
  std::vector<std::string> names;
  if (displacement)
    for (int d = 0; d < dim; ++d)
      names.push_back(std::string("displacement") + referenceAxisName(d));
  if (dynamic) {
    for (int d = 0; d < dim; ++d)
      names.push_back(std::string("velocity") + referenceAxisName(d));
    names.push_back("mass");
  }
  return names;
}

}  // namespace

template <int Dim>
GridFields<Dim>::GridFields(const NodeOwnership<Dim>& ownership, bool displacement, bool dynamic)
    : names_(fieldNames(displacement, dynamic, Dim)),
      values_(ownership.nodeMap(), std::max<std::size_t>(names_.size(), 1)) {
  int column = 0;
  if (displacement)
    displacement_ = column, column += Dim;
  if (dynamic)
    velocity_ = column, mass_ = column + Dim;
}

template <int Dim>
const std::vector<LO>& GridFields<Dim>::outputSlots(const Teuchos::RCP<const Map>& dofs,
                                                    const DofMap<Dim>& dofMap) {
  if (slotsDofs_ == dofs && slotsNodes_ == values_.getMap())
    return slots_;
  const auto& nodes = *values_.getMap();
  slots_.assign(dofs->getNodeNumElements(), -1);
  for (std::size_t k = 0; k < slots_.size(); ++k) {
    const GO dof = dofs->getGlobalElement(static_cast<LO>(k));
    if (dofMap.isExtraDof(dof))
      continue;
    const LO node = nodes.getLocalElement(DofMap<Dim>::nodeOf(dof));
    if (node == Teuchos::OrdinalTraits<LO>::invalid())
      throw std::logic_error("grid output: an unknown's node is not on its rank");
    slots_[k] = node * Dim + DofMap<Dim>::componentOf(dof);
  }
  slotsDofs_ = dofs, slotsNodes_ = values_.getMap();
  return slots_;
}

template <int Dim>
void GridFields<Dim>::update(const StepGrid<Dim>& step) {
  // Every step (the displacement accumulates): local views and local indices found once
  // per set of unknowns, not Tpetra's per-value global accessors, which cost as much as a
  // residual evaluation.
  if (step.du.getMap() != slotsDofs_)
    copyPending();  // the step before's, on its own unknowns
  const auto& slots = outputSlots(step.du.getMap(), step.system.dofs());
  if (displacement_ >= 0) {
    auto out = values_.getLocalViewHost(Tpetra::Access::ReadWrite);
    auto du = step.du.getData();
    for (decltype(du.size()) k = 0; k < du.size(); ++k)
      if (slots[k] >= 0)
        out(slots[k] / Dim, displacement_ + slots[k] % Dim) += du[k];
  }
  if (velocity_ >= 0 && step.velocity)
    pendingVelocity_ = step.velocity, pendingMass_ = step.mass;
}

template <int Dim>
void GridFields<Dim>::copyPending() const {
  if (!pendingVelocity_)
    return;
  auto out = values_.getLocalViewHost(Tpetra::Access::ReadWrite);
  for (std::size_t n = 0; n < out.extent(0); ++n)
    for (int c = velocity_; c <= mass_; ++c)
      out(n, c) = 0.0;
  auto v = pendingVelocity_->getData(), m = pendingMass_->getData();
  for (decltype(v.size()) k = 0; k < v.size(); ++k) {
    if (slots_[k] < 0)
      continue;
    const LO node = slots_[k] / Dim;
    const int d = slots_[k] % Dim;
    out(node, velocity_ + d) = v[k];
    if (d == 0)
      out(node, mass_) = m[k];
  }
  pendingVelocity_ = Teuchos::null, pendingMass_ = Teuchos::null;
}

template <int Dim>
const MultiVector& GridFields<Dim>::values() const {
  copyPending();
  return values_;
}

template <int Dim>
MultiVector& GridFields<Dim>::values() {
  copyPending();
  return values_;
}

template <int Dim>
void GridFields<Dim>::redistribute(const Teuchos::RCP<const Map>& nodeMap) {
  copyPending();
  MultiVector moved(nodeMap, values_.getNumVectors());
  moved.doImport(values_, Import(values_.getMap(), nodeMap), Tpetra::INSERT);
  values_.swap(moved);
}

template class GridFields<1>;
template class GridFields<2>;
template class GridFields<3>;

}  // namespace impm

#pragma once
// Boundary conditions from the deck's Boundary Conditions/<name> sublists.

#include <Teuchos_ParameterList.hpp>

#include <memory>
#include <vector>

#include "app/Bodies.hpp"
#include "assembly/Kinematics.hpp"
#include "solver/Contribution.hpp"

namespace impm {

Teuchos::ParameterList boundaryConditionValidParameters();

template <int Dim>
std::vector<std::shared_ptr<Contribution<Dim>>> createBoundaryConditions(
    const Teuchos::ParameterList& deck, const Bodies<Dim>& bodies, const GridGeometry<Dim>& grid,
    Method method, Kinematics kinematics);

}  // namespace impm

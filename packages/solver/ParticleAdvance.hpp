#pragma once
// Grid to particles after a converged step: the particles take the step's deformation (trial
// F and its stress) and displacement from the grid (eq. 1.23), as every stepper does.  The
// materials are left at their trial state at du, which the step's commit makes theirs.

#include "solver/GridSystem.hpp"

namespace impm {

template <int Dim>
void advanceParticles(GridSystem<Dim>& system, const Vector& du, Kinematics kinematics,
                      ParticleSet<Dim>& particles);

}  // namespace impm

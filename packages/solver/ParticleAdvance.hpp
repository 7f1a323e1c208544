#pragma once
// Grid to particles after a converged step: the particles take the step's deformation (trial
// F and its stress) and displacement from the grid (eq. 1.23), as every stepper does.  The
// materials are left at their trial state at du, which the step's commit makes theirs.

#include "solver/GridSystem.hpp"

namespace impm {

// The step's deformation and displacement: advanceParticles is deformParticles and
// moveParticles together (one import of du).
template <int Dim>
void advanceParticles(GridSystem<Dim>& system, const Vector& du, Kinematics kinematics,
                      ParticleSet<Dim>& particles);

// F, the Cauchy stress, and where the particles move with the grid their domains and volumes.
template <int Dim>
void deformParticles(GridSystem<Dim>& system, const Vector& du, Kinematics kinematics,
                     ParticleSet<Dim>& particles);

// u_p and x_p (and the tracked domain corners) by the grid increment du, which may sum
// several steps' on a fixed grid (the weights do not change there).
template <int Dim>
void moveParticles(const GridSystem<Dim>& system, const Vector& du, Kinematics kinematics,
                   ParticleSet<Dim>& particles);

}  // namespace impm

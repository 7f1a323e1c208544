#pragma once
// The history file's columns and rows: one row per step with time, end forces, energies
// (kinetic, strain, their sum, the external work and the balance KE + SE - W), the total
// momentum, and per body the centre-of-mass velocity and the particles' extent, per
// support (Dirichlet condition) its reaction, then the Newton and linear iteration counts.

#include <string>
#include <vector>

#include "core/ParticleSet.hpp"
#include "core/TpetraTypes.hpp"
#include "solver/StepperSetup.hpp"

namespace impm {

template <int Dim>
class History {
 public:
  // supportNames: the conditions whose reactions are recorded (column reaction_<name>, spaces
  // as '_'), in the order of StepRecord::supportForces.
  History(const std::vector<std::string>& bodyNames, const std::vector<std::string>& supportNames);

  const std::vector<std::string>& columns() const { return columns_; }
  // The row of a step.  Collective (sums over every rank's particles).
  std::vector<double> row(const StepRecord& record, double F0, double FL,
                          const ParticleSet<Dim>& particles, const Comm& comm) const;

 private:
  std::size_t bodies_, supports_;
  std::vector<std::string> columns_;
};

}  // namespace impm

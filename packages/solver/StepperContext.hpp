#pragma once
// Everything a time stepper works on: the grid and its ownership, the discretisation, the
// particles with their materials, the extra terms, the Newton solver, and how to set the
// particles' external forces at a given time.

#include <functional>
#include <memory>
#include <vector>

#include "assembly/Kinematics.hpp"
#include "basis/Method.hpp"
#include "solver/Contribution.hpp"
#include "solver/NewtonSolver.hpp"

namespace impm {

template <int Dim>
struct StepperContext {
  const NodeOwnership<Dim>& ownership;
  Method method;
  Kinematics kinematics;
  ParticleSet<Dim>& particles;
  const std::vector<std::shared_ptr<Material<Dim>>>& materials;
  const std::vector<std::shared_ptr<Contribution<Dim>>>& contributions;
  const NewtonSolver& newton;
  // Sets particles.force (the full external force at `time`).
  std::function<void(double time)> applyLoads;
};

// What a stepper reports after every accepted step.
struct StepRecord {
  int step = 0;
  double time = 0.0;
  double loadFactor = 1.0;
  int attempts = 1;   // 1 + number of cutbacks before this step was accepted
  bool last = false;  // the run ends with this step
  NewtonReport newton;
};

}  // namespace impm

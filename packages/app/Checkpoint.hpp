#pragma once
// Checkpoints of a run and restarts from them (impm --restart).  A checkpoint holds every
// particle field whose FieldSpec says so, at full precision and sorted by id (so it does not
// depend on the number of ranks), the stepper's state (step, time, load factor, step size
// after cutbacks, the fixed grid's nodal u, v, a), the boundary conditions' state, the
// grid's output fields, how many Exodus steps were written, and what identifies the problem
// (dimension, method, kinematics, time integration, grid, materials, bodies, particle count
// and a fingerprint of the particles' ids and reference positions).  A restart refuses a
// checkpoint of another problem; run controls (final time, output, solver settings) may
// change.  Files: <prefix>_checkpoint_<step>.nc, the newest also as <prefix>_checkpoint.nc
// (a symbolic link), the oldest removed beyond Output/Checkpoints Kept.

#include <Teuchos_ParameterList.hpp>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/Decomposition.hpp"
#include "core/ParticleSet.hpp"
#include "solver/Contribution.hpp"
#include "solver/StepperSetup.hpp"

namespace impm {

// What a checkpoint must share with the deck it restarts.
struct RunIdentity {
  std::vector<long long> cells;
  std::vector<double> origin, spacing;
  std::string method, kinematics, timeIntegration, materials, bodies;
  long long particles = 0;
  long long fingerprint = 0;
  // The deck's parameters that define the problem, "path = value" a line, sorted: all but the
  // run controls a restart may change (physicsParameters()).
  std::string physics;
  // Whether a restart may continue with other physics than its checkpoint's (each change is
  // printed); not written.
  bool allowPhysicsChange = false;
};

// The lines of RunIdentity::physics for `deck`: every parameter but Output/..., Solver/...,
// Verification/..., Load Balance/... and Time Integration/Final Time.
std::string physicsParameters(const Teuchos::ParameterList& deck);

// The identity of `deck` with its grid and its particles as created.  Collective.
template <int Dim>
RunIdentity runIdentity(const Teuchos::ParameterList& deck, const GridGeometry<Dim>& grid,
                        const ParticleSet<Dim>& particles, GlobalId totalParticles,
                        const Comm& comm);

// The decomposition of a run whose cells were repartitioned: it holds for that number of
// ranks only (a restart on another number starts from blocks).
struct Partition {
  int ranks = 0;
  std::vector<int> cellOwners;             // empty: blocks
  double imbalanceAfterRepartition = 1.0;  // LoadBalance's memory of the last repartition
};

// The partition a checkpoint holds (blocks for checkpoints written before partitions were).
// Collective.
Partition readPartition(const std::string& path, const Comm& comm);

// Everything a checkpoint saves besides the identity.
template <int Dim>
struct RunState {
  StepperState stepper;
  std::vector<std::vector<double>> contributions;  // each contribution's state()
  int exodusSteps = 0;                             // time steps in the Exodus files
  Partition partition;                             // the ranks' cells (app/LoadBalance)
  std::vector<std::string> physicsChanges;         // read only: "Path: old -> new", allowed changes
};

// Writes `path` atomically.  Collective (rank 0 writes; the fields are gathered to it).
template <int Dim>
void writeCheckpoint(const std::string& path, const RunIdentity& identity,
                     const ParticleSet<Dim>& particles, GlobalId totalParticles,
                     const RunState<Dim>& state, const MultiVector& gridFields);

// Reads `path` into `particles` (whose material variables are declared; each rank keeps the
// particles whose position lies in its cells: x for updated, X for total Lagrangian runs, in
// id order) and `gridFields`; returns the rest.  Throws FileError (on every rank) when the
// file is missing, unreadable, corrupted, of a newer format or of another problem.
// Collective.
template <int Dim>
RunState<Dim> readCheckpoint(const std::string& path, const RunIdentity& identity,
                             const Decomposition<Dim>& decomposition, bool byReference,
                             ParticleSet<Dim>& particles, MultiVector& gridFields,
                             const Teuchos::RCP<const Comm>& comm);

// The checkpoints of one run: when they are due, their names, the newest link, how many
// are kept.
class CheckpointSeries {
 public:
  CheckpointSeries(const Teuchos::ParameterList& output, const std::string& directory,
                   const std::string& prefix);
  // Output/Checkpoint Every > 0, and the step is a multiple of it or the last.
  bool due(int step, bool last) const;
  std::string pathOf(int step) const;
  // After `path` (step) was written: the newest link, and the oldest files removed.  Rank 0.
  void written(int step);

 private:
  int every_, kept_;
  std::string directory_, prefix_;
  std::vector<int> steps_;
};

}  // namespace impm

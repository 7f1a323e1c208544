#pragma once
// A run: the validated deck turned into grid, integration points, materials, boundary
// conditions and solvers, then stepped, written and checked.  Everything that can be
// wrong with the deck is found by the constructor, before any file is written.

#include <Teuchos_ParameterList.hpp>

#include <memory>
#include <string>
#include <vector>

#include "app/Bodies.hpp"
#include "app/Checkpoint.hpp"
#include "app/GridFields.hpp"
#include "app/History.hpp"
#include "app/LoadBalance.hpp"
#include "app/Output.hpp"
#include "app/ProgressLog.hpp"
#include "app/Verification.hpp"
#include "assembly/Kinematics.hpp"
#include "solver/Contribution.hpp"
#include "solver/NewtonSolver.hpp"
#include "solver/Stepper.hpp"

namespace impm {

class RobinEnd;

template <int Dim>
class Simulation {
 public:
  // Collective; throws InputError (on every rank) when the deck is inconsistent.  With a
  // checkpoint file the run continues from it; FileError when it cannot.
  // `allowPhysicsChange`: a restart may go on with other values of the parameters that define
  // the problem than its checkpoint's (app/Checkpoint.hpp).
  Simulation(const Teuchos::ParameterList& deck, const std::string& deckFile,
             const std::string& outputDirectory, const Teuchos::RCP<const Comm>& comm,
             const std::string& restart = "", Verbosity verbosity = Verbosity::normal,
             bool allowPhysicsChange = false);
  ~Simulation();

  // Runs to the end; returns the failed verification checks (empty: all passed).  Throws
  // NumericalError when the computation cannot go on, RunStopped after a stop signal
  // (core/StopRequest.hpp) once the checkpoint of the last accepted step is written.
  std::vector<std::string> run();

  const ParticleSet<Dim>& particles() const { return particles_; }

 private:
  void setUp(const Teuchos::ParameterList& deck);
  void restart(const std::string& file);
  // A checkpoint's partition of the cells, when it was made on this many ranks.
  void restorePartition(const std::string& file);
  void balanceAfterStep(int step);
  void addDerivedFields();
  // Collective; rank 0 then updates the series (the newest link, the oldest removed).
  void writeCheckpoint(CheckpointSeries& series, int step, Stepper<Dim>& stepper,
                       const Output<Dim>& output) const;
  // The output files (continued on a restart) with the initial state written (not on one).
  std::unique_ptr<Output<Dim>> startOutput(const History<Dim>& history);
  std::unique_ptr<Stepper<Dim>> makeStepper();
  // The ghost penalty's gamma of this run's steps (Discretization/Ghost Penalty).
  double ghostPenalty() const;
  // Prints a warning the first time a particle domain passes kDistortionWarning
  // (assembly/DomainDistortion.hpp).  Collective.
  void warnOfDistortedDomains(int step);
  void checkExplicitTimeStep() const;
  OperatorKind operatorKind() const;
  std::vector<double> reactions() const;
  // The particles' external forces at `time`, on every rank; NumericalError when a load
  // formula is not finite at a particle.  Collective.
  void applyLoads(double time);
  // Whether the loads or a boundary condition read the particles' positions in every step.
  bool particlesReadEveryStep() const;
  void printHeader() const;
  void printProgress(const StepRecord& record, const std::vector<double>& F) const;
  double progressFraction(double time, double loadFactor) const;
  std::vector<std::string> finish(double finalTime, const std::vector<std::string>& files,
                                  const LayoutCache<Dim>& layouts) const;

  Teuchos::RCP<const Comm> comm_;
  Teuchos::ParameterList deck_;
  std::string deckFile_, outputDirectory_, prefix_;
  std::unique_ptr<NodeOwnership<Dim>> ownership_;
  Method method_;
  Kinematics kinematics_;
  FBar fbar_ = FBar::none;
  std::vector<std::string> materialNames_;
  Materials<Dim> materials_;
  std::unique_ptr<Bodies<Dim>> bodies_;
  ParticleSet<Dim> particles_;
  GlobalId totalParticles_ = 0;
  std::vector<std::shared_ptr<Contribution<Dim>>> conditions_;
  std::shared_ptr<RobinEnd> left_, right_;  // the ends whose forces are F0 and FL
  std::unique_ptr<NewtonSolver> newton_;
  Verbosity verbosity_;
  bool distortionWarned_ = false;          // warnOfDistortedDomains()
  std::unique_ptr<ProgressLog> progress_;  // made when run() starts
  std::unique_ptr<Verification> verification_;
  std::unique_ptr<GridFields<Dim>> gridFields_;
  std::unique_ptr<LoadBalance<Dim>> loadBalance_;
  RunIdentity identity_;                     // what a checkpoint of this run must match
  std::unique_ptr<RunState<Dim>> restored_;  // the checkpoint's state, on a restart
  std::unique_ptr<Stepper<Dim>> stepper_;    // made with the first step's system
};

}  // namespace impm

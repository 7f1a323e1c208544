#include "app/Simulation.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>

#include "app/BoundaryConditions.hpp"
#include "bc/RobinEnd.hpp"
#include "core/Collective.hpp"
#include "core/Errors.hpp"
#include "core/Timers.hpp"
#include "io/InputDeck.hpp"
#include "material/MaterialFactory.hpp"
#include "solver/GridSystem.hpp"
#include "solver/QuasiStaticStepper.hpp"

namespace impm {

namespace {

template <int Dim>
GridGeometry<Dim> readGrid(const Teuchos::ParameterList& p) {
  const auto& cells = p.get<Teuchos::Array<int>>("Cells");
  const auto& length = p.get<Teuchos::Array<double>>("Length");
  const auto& origin = p.get<Teuchos::Array<double>>("Origin");
  if (static_cast<int>(length.size()) != Dim)
    throw InputError("Grid/Length", "has " + std::to_string(length.size()) +
                                        " entries but Grid/Cells has " + std::to_string(Dim));
  if (!origin.empty() && static_cast<int>(origin.size()) != Dim)
    throw InputError("Grid/Origin", "has " + std::to_string(origin.size()) +
                                        " entries but Grid/Cells has " + std::to_string(Dim));
  std::array<double, Dim> o, l;
  std::array<int, Dim> n;
  for (int d = 0; d < Dim; ++d)
    o[d] = origin.empty() ? 0.0 : origin[d], l[d] = length[d], n[d] = cells[d];
  return makeGridGeometry<Dim>(o, l, n);
}

Kinematics readKinematics(const Teuchos::ParameterList& p, Method method) {
  const auto& k = p.get<std::string>("Kinematics");
  if (k == "auto")
    return method == Method::fem ? Kinematics::totalLagrangian : Kinematics::updatedLagrangian;
  if (k == "updated Lagrangian" && method == Method::fem)
    throw InputError("Discretization/Kinematics",
                     "fem integrates on the grid as a fixed mesh: use total Lagrangian");
  return k == "total Lagrangian" ? Kinematics::totalLagrangian : Kinematics::updatedLagrangian;
}

std::string format(double v) {
  std::ostringstream s;
  s << std::setprecision(8) << v;
  return s.str();
}

}  // namespace

template <int Dim>
Simulation<Dim>::Simulation(const Teuchos::ParameterList& deck, const std::string& deckFile,
                            const std::string& outputDirectory,
                            const Teuchos::RCP<const Comm>& comm)
    : comm_(comm), deck_(deck), deckFile_(deckFile), outputDirectory_(outputDirectory) {
  // Local checks first, agreed on by every rank; then the collective set-up.
  collectively(*comm_, [&] { setUp(deck_); });
  collectively(*comm_, [&] {
    newton_ = std::make_unique<NewtonSolver>(deck_.sublist("Solver"), comm_);
    newton_->setLog(deck_.sublist("Solver").get<bool>("Print Iterations") ? &std::cout : nullptr,
                    "    ");
  });
  const GlobalId local = particles_.size();
  Teuchos::reduceAll(*comm_, Teuchos::REDUCE_SUM, local, Teuchos::outArg(totalParticles_));
  // A dry build of the first step's system: particles outside the grid, or boundary
  // conditions on nodes no integration point reaches, are deck errors.
  try {
    GridSystem<Dim>(*ownership_, method_, kinematics_, particles_, materials_, conditions_, 0.0,
                    0.0);
  } catch (const NumericalError& e) {
    throw InputError("Bodies", e.what());
  }
}

template <int Dim>
Simulation<Dim>::~Simulation() = default;

template <int Dim>
void Simulation<Dim>::setUp(const Teuchos::ParameterList& deck) {
  const auto& output = deck.sublist("Output");
  prefix_ = output.get<std::string>("Prefix").empty() ? deckStem(deckFile_)
                                                      : output.get<std::string>("Prefix");
  if (outputDirectory_.empty())
    outputDirectory_ = output.get<std::string>("Directory");
  const auto grid = readGrid<Dim>(deck.sublist("Grid"));
  ownership_ = std::make_unique<NodeOwnership<Dim>>(grid, comm_);
  method_ = parseMethod(deck.sublist("Discretization").get<std::string>("Method"));
  kinematics_ = readKinematics(deck.sublist("Discretization"), method_);

  const auto& materials = deck.sublist("Materials");
  for (auto it = materials.begin(); it != materials.end(); ++it) {
    materialNames_.push_back(materials.name(it));
    materials_.push_back(
        createMaterial<Dim>(materials.name(it), materials.sublist(materials.name(it))));
  }
  bodies_ = std::make_unique<Bodies<Dim>>(deck, materialNames_, grid);
  particles_ =
      bodies_->createParticles(method_, ownership_->decomposition(), comm_->getRank(), materials_);
  for (std::size_t m = 0; m < materials_.size(); ++m)
    materials_[m]->initialize(particles_, static_cast<int>(m));
  conditions_ = createBoundaryConditions<Dim>(deck, *bodies_, kinematics_);
  for (const auto& c : conditions_) {
    auto robin = std::dynamic_pointer_cast<RobinEnd>(c);
    if (!robin)
      continue;
    if (robin->isLeft() && !left_)
      left_ = robin;
    if (!robin->isLeft() && !right_)
      right_ = robin;
  }
  verification_ = std::make_unique<Verification>(deck.sublist("Verification"));
}

template <int Dim>
std::vector<double> Simulation<Dim>::reactions() const {
  const double none = std::numeric_limits<double>::quiet_NaN();
  return {left_ ? left_->force() : none, right_ ? right_->force() : none};
}

template <int Dim>
std::vector<std::string> Simulation<Dim>::run() {
  const bool root = comm_->getRank() == 0;
  const auto& grid = ownership_->grid();
  if (root)
    std::cout << "impm: " << deckFile_ << ": " << Dim << "-D, " << methodName(method_) << ", "
              << (kinematics_ == Kinematics::totalLagrangian ? "total" : "updated")
              << " Lagrangian, " << totalParticles_ << " integration points, " << grid.cells[0]
              << " cells, " << comm_->getSize() << " rank" << (comm_->getSize() > 1 ? "s" : "")
              << "\n";

  std::unique_ptr<Output<Dim>> output;
  collectively(*comm_, [&] {
    output = std::make_unique<Output<Dim>>(
        deck_.sublist("Output"), outputDirectory_, prefix_, *ownership_, particles_,
        totalParticles_,
        std::vector<std::string>{"step", "time", "load_factor", "F0", "FL", "newton_iterations",
                                 "linear_iterations", "residual", "attempts"},
        std::vector<std::string>{"F0", "FL"});
  });
  MultiVector gridDisplacement(ownership_->nodeMap(), Dim);
  collectively(*comm_,
               [&] { output->writeFields(0.0, particles_, gridDisplacement, reactions()); });

  StepperContext<Dim> context{
      *ownership_, method_,
      kinematics_, particles_,
      materials_,  conditions_,
      *newton_,    [this](double t) { bodies_->applyLoads(particles_, t); }};
  const auto& timeIntegration = deck_.sublist("Time Integration");
  QuasiStaticStepper<Dim> stepper(timeIntegration, context);
  const int steps = timeIntegration.get<int>("Load Steps");
  double finalTime = 0.0;
  stepper.run([&](const StepRecord& r, const GridSystem<Dim>& system, const Vector& du) {
    // Accumulate the grid displacement for output (active nodes only).
    auto values = du.getData();
    const auto& map = *du.getMap();
    for (decltype(values.size()) k = 0; k < values.size(); ++k) {
      const GO dof = map.getGlobalElement(static_cast<LO>(k));
      if (system.dofs().isExtraDof(dof))
        continue;
      gridDisplacement.sumIntoGlobalValue(dof / Dim, dof % Dim, values[k]);
    }
    const auto F = reactions();
    output->appendHistory({double(r.step), r.time, r.loadFactor, F[0], F[1],
                           double(r.newton.iterations()), double(r.newton.totalLinearIterations()),
                           r.newton.residualNorms.back(), double(r.attempts)});
    if (root)
      std::cout << "  step " << r.step << "/" << steps << "  load " << std::fixed
                << std::setprecision(3) << r.loadFactor << std::defaultfloat << "  newton "
                << r.newton.iterations() << "  linear " << r.newton.totalLinearIterations()
                << "  |R| " << std::scientific << std::setprecision(2)
                << r.newton.residualNorms.back() << std::defaultfloat << "  F0 " << format(F[0])
                << "  FL " << format(F[1]) << "\n";
    if (output->due(r.step) || r.last) {
      IMPM_TIMER("output");
      collectively(*comm_, [&] { output->writeFields(r.time, particles_, gridDisplacement, F); });
    }
    finalTime = r.time;
  });

  const auto F = reactions();
  const auto result = verification_->check<Dim>(particles_, comm_, finalTime, F[0], F[1]);
  if (root) {
    for (const auto& line : result.report)
      std::cout << "  verification: " << line << "\n";
    const std::string path = outputDirectory_ + "/" + prefix_ + "_verification.csv";
    writeCsvTable(path, {"cells", "points", "rms_error", "max_error", "F0", "FL"},
                  {{double(grid.cells[0])},
                   {double(totalParticles_)},
                   {result.hasExact ? result.rmsError : std::nan("")},
                   {result.hasExact ? result.maxError : std::nan("")},
                   {F[0]},
                   {F[1]}});
    std::cout << "impm: wrote";
    for (const auto& f : output->files())
      std::cout << " " << f;
    std::cout << " " << path << "\n";
  }
  if (deck_.sublist("Output").get<bool>("Timers"))
    Teuchos::TimeMonitor::summarize(comm_.ptr(), std::cout, false, true, false, Teuchos::Union,
                                    "impm: ");
  return result.failures;
}

template class Simulation<1>;

}  // namespace impm

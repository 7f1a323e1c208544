#pragma once
// A term of the grid system other than the particle integrals: the boundary-force unknowns
// of Robin ends (primer eq. 1.18-1.19), Dirichlet rows, inertia.  Contributions are defined
// here and implemented above (bc), so the solver depends on no particular condition.
//
// Per step the grid system calls prepare() (before the unknowns are numbered), then
// evaluates residuals and Jacobians as Newton asks, then commit() with the converged
// solution.  Indices given to a contribution are local to the overlap map.

#include <utility>
#include <vector>

#include "basis/ParticleGridMap.hpp"
#include "core/DofMap.hpp"
#include "core/ParticleSet.hpp"

namespace impm {

using HostValues = Kokkos::View<const double**, Kokkos::LayoutLeft, Kokkos::HostSpace>;
using HostValuesMutable = Kokkos::View<double**, Kokkos::LayoutLeft, Kokkos::HostSpace>;

// What a contribution sees of the current step.
template <int Dim>
struct ContributionContext {
  const GridGeometry<Dim>& grid;
  const ParticleSet<Dim>& particles;
  const ParticleGridMap<Dim>& map;
  const Kokkos::View<LO*>& entryDofs;  // overlap-map index of each map entry's node
  const DofMap<Dim>& dofs;
  double time;        // time at the end of the step
  double loadFactor;  // fraction of the loads applied at the end of the step (static ramps)
  int firstExtra;     // global index of this contribution's first extra unknown
};

template <int Dim>
class Contribution {
 public:
  virtual ~Contribution() = default;

  // Before numbering: extra unknowns (the same list on every rank) and the grid nodes this
  // rank's entries reach.
  virtual void prepare(const NodeOwnership<Dim>& /*ownership*/, std::vector<ExtraDof>& /*extras*/,
                       std::vector<GlobalId>& /*touched*/) {}
  // Matrix entries (global row, global column) this rank adds beyond the particle couplings.
  virtual void couplings(const ContributionContext<Dim>& /*ctx*/,
                         std::vector<std::pair<GO, GO>>& /*out*/) const {}
  // Prescribed unknowns this rank owns, as (global index, value of the increment): their
  // rows of the system become du_i = value (Dirichlet conditions).  They may depend on the
  // context's layout, time and load factor and on what commit() changes (restore() runs
  // before any system is built), and on nothing else: a system asks once per time and
  // commit, not at every evaluation.
  virtual void constraints(const ContributionContext<Dim>& /*ctx*/,
                           std::vector<std::pair<GO, double>>& /*out*/) const {}
  // Initial guess of the extra unknowns this rank owns (x is the owned vector).
  virtual void initialGuess(const ContributionContext<Dim>& /*ctx*/, Vector& /*x*/) const {}
  // Adds to the residual / Jacobian; x and f are overlap-local.
  virtual void addResidual(const ContributionContext<Dim>& /*ctx*/, const HostValues& /*x*/,
                           const HostValuesMutable& /*f*/) const {}
  virtual void addJacobian(const ContributionContext<Dim>& /*ctx*/, const HostValues& /*x*/,
                           FECrsMatrix& /*J*/) const {}
  // The step converged with solution x (overlap-local).  Collective.
  virtual void commit(const ContributionContext<Dim>& /*ctx*/, const HostValues& /*x*/) {}
  // Work done on the bodies so far (for the energy balance); the same on every rank.
  virtual double work() const { return 0.0; }
  // What the contribution carries from one step to the next (an end force and position, the
  // time of the last commit), for checkpoints; the same on every rank.  restore() puts back
  // what state() gave.
  virtual std::vector<double> state() const { return {}; }
  virtual void restore(const std::vector<double>& /*state*/) {}
  // The name under which the force on this contribution's constrained unknowns (a support's
  // reaction) is reported; empty: none reported.
  virtual std::string reactionName() const { return ""; }
  // A converged step's force on those unknowns: r is the owned residual f_int - f_ext (+ M a)
  // at the solution, which the support balances.  Returns the total (the same on every rank)
  // and keeps what the work of the step needs until commit().  Collective; called only for
  // contributions with a reactionName(), before commit().
  virtual double reaction(const ContributionContext<Dim>& /*ctx*/, const HostValues& /*r*/) {
    return 0.0;
  }
  // Whether any call reads the particles' displacement or position (an edge traction follows
  // the particles' faces).  A fixed grid's explicit steps let the particles' motion wait
  // only when none does (solver/DynamicStepper.hpp); a condition that reads the grid alone
  // says so.
  virtual bool readsParticleMotion() const { return true; }
};

}  // namespace impm

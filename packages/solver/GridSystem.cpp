#include "solver/GridSystem.hpp"

#include <cstring>

#include "assembly/Energy.hpp"
#include "assembly/Forces.hpp"
#include "basis/CornerWeights.hpp"
#include "core/Axes.hpp"
#include "core/Collective.hpp"
#include "core/Diagnostics.hpp"
#include "core/Errors.hpp"
#include "core/Timers.hpp"
#include "solver/RigidBodyModes.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <type_traits>

namespace impm {

namespace {

// The map, built on every rank; a particle outside the grid on one rank stops all of them.
// With total-Lagrangian kinematics the map is built at the reference positions and domains.
template <int Dim>
ParticleGridMap<Dim> buildMapCollectively(const NodeOwnership<Dim>& ownership, Method method,
                                          Kinematics kinematics,
                                          const ParticleSet<Dim>& particles) {
  ParticleSet<Dim> at = particles;  // views: a shallow copy
  if (kinematics == Kinematics::totalLagrangian) {
    at.x = particles.X, at.domain = particles.domain0;
    if (particles.has(kCornersField))
      at.replaceValues(kCornersField, particles.values(kReferenceCornersField));
  }
  IMPM_TIMER("particle-grid map");
  ParticleGridMap<Dim> map;
  collectively(*ownership.comm(),
               [&] { map = buildParticleGridMap(method, ownership.grid(), at); });
  return map;
}

// F-bar's groups, by the cell of the map's positions; each must be this rank's cell.
template <int Dim>
CellGroups<> cellGroupsOf(FBar fbar, const NodeOwnership<Dim>& ownership, Kinematics kinematics,
                          const ParticleSet<Dim>& particles) {
  if (fbar == FBar::none)
    return {};
  const auto& y = kinematics == Kinematics::totalLagrangian ? particles.X : particles.x;
  auto groups = groupByCell<Dim>(ownership.grid(), y);
  const auto& decomposition = ownership.decomposition();
  const int rank = ownership.comm()->getRank();
  collectively(*ownership.comm(), [&] {
    for (const GlobalId cell : groups.cells)
      if (decomposition.ownerOfCell(cell) != rank)
        throw std::logic_error("F-bar: a particle of cell " + std::to_string(cell) +
                               " is on rank " + std::to_string(rank) + ", not on the cell's owner");
  });
  return groups;
}

// The F-bar table of the compatible F as a view of tensors (the same row-major storage).
template <int Dim>
typename ParticleSet<Dim>::Tensors compatibleF(const ParticleSet<Dim>& particles) {
  using Tensors = typename ParticleSet<Dim>::Tensors;
  static_assert(std::is_same_v<typename Tensors::array_layout, Kokkos::LayoutRight>,
                "compatibleF: the tensor views must be row-major to alias the field's table");
  const auto& table = particles.values(kCompatibleFField);
  return Tensors(table.data(), table.extent(0));
}

template <class View>
HostValues constHost(const View& v) {
  return HostValues(v.data(), v.extent(0), v.extent(1));
}

}  // namespace

template <int Dim>
GridSystem<Dim>::GridSystem(const NodeOwnership<Dim>& ownership, Method method,
                            Kinematics kinematics, const ParticleSet<Dim>& particles,
                            const Materials<Dim>& materials, const Contributions& contributions,
                            double time, double loadFactor, StepWorkspace<Dim>* workspace,
                            LayoutCache<Dim>* layouts, NodeCoupling coupling, FBar fbar,
                            double ghostPenalty)
    : grid_(ownership.grid()),
      kinematics_(kinematics),
      fbar_(fbar),
      particles_(particles),
      materials_(materials),
      contributions_(contributions),
      time_(time),
      loadFactor_(loadFactor),
      particleGridMap_(buildMapCollectively(ownership, method, kinematics, particles)),
      cellGroups_(cellGroupsOf(fbar, ownership, kinematics, particles)),
      ghostPenalty_(coupling == NodeCoupling::shared ? ghostPenalty : 0.0),
      ghostFaces_(ghostPenalty_ > 0.0 ? ghostFaces(ownership, particleGridMap_) : GhostFaces{}),
      laidOut_(layoutOf(
          LayoutInputs<Dim>{ownership, particleGridMap_, particles, contributions, time, loadFactor,
                            coupling, fbar == FBar::none ? nullptr : &cellGroups_,
                            ghostPenalty_ > 0.0 ? &ghostFaces_ : nullptr},
          layouts ? *layouts : ownLayouts_)),
      layout_(*laidOut_.layout),
      firstExtra_(layout_.firstExtra),
      dofs_(layout_.dofs),
      entryDofs_(laidOut_.entryDofs),
      graph_(layout_.graph),
      importer_(layout_.importer),
      work_((workspace ? *workspace : ownWorkspace_)
                .arrays(particles.size(), kinematics, fbar != FBar::none)),
      trial_(particles, materials) {
  loaded_ = carriesForces<Dim>(particles_);
  if (ghostPenalty_ > 0.0)
    ghostDofs_ = ghostFaceDofs<Dim>(ghostFaces_, grid_, *dofs_.overlapMap(),
                                    ghostPenalty_ * lawModulus(Modulus::young));
}

template <int Dim>
double GridSystem<Dim>::lawModulus(Modulus which) const {
  auto& cached = lawModulus_[which == Modulus::young];
  if (!cached) {
    double modulus = 0.0;
    for (std::size_t m = 0; m < materials_.size(); ++m)
      modulus = std::max(modulus, maxModulus(particles_, materials_, static_cast<int>(m),
                                             *dofs_.ownedMap()->getComm(), which));
    cached = modulus > 0 ? modulus : 1.0;
  }
  return *cached;
}

template <int Dim>
double GridSystem<Dim>::constraintScale() const {
  // Prescribed rows get the size of a stiffness diagonal (modulus h^(Dim-2)), so that they
  // neither dominate nor vanish in the preconditioner.  Made on first use: the laws'
  // modulus is a pass over the particles that systems without prescribed unknowns (every
  // step of an explicit bar with Robin ends) do not need.
  if (!constraintScale_) {
    double h = grid_.spacing[0];
    for (int d = 1; d < Dim; ++d)
      h = std::min(h, grid_.spacing[d]);
    constraintScale_ = lawModulus() * std::pow(h, Dim - 2);
  }
  return *constraintScale_;
}

template <int Dim>
Teuchos::RCP<MultiVector> GridSystem<Dim>::nearNullSpace() const {
  return rigidBodyModes(grid_, dofs_);
}

template <int Dim>
const std::vector<std::pair<LO, double>>& GridSystem<Dim>::constrainedRows() const {
  if (!constrainedRows_)
    constrainedRows_ = prescribedRows();
  return *constrainedRows_;
}

template <int Dim>
std::vector<std::pair<LO, double>> GridSystem<Dim>::prescribedRows() const {
  std::vector<std::pair<GO, double>> global;
  for (std::size_t c = 0; c < contributions_.size(); ++c)
    contributions_[c]->constraints(context(static_cast<int>(c)), global);
  for (GO padding : dofs_.paddingDofs())
    global.emplace_back(padding, 0.0);
  // A retired node (solver/SystemLayout.hpp) is fixed at zero, also where a boundary
  // condition holds it: a built layout would not have it at all.
  const auto& retired = laidOut_.retired;
  std::vector<std::pair<LO, double>> rows;
  const auto& owned = *dofs_.ownedMap();
  for (const auto& [gid, value] : global) {
    const LO lid = owned.getLocalElement(gid);
    if (lid != Teuchos::OrdinalTraits<LO>::invalid() &&
        !std::binary_search(retired.begin(), retired.end(), lid))
      rows.emplace_back(lid, value);
  }
  for (const LO lid : retired)
    rows.emplace_back(lid, 0.0);
  return rows;
}

template <int Dim>
bool GridSystem<Dim>::anyConstrained(bool mine) const {
  if (!anyConstrained_) {
    int any = 0;
    Teuchos::reduceAll(*dofs_.ownedMap()->getComm(), Teuchos::REDUCE_MAX, mine ? 1 : 0,
                       Teuchos::outArg(any));
    anyConstrained_ = any == 1;
  }
  return *anyConstrained_;
}

template <int Dim>
void GridSystem<Dim>::applyConstraints(const Vector& x, Vector* residual,
                                       CrsMatrix* jacobian) const {
  const auto& rows = constrainedRows();
  if (!anyConstrained(!rows.empty()))
    return;  // no prescribed unknown on any rank
  const double scale = constraintScale();
  if (residual) {
    auto r = residual->getLocalViewHost(Tpetra::Access::ReadWrite);
    auto xv = x.getLocalViewHost(Tpetra::Access::ReadOnly);
    for (const auto& [lid, value] : rows)
      r(lid, 0) = scale * (xv(lid, 0) - value);
  }
  if (jacobian)
    eliminateConstrained(rows, *jacobian);
}

template <int Dim>
void GridSystem<Dim>::eliminateConstrained(const std::vector<std::pair<LO, double>>& rows,
                                           CrsMatrix& J) const {
  // Mark the prescribed unknowns on the rows and bring the marks to the columns (collective:
  // a rank without prescribed rows may hold their columns).
  Vector marks(J.getRowMap());
  {
    auto m = marks.getLocalViewHost(Tpetra::Access::ReadWrite);
    for (const auto& row : rows)
      m(row.first, 0) = 1.0;
  }
  const Vector atColumns = onColumns(J, marks);
  auto K = J.getLocalMatrixDevice();
  const auto rowMap = J.getRowMap()->getLocalMap(), colMap = J.getColMap()->getLocalMap();
  const auto fixedRow = marks.getLocalViewDevice(Tpetra::Access::ReadOnly);
  const auto fixedCol = atColumns.getLocalViewDevice(Tpetra::Access::ReadOnly);
  const double scale = constraintScale();
  Kokkos::parallel_for(
      "impm::eliminateConstrained", RangePolicy<DefaultExecSpace>(0, K.numRows()),
      KOKKOS_LAMBDA(const LO r) {
        auto row = K.row(r);
        if (fixedRow(r, 0) != 0.0) {
          const LO diagonal = colMap.getLocalElement(rowMap.getGlobalElement(r));
          for (LO k = 0; k < row.length; ++k)
            row.value(k) = row.colidx(k) == diagonal ? scale : 0.0;
          return;
        }
        for (LO k = 0; k < row.length; ++k)
          if (fixedCol(row.colidx(k), 0) != 0.0)
            row.value(k) = 0.0;
      });
}

template <int Dim>
void GridSystem<Dim>::imposeConstraints(Vector& x) const {
  auto values = x.getLocalViewHost(Tpetra::Access::ReadWrite);
  for (const auto& [lid, value] : constrainedRows())
    values(lid, 0) = value;
}

template <int Dim>
ContributionContext<Dim> GridSystem<Dim>::context(int contribution) const {
  return ContributionContext<Dim>{grid_, particles_, particleGridMap_, entryDofs_,
                                  dofs_, time_,      loadFactor_,      firstExtra_[contribution]};
}

template <int Dim>
Teuchos::RCP<CrsMatrix> GridSystem<Dim>::createJacobian() const {
  return Teuchos::rcp(new FECrsMatrix(graph_));
}

template <int Dim>
void GridSystem<Dim>::setTime(double time, double loadFactor) {
  time_ = time, loadFactor_ = loadFactor;
  constrainedRows_.reset();
  loaded_ = carriesForces<Dim>(particles_);
}

template <int Dim>
Teuchos::RCP<const Vector> GridSystem<Dim>::toOverlap(const Vector& owned) const {
  auto overlap = Teuchos::rcp(new Vector(dofs_.overlapMap(), false));  // every entry imported
  overlap->doImport(owned, *importer_, Tpetra::INSERT);
  return overlap;
}

template <int Dim>
Teuchos::RCP<Vector> GridSystem<Dim>::initialGuess() const {
  auto x = Teuchos::rcp(new Vector(dofs_.ownedMap()));
  for (std::size_t c = 0; c < contributions_.size(); ++c)
    contributions_[c]->initialGuess(context(static_cast<int>(c)), *x);
  imposeConstraints(*x);
  return x;
}

template <int Dim>
bool GridSystem<Dim>::stressIsAt(const Vector& x) const {
  bool same = false;
  if (stressX_ && stressX_->getMap()->isSameAs(*x.getMap())) {
    auto now = x.getLocalViewHost(Tpetra::Access::ReadOnly);
    auto then = stressX_->getLocalViewHost(Tpetra::Access::ReadOnly);
    same = std::memcmp(now.data(), then.data(), now.extent(0) * sizeof(double)) == 0;
  }
  // Every rank takes the same branch: the evaluation is collective.
  return onEveryRank(same, *dofs_.ownedMap()->getComm());
}

template <int Dim>
Teuchos::RCP<const Vector> GridSystem<Dim>::updateStress(const Vector& x) {
  // Newton asks for the residual and then the Jacobian at one iterate, and the particle
  // update for the stress at the converged one: the laws are evaluated once per iterate.
  if (stressIsAt(x))
    return stressXOverlap_;
  IMPM_TIMER("stress update");
  atStepStart_ = false;
  stressX_ = Teuchos::null;  // set again once the evaluation has succeeded
  auto xo = toOverlap(x);
  {
    auto du = xo->getLocalViewDevice(Tpetra::Access::ReadOnly);
    if (fbar_ == FBar::none) {
      trialDeformationGradient<Dim>(kinematics_, particleGridMap_, entryDofs_, du, particles_.F,
                                    work_.F);
    } else {  // F^std from the compatible F, then theta F^std
      const bool total = kinematics_ == Kinematics::totalLagrangian;
      trialDeformationGradient<Dim>(kinematics_, particleGridMap_, entryDofs_, du,
                                    total ? compatibleF(particles_) : particles_.F, work_.F,
                                    work_.g);
      averageDilatation<Dim>(cellGroups_, particles_, work_.g, work_.theta, work_.omega);
      scaleByTheta<Dim>(work_.theta, work_.F);
    }
  }
  collectively(*dofs_.ownedMap()->getComm(), [&] {
    for (std::size_t m = 0; m < materials_.size(); ++m) {
      const int k = static_cast<int>(m);
      materials_[m]->firstPiola(evaluationOf(particles_, materials_, k, work_.F, trial_.of(k)),
                                work_.P, work_.A);
    }
    requireFiniteStress();
  });
  stressRelativeToStepStart<Dim>(kinematics_, particles_.F, work_.P, work_.A, work_.Pn, work_.An);
  stressX_ = Teuchos::rcp(new Vector(x, Teuchos::Copy));
  stressXOverlap_ = xo;
  return xo;
}

template <int Dim>
void GridSystem<Dim>::commitMaterials() {
  commitMaterialState(particles_, materials_, trial_);
  stressX_ = Teuchos::null;  // the stress at any x is now relative to the new state
}

template <int Dim>
void GridSystem<Dim>::requireFiniteStress() const {
  const long stress = firstNonFiniteRow(work_.P, particles_.size());
  // A frozen internal force (explicit steps) assembles no tangent: nothing to check.
  const long tangent = frozen_ ? -1 : firstNonFiniteRow(work_.A, particles_.size());
  if (stress < 0 && tangent < 0)
    return;
  const long p = stress >= 0 ? stress : tangent;
  auto material = Kokkos::create_mirror_view_and_copy(
      Kokkos::HostSpace(), Kokkos::subview(particles_.material, Kokkos::make_pair(p, p + 1)));
  auto F = Kokkos::create_mirror_view_and_copy(
      Kokkos::HostSpace(),
      Kokkos::subview(work_.F, Kokkos::make_pair(p, p + 1), Kokkos::ALL(), Kokkos::ALL()));
  std::ostringstream msg;
  msg << "the " << (stress >= 0 ? "stress" : "tangent") << " of " << particleLabel(particles_, p)
      << " (material '" << materials_[material(0)]->name() << "') is not finite at F = (";
  for (int a = 0; a < Dim; ++a)
    for (int b = 0; b < Dim; ++b)
      msg << (a + b ? ", " : "") << F(0, a, b);
  throw NumericalError(msg.str() + ")");
}

template <int Dim>
std::string GridSystem<Dim>::unknownLabel(GO dof) const {
  if (dofs_.isExtraDof(dof))
    return "extra unknown " + std::to_string(dof) + " (a boundary force)";
  if (Dim == 1)
    return nodeLabel(grid_, dof);
  return nodeLabel(grid_, DofMap<Dim>::nodeOf(dof)) + ", component " +
         axisName(DofMap<Dim>::componentOf(dof));
}

template <int Dim>
void GridSystem<Dim>::requireFinite(const Vector& v, const std::string& what) const {
  collectively(*v.getMap()->getComm(), [&] {
    const long k =
        firstNonFiniteRow(v.getLocalViewDevice(Tpetra::Access::ReadOnly), v.getLocalLength());
    if (k >= 0)
      throw NumericalError(what + " is not finite at " +
                           unknownLabel(v.getMap()->getGlobalElement(static_cast<LO>(k))));
  });
}

template <int Dim>
void GridSystem<Dim>::requireFinite(const CrsMatrix& J) const {
  collectively(*J.getRowMap()->getComm(), [&] {
    const auto K = J.getLocalMatrixDevice();
    const long k = firstNonFiniteRow(K.values, K.values.extent(0));
    if (k < 0)
      return;
    auto rowMap = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), K.graph.row_map);
    const LO row = static_cast<LO>(std::upper_bound(rowMap.data(), rowMap.data() + rowMap.extent(0),
                                                    static_cast<std::size_t>(k)) -
                                   rowMap.data()) -
                   1;
    throw NumericalError("the Jacobian is not finite in the row of " +
                         unknownLabel(J.getRowMap()->getGlobalElement(row)));
  });
}

template <int Dim>
typename GridSystem<Dim>::Trial GridSystem<Dim>::trialState(const Vector& x) {
  auto xo = updateStress(x);
  return {work_.F, work_.P, work_.g, xo};
}

template <int Dim>
Teuchos::RCP<Vector> GridSystem<Dim>::acceleration(const Vector& xOverlap) const {
  if (inertia_.c0 == 0.0 || inertia_.mass == MassType::lumped)
    return Teuchos::null;
  auto a = Teuchos::rcp(new Vector(dofs_.overlapMap(), false));  // overwritten whole
  a->update(inertia_.c0, xOverlap, -1.0, *inertiaOverlap_, 0.0);
  return a;
}

template <int Dim>
void GridSystem<Dim>::assembleResidual(const Vector& xOverlap, Vector& residual) const {
  IMPM_TIMER("residual");
  const auto a = acceleration(xOverlap);
  FEMultiVector f(dofs_.ownedMap(), importer_, 1);
  f.beginAssembly();
  // A failure one rank finds (a loaded face that no integration point reaches) stops every
  // rank here: alone, it left the others waiting in endAssembly for ever.
  collectively(*dofs_.ownedMap()->getComm(), [&] { addLocalResidual(a, xOverlap, f); });
  f.endAssembly();
  Tpetra::deep_copy(residual, *f.getVector(0));
  if (inertia_.c0 != 0.0 && inertia_.mass == MassType::lumped)
    addLumpedInertia(xOverlap, residual);
}

template <int Dim>
void GridSystem<Dim>::addLocalResidual(const Teuchos::RCP<const Vector>& a, const Vector& xOverlap,
                                       FEMultiVector& f) const {
  auto xHost = xOverlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  {
    auto local = f.getLocalViewDevice(Tpetra::Access::ReadWrite);
    addInternalForce<Dim>(particleGridMap_, entryDofs_, particles_, work_.Pn, local);
    if (loaded_)
      addExternalForce<Dim>(particleGridMap_, entryDofs_, particles_.force, loadFactor_, local);
    if (a)
      addConsistentInertiaForce<Dim>(particleGridMap_, entryDofs_, particles_.mass,
                                     a->getLocalViewDevice(Tpetra::Access::ReadOnly), local);
    if (!frozen_ && ghostDofs_.size() > 0)
      addGhostForce<Dim>(ghostDofs_, xOverlap.getLocalViewDevice(Tpetra::Access::ReadOnly), local);
  }
  {
    auto local = f.getLocalViewHost(Tpetra::Access::ReadWrite);
    const HostValuesMutable fHost(local.data(), local.extent(0), local.extent(1));
    for (std::size_t c = 0; c < contributions_.size(); ++c)
      contributions_[c]->addResidual(context(static_cast<int>(c)), constHost(xHost), fHost);
  }
}

template <int Dim>
void GridSystem<Dim>::addLumpedInertia(const Vector& xOverlap, Vector& residual) const {
  // The owned rows come first on the overlap map (core/DofMap.hpp).
  const auto x = xOverlap.getLocalViewDevice(Tpetra::Access::ReadOnly);
  const auto r = inertia_.r->getLocalViewDevice(Tpetra::Access::ReadOnly);
  const auto m = lumpedMass()->getLocalViewDevice(Tpetra::Access::ReadOnly);
  const auto f = residual.getLocalViewDevice(Tpetra::Access::ReadWrite);
  const double c0 = inertia_.c0;
  Kokkos::parallel_for(
      "impm::lumpedInertia", RangePolicy<DefaultExecSpace>(0, f.extent(0)),
      KOKKOS_LAMBDA(const LO k) { f(k, 0) += m(k, 0) * (c0 * x(k, 0) - r(k, 0)); });
}

template <int Dim>
void GridSystem<Dim>::stressAtStepStart() {
  if (atStepStart_)
    return;
  if (committedStart_) {  // the particles' committed Cauchy stress is the laws' at du = 0
    const auto rows = Kokkos::make_pair(std::size_t(0), particles_.size());
    Kokkos::deep_copy(work_.Pn,
                      Kokkos::subview(particles_.stress, rows, Kokkos::ALL(), Kokkos::ALL()));
  } else {
    updateStress(Vector(unknownMap()));  // the laws evaluated at du = 0
  }
  atStepStart_ = true;
}

template <int Dim>
void GridSystem<Dim>::evaluate(const Vector& x, Vector* residual, CrsMatrix* jacobian) {
  // NaN or inf stops the step here, named, before a Krylov solver or an output meets it.
  requireFinite(x, "the Newton iterate (the last linear solve's result)");
  Teuchos::RCP<const Vector> xo;
  if (!frozen_) {
    xo = updateStress(x);
  } else {
    stressAtStepStart();
    xo = toOverlap(x);
  }
  if (residual) {
    assembleResidual(*xo, *residual);
    applyConstraints(x, residual, nullptr);
    requireFinite(*residual, "the residual");
  }
  if (jacobian) {
    IMPM_TIMER("Jacobian");
    if (layout_.coupling == NodeCoupling::self && !hasDiagonalJacobian())
      throw std::logic_error("a Jacobian with node couplings asked of a diagonal graph");
    auto& J = dynamic_cast<FECrsMatrix&>(*jacobian);
    J.beginAssembly();
    J.setAllToScalar(0.0);
    collectively(*dofs_.ownedMap()->getComm(), [&] { addLocalJacobian(*xo, J); });  // as above
    J.endAssembly();
    applyConstraints(x, nullptr, &J);
    requireFinite(J);
  }
}

template <int Dim>
void GridSystem<Dim>::addLocalJacobian(const Vector& xOverlap, FECrsMatrix& J) const {
  if (!frozen_) {
    addTangent<Dim>(particleGridMap_, entryDofs_, particles_, work_.An, J.getLocalMatrixDevice(),
                    work_.theta);
    if (fbar_ != FBar::none)
      addFBarTangent<Dim>(particleGridMap_, entryDofs_, particles_, cellGroups_, work_.g,
                          work_.theta, work_.omega, work_.An, J.getLocalMatrixDevice());
    if (ghostDofs_.size() > 0)
      addGhostTangent<Dim>(ghostDofs_, J.getLocalMatrixDevice());
  }
  if (inertia_.c0 != 0.0 && inertia_.mass == MassType::lumped)
    addDiagonal(inertia_.c0, lumpedMass()->getLocalViewDevice(Tpetra::Access::ReadOnly),
                J.getLocalMatrixDevice());  // the owned rows, first on the overlap map
  else if (inertia_.c0 != 0.0)
    addConsistentMassMatrix<Dim>(inertia_.c0, particleGridMap_, entryDofs_, particles_.mass,
                                 J.getLocalMatrixDevice());
  auto xHost = xOverlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  for (std::size_t c = 0; c < contributions_.size(); ++c)
    contributions_[c]->addJacobian(context(static_cast<int>(c)), constHost(xHost), J);
}

template <int Dim>
double GridSystem<Dim>::roundOffScale() const {
  if (frozen_ || stressX_.is_null())
    return 0.0;  // no stress of this system's own at an iterate
  FEMultiVector s(dofs_.ownedMap(), importer_, 1);
  s.beginAssembly();
  const bool total = kinematics_ == Kinematics::totalLagrangian;
  addStressRoundOffScale<Dim>(particleGridMap_, entryDofs_, particles_, work_.An,
                              total ? work_.F : typename ParticleSet<Dim>::Tensors(),
                              s.getLocalViewDevice(Tpetra::Access::ReadWrite));
  s.endAssembly();
  Vector owned(dofs_.ownedMap());
  Tpetra::deep_copy(owned, *s.getVector(0));
  // Prescribed rows hold scale (x - value), not forces.
  {
    auto values = owned.getLocalViewHost(Tpetra::Access::ReadWrite);
    for (const auto& [lid, value] : constrainedRows())
      values(lid, 0) = 0.0;
  }
  return owned.norm2();
}

template <int Dim>
bool GridSystem<Dim>::isLinear() const {
  if (frozen_)
    return true;
  for (const auto& m : materials_)
    if (!m->isLinear())
      return false;
  // F-bar's theta is nonlinear in du, except in 1-D, where F-bar's F is jbar itself.
  return Dim == 1 || (kinematics_ == Kinematics::totalLagrangian && fbar_ == FBar::none);
}

template <int Dim>
bool GridSystem<Dim>::hasDiagonalJacobian() const {
  return frozen_ && inertia_.mass == MassType::lumped && inertia_.r;
}

template <int Dim>
const DiagonalElimination& GridSystem<Dim>::explicitElimination() {
  if (!explicitElimination_ || explicitC0_ != inertia_.c0) {
    auto J = createJacobian();
    evaluate(Vector(unknownMap()), nullptr, J.get());  // affine: any du will do
    explicitElimination_ = std::make_unique<DiagonalElimination>(*J, nodalMask(), extraDofs());
    explicitC0_ = inertia_.c0;
  }
  return *explicitElimination_;
}

template <int Dim>
std::vector<GO> GridSystem<Dim>::extraDofs() const {
  std::vector<GO> out;
  for (int k = 0; k < dofs_.numExtras(); ++k)
    out.push_back(dofs_.extraDof(k));
  return out;
}

template <int Dim>
void GridSystem<Dim>::setInertia(const Inertia& inertia) {
  inertia_ = inertia;
  inertiaOverlap_ = inertia.mass == MassType::consistent ? toOverlap(*inertia.r) : Teuchos::null;
}

template <int Dim>
Teuchos::RCP<Vector> GridSystem<Dim>::particleToGrid(
    const typename ParticleSet<Dim>::Vectors& q) const {
  FEMultiVector f(dofs_.ownedMap(), importer_, 1);
  f.beginAssembly();
  impm::particleToGrid<Dim>(particleGridMap_, entryDofs_, particles_.mass, q,
                            f.getLocalViewDevice(Tpetra::Access::ReadWrite));
  f.endAssembly();
  auto result = Teuchos::rcp(new Vector(dofs_.ownedMap()));
  Tpetra::deep_copy(*result, *f.getVector(0));
  return result;
}

template <int Dim>
Teuchos::RCP<const Vector> GridSystem<Dim>::lumpedMass() const {
  if (lumpedMass_)
    return lumpedMass_;
  FEMultiVector m(dofs_.ownedMap(), importer_, 1);
  m.beginAssembly();
  addLumpedMass<Dim>(particleGridMap_, entryDofs_, particles_.mass,
                     m.getLocalViewDevice(Tpetra::Access::ReadWrite));
  m.endAssembly();
  auto result = Teuchos::rcp(new Vector(dofs_.ownedMap()));
  Tpetra::deep_copy(*result, *m.getVector(0));
  lumpedMass_ = result;
  return result;
}

template <int Dim>
Teuchos::RCP<CrsMatrix> GridSystem<Dim>::consistentMassMatrix() const {
  auto M = Teuchos::rcp(new FECrsMatrix(graph_));
  M->beginAssembly();
  M->setAllToScalar(0.0);
  addConsistentMassMatrix<Dim>(1.0, particleGridMap_, entryDofs_, particles_.mass,
                               M->getLocalMatrixDevice());
  const auto& owned = *dofs_.ownedMap();
  const double one = 1.0;
  for (std::size_t k = 0; k < owned.getNodeNumElements(); ++k) {
    const GO gid = owned.getGlobalElement(static_cast<LO>(k));
    if (dofs_.isExtraDof(gid))
      M->sumIntoGlobalValues(gid, 1, &one, &gid);
  }
  M->endAssembly();
  return M;
}

template <int Dim>
std::vector<double> GridSystem<Dim>::supportForces(const Vector& x) {
  const bool any = std::any_of(contributions_.begin(), contributions_.end(),
                               [](const auto& c) { return !c->reactionName().empty(); });
  if (!any)
    return {};  // nothing to report: no extra residual evaluation
  // The stress is that of the last evaluation, Newton's at x: not evaluated again.
  Vector r(unknownMap());
  assembleResidual(*toOverlap(x), r);
  auto values = r.getLocalViewHost(Tpetra::Access::ReadOnly);
  std::vector<double> forces;
  for (std::size_t c = 0; c < contributions_.size(); ++c)
    if (!contributions_[c]->reactionName().empty())
      forces.push_back(
          contributions_[c]->reaction(context(static_cast<int>(c)), constHost(values)));
  return forces;
}

template <int Dim>
void GridSystem<Dim>::commit(const Vector& x) {
  // The stress of the particle update at x, when it is there, is the next step's start
  // (startStressKept()).
  const bool stressAtX = stressIsAt(x);
  Teuchos::RCP<const Vector> xo = stressXOverlap_;
  if (!stressAtX)
    xo = toOverlap(x);
  auto xHost = xo->getLocalViewHost(Tpetra::Access::ReadOnly);
  for (std::size_t c = 0; c < contributions_.size(); ++c)
    contributions_[c]->commit(context(static_cast<int>(c)), constHost(xHost));
  constrainedRows_.reset();  // the increments are now from the committed state
  commitMaterials();
  // An explicit run on a fixed grid then skips one of its two law evaluations per step.
  atStepStart_ = stressAtX && startStressKept();
}

template <int Dim>
bool GridSystem<Dim>::startStressKept() const {
  return kinematics_ == Kinematics::totalLagrangian && !hasTrialState();
}

template <int Dim>
void GridSystem<Dim>::startFromCommittedStress() {
  committedStart_ = kinematics_ == Kinematics::updatedLagrangian && !hasTrialState();
}

template <int Dim>
bool GridSystem<Dim>::hasTrialState() const {
  for (std::size_t m = 0; m < materials_.size(); ++m)
    if (!trial_.of(static_cast<int>(m)).empty())
      return true;
  return false;
}

template class GridSystem<1>;
template class GridSystem<2>;
template class GridSystem<3>;

}  // namespace impm

#include "solver/GridSystem.hpp"

#include "assembly/EntryDofs.hpp"
#include "assembly/Forces.hpp"
#include "assembly/Graph.hpp"

namespace impm {

namespace {

// Numbers the unknowns: the nodes the particles touch, plus the contributions' extras.
template <int Dim>
DofMap<Dim> numberUnknowns(const NodeOwnership<Dim>& ownership, const ParticleGridMap<Dim>& map,
                           const std::vector<std::shared_ptr<Contribution<Dim>>>& contributions,
                           std::vector<int>& firstExtra) {
  auto node = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), map.node);
  std::vector<GlobalId> touched(node.data(), node.data() + node.extent(0));
  std::vector<ExtraDof> extras;
  for (const auto& c : contributions) {
    firstExtra.push_back(static_cast<int>(extras.size()));
    c->prepare(ownership, extras, touched);
  }
  return DofMap<Dim>(ownership, std::move(touched), extras);
}

template <class View>
HostValues constHost(const View& v) {
  return HostValues(v.data(), v.extent(0), v.extent(1));
}

}  // namespace

template <int Dim>
GridSystem<Dim>::GridSystem(const NodeOwnership<Dim>& ownership, Method method,
                            Kinematics kinematics, const ParticleSet<Dim>& particles,
                            const Materials& materials, const Contributions& contributions,
                            double time, double loadFactor)
    : grid_(ownership.grid()),
      kinematics_(kinematics),
      particles_(particles),
      materials_(materials),
      contributions_(contributions),
      time_(time),
      loadFactor_(loadFactor),
      map_(buildParticleGridMap(method, ownership.grid(), particles)),
      dofs_(numberUnknowns(ownership, map_, contributions, firstExtra_)) {
  entryDofs_ = impm::entryDofs(map_, *dofs_.overlapMap());
  std::vector<std::pair<GO, GO>> couplings;
  for (std::size_t c = 0; c < contributions_.size(); ++c)
    contributions_[c]->couplings(context(static_cast<int>(c)), couplings);
  graph_ = buildGraph(map_, entryDofs_, dofs_, couplings);
  entryCols_ = impm::entryDofs(map_, *graph_->getColMap());
  importer_ = Teuchos::rcp(new Import(dofs_.ownedMap(), dofs_.overlapMap()));
  const std::size_t n = particles.size();
  F_ = typename ParticleSet<Dim>::Tensors("trial F", n);
  P_ = typename ParticleSet<Dim>::Tensors("P", n);
  Pn_ = typename ParticleSet<Dim>::Tensors("P relative to step start", n);
  A_ = Tangents<Dim>("A", n);
  An_ = Tangents<Dim>("A relative to step start", n);
}

template <int Dim>
StepContext<Dim> GridSystem<Dim>::context(int contribution) const {
  return StepContext<Dim>{grid_, particles_, map_,        entryDofs_,
                          dofs_, time_,      loadFactor_, firstExtra_[contribution]};
}

template <int Dim>
Teuchos::RCP<CrsMatrix> GridSystem<Dim>::createJacobian() const {
  return Teuchos::rcp(new FECrsMatrix(graph_));
}

template <int Dim>
Teuchos::RCP<Vector> GridSystem<Dim>::toOverlap(const Vector& owned) const {
  auto overlap = Teuchos::rcp(new Vector(dofs_.overlapMap()));
  overlap->doImport(owned, *importer_, Tpetra::INSERT);
  return overlap;
}

template <int Dim>
Teuchos::RCP<Vector> GridSystem<Dim>::initialGuess() const {
  auto x = Teuchos::rcp(new Vector(dofs_.ownedMap()));
  for (std::size_t c = 0; c < contributions_.size(); ++c)
    contributions_[c]->initialGuess(context(static_cast<int>(c)), *x);
  return x;
}

template <int Dim>
void GridSystem<Dim>::updateStress(const Vector& x) {
  auto xo = toOverlap(x);
  {
    auto du = xo->getLocalViewDevice(Tpetra::Access::ReadOnly);
    trialDeformationGradient<Dim>(kinematics_, map_, entryDofs_, du, particles_.F, F_);
  }
  for (std::size_t m = 0; m < materials_.size(); ++m)
    materials_[m]->firstPiola(particles_, F_, static_cast<int>(m), P_, A_);
  stressRelativeToStepStart<Dim>(kinematics_, particles_.F, P_, A_, Pn_, An_);
}

template <int Dim>
void GridSystem<Dim>::trialState(const Vector& x, typename ParticleSet<Dim>::Tensors& F,
                                 typename ParticleSet<Dim>::Tensors& P) {
  updateStress(x);
  Kokkos::deep_copy(F, F_);
  Kokkos::deep_copy(P, P_);
}

template <int Dim>
void GridSystem<Dim>::evaluate(const Vector& x, Vector* residual, CrsMatrix* jacobian) {
  updateStress(x);
  auto xo = toOverlap(x);
  auto xHost = xo->getLocalViewHost(Tpetra::Access::ReadOnly);
  if (residual) {
    FEMultiVector f(dofs_.ownedMap(), importer_, 1);
    f.beginAssembly();
    {
      auto local = f.getLocalViewDevice(Tpetra::Access::ReadWrite);
      addInternalForce<Dim>(map_, entryDofs_, particles_, Pn_, local);
      addExternalForce<Dim>(map_, entryDofs_, particles_.force, loadFactor_, local);
    }
    {
      auto local = f.getLocalViewHost(Tpetra::Access::ReadWrite);
      const HostValuesMutable fHost(local.data(), local.extent(0), local.extent(1));
      for (std::size_t c = 0; c < contributions_.size(); ++c)
        contributions_[c]->addResidual(context(static_cast<int>(c)), constHost(xHost), fHost);
    }
    f.endAssembly();
    Tpetra::deep_copy(*residual, *f.getVector(0));
  }
  if (jacobian) {
    auto& J = dynamic_cast<FECrsMatrix&>(*jacobian);
    J.beginAssembly();
    J.setAllToScalar(0.0);
    addTangent<Dim>(map_, entryDofs_, entryCols_, particles_, An_, J.getLocalMatrixDevice());
    for (std::size_t c = 0; c < contributions_.size(); ++c)
      contributions_[c]->addJacobian(context(static_cast<int>(c)), constHost(xHost), J);
    J.endAssembly();
  }
}

template <int Dim>
void GridSystem<Dim>::commit(const Vector& x) {
  auto xo = toOverlap(x);
  auto xHost = xo->getLocalViewHost(Tpetra::Access::ReadOnly);
  for (std::size_t c = 0; c < contributions_.size(); ++c)
    contributions_[c]->commit(context(static_cast<int>(c)), constHost(xHost));
}

template class GridSystem<1>;
template class GridSystem<2>;

}  // namespace impm

#include "solver/FinestLevel.hpp"

#include <MueLu_CreateTpetraPreconditioner.hpp>
#include <MueLu_HierarchyUtils.hpp>
#include <MueLu_TopSmootherFactory.hpp>
#include <MueLu_Utilities.hpp>
#include <MueLu_XpetraOperator.hpp>
#include <Thyra_XpetraLinearOp.hpp>

#include "core/Timers.hpp"
#include "core/Types.hpp"

namespace impm {

namespace {

using Hierarchy = MueLu::Hierarchy<double, LO, GO, Node>;

// The factory manager a hierarchy's set-up used on a level.  Hierarchy::GetLevelManager is
// protected (MueLu 13.2): a pointer to it, taken in the scope of a class derived from
// Hierarchy, is a pointer to Hierarchy's member, and calls it on any hierarchy.
struct LevelManagers : Hierarchy {
  static Teuchos::RCP<const MueLu::FactoryManagerBase> of(const Hierarchy& hierarchy, int level) {
    const auto get = &LevelManagers::GetLevelManager;
    return (hierarchy.*get)(level);
  }
};

using XpetraOp = Xpetra::Operator<double, LO, GO, Node>;
using XpetraMatrix = Xpetra::Matrix<double, LO, GO, Node>;

// The MueLu hierarchy behind `prec`, or null.
Teuchos::RCP<Hierarchy> hierarchyOf(const Thyra::LinearOpBase<double>& prec) {
  const auto* thyraOp = dynamic_cast<const Thyra::XpetraLinearOp<double, LO, GO, Node>*>(&prec);
  if (!thyraOp)
    return Teuchos::null;
  const auto mueluOp = Teuchos::rcp_dynamic_cast<const MueLu::XpetraOperator<double, LO, GO, Node>>(
      thyraOp->getConstXpetraOperator());
  return mueluOp.is_null() ? Teuchos::null : mueluOp->GetHierarchy();
}

// The matrix of the hierarchy's finest level, or null.
Teuchos::RCP<XpetraMatrix> finestMatrix(Hierarchy& hierarchy) {
  return Teuchos::rcp_dynamic_cast<XpetraMatrix>(
      hierarchy.GetLevel(0)->Get<Teuchos::RCP<XpetraOp>>("A"));
}

// Makes `matrix` the finest level's, with the same block size as `old`, and sets the level's
// smoothers up again on it, as the hierarchy's set-up makes them (Hierarchy::Setup); a
// hierarchy of one level has its coarse solver there.
void setFinestLevel(Hierarchy& hierarchy, const XpetraMatrix& old,
                    const Teuchos::RCP<const CrsMatrix>& matrix) {
  IMPM_TIMER("preconditioner");  // only where there is work: not for a request on the same matrix
  const auto next = MueLu::TpetraCrs_To_XpetraMatrix<double, LO, GO, Node>(
      Teuchos::rcp_const_cast<CrsMatrix>(matrix));
  next->SetFixedBlockSize(old.GetFixedBlockSize());
  const auto finest = hierarchy.GetLevel(0);
  finest->Set("A", next);  // as MueLu's Thyra adapter sets it: a Matrix
  const auto manager = LevelManagers::of(hierarchy, 0);
  MueLu::SetFactoryManager attach(finest, manager);
  MueLu::TopSmootherFactory<double, LO, GO, Node> smoothers(
      manager, hierarchy.GetNumLevels() == 1 ? "CoarseSolver" : "Smoother");
  finest->Request(smoothers);
  smoothers.Build(*finest);
  finest->Release(smoothers);
}

// The identity on the unknowns of `like` (one entry per row): what the finest level holds
// between two Jacobians.  Made from its arrays, at the cost of a vector.
Teuchos::RCP<const CrsMatrix> identityLike(const CrsMatrix& like) {
  using Graph = CrsMatrix::local_graph_device_type;
  const auto rows = like.getRowMap();
  const LO n = static_cast<LO>(rows->getNodeNumElements());
  Graph::row_map_type::non_const_type start("identity rows", n + 1);
  Graph::entries_type::non_const_type column(Kokkos::ViewAllocateWithoutInitializing("identity"),
                                             n);
  CrsMatrix::local_matrix_device_type::values_type one(
      Kokkos::ViewAllocateWithoutInitializing("identity"), n);
  Kokkos::parallel_for(
      "impm::identity", Kokkos::RangePolicy<DefaultExecSpace>(0, n + 1), KOKKOS_LAMBDA(const LO k) {
        start(k) = k;
        if (k < n)
          column(k) = k, one(k) = 1.0;
      });
  auto identity = Teuchos::rcp(new CrsMatrix(rows, rows, start, column, one));
  identity->expertStaticFillComplete(like.getDomainMap(), like.getRangeMap());
  return identity;
}

}  // namespace

bool moveFinestLevelTo(const Thyra::LinearOpBase<double>& prec,
                       const Teuchos::RCP<const CrsMatrix>& jacobian) {
  const auto hierarchy = hierarchyOf(prec);
  if (hierarchy.is_null() || jacobian.is_null())
    return false;
  const auto old = finestMatrix(*hierarchy);
  if (old.is_null() ||
      &MueLu::Utilities<double, LO, GO, Node>::Op2TpetraCrs(*old) == jacobian.get())
    return false;
  setFinestLevel(*hierarchy, *old, jacobian);
  return true;
}

bool releaseFinestLevel(const Thyra::LinearOpBase<double>& prec) {
  const auto hierarchy = hierarchyOf(prec);
  if (hierarchy.is_null())
    return false;
  const auto old = finestMatrix(*hierarchy);
  if (old.is_null())
    return false;
  setFinestLevel(*hierarchy, *old,
                 identityLike(MueLu::Utilities<double, LO, GO, Node>::Op2TpetraCrs(*old)));
  return true;
}

}  // namespace impm

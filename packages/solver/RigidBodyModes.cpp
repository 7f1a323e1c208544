#include "solver/RigidBodyModes.hpp"

#include <algorithm>

namespace impm {

template <int Dim>
Teuchos::RCP<MultiVector> rigidBodyModes(const GridGeometry<Dim>& grid, const DofMap<Dim>& dofs) {
  const Map& map = *dofs.ownedMap();
  constexpr int rotations = Dim * (Dim - 1) / 2;
  auto modes = Teuchos::rcp(new MultiVector(dofs.ownedMap(), Dim + rotations));
  auto v = modes->getLocalViewHost(Tpetra::Access::OverwriteAll);
  Kokkos::deep_copy(v, 0.0);
  double centre[Dim];
  for (int d = 0; d < Dim; ++d)
    centre[d] = grid.origin[d] + 0.5 * grid.cells[d] * grid.spacing[d];
  const auto& padding = dofs.paddingDofs();
  const GO nodal = grid.numNodes() * Dim;
  for (LO k = 0; k < static_cast<LO>(map.getNodeNumElements()); ++k) {
    const GO gid = map.getGlobalElement(k);
    if (std::find(padding.begin(), padding.end(), gid) != padding.end()) {
      v(k, DofMap<Dim>::componentOf(gid)) = 1.0;
      continue;
    }
    if (gid >= nodal)  // an extra unknown
      continue;
    const int component = DofMap<Dim>::componentOf(gid);
    int idx[Dim];
    grid.nodeIndex(DofMap<Dim>::nodeOf(gid), idx);
    double x[Dim];
    for (int d = 0; d < Dim; ++d)
      x[d] = grid.nodeCoord(d, idx[d]) - centre[d];
    v(k, component) = 1.0;
    int column = Dim;
    for (int a = 0; a < Dim; ++a)
      for (int b = a + 1; b < Dim; ++b, ++column) {
        if (component == a)
          v(k, column) = -x[b];
        if (component == b)
          v(k, column) = x[a];
      }
  }
  return modes;
}

template Teuchos::RCP<MultiVector> rigidBodyModes<1>(const GridGeometry<1>&, const DofMap<1>&);
template Teuchos::RCP<MultiVector> rigidBodyModes<2>(const GridGeometry<2>&, const DofMap<2>&);
template Teuchos::RCP<MultiVector> rigidBodyModes<3>(const GridGeometry<3>&, const DofMap<3>&);

}  // namespace impm

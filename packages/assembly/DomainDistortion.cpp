#include "assembly/DomainDistortion.hpp"

#include <Teuchos_CommHelpers.hpp>

#include "core/Tensor.hpp"

namespace impm {

namespace {

// delta and det D of particle p's domain (delta = 1, J = 1 where the particle has no domain
// of its own: a mesh element's tracked corners).
template <int Dim, class View>
KOKKOS_INLINE_FUNCTION void shapeOf(const View& R, const View& R0, int p, double& delta,
                                    double& J) {
  double r[Dim][Dim], r0[Dim][Dim], r0inv[Dim][Dim], D[Dim][Dim], Dinv[Dim][Dim];
  for (int a = 0; a < Dim; ++a)
    for (int k = 0; k < Dim; ++k)
      r[a][k] = R(p, a, k), r0[a][k] = R0(p, a, k);
  delta = 1.0, J = 1.0;
  const double J0 = determinant<Dim>(r0);
  if (!(J0 > 0.0))
    return;
  inverse<Dim>(r0, J0, r0inv);
  double norm = 0.0, normInv = 0.0;
  for (int a = 0; a < Dim; ++a)
    for (int b = 0; b < Dim; ++b) {
      D[a][b] = 0.0;
      for (int k = 0; k < Dim; ++k)
        D[a][b] += r[a][k] * r0inv[k][b];
      norm += D[a][b] * D[a][b];
    }
  J = determinant<Dim>(D);
  if (!(J > 0.0)) {  // turned inside out: as distorted as any
    delta = Kokkos::Experimental::infinity<double>::value;
    return;
  }
  inverse<Dim>(D, J, Dinv);
  for (int a = 0; a < Dim; ++a)
    for (int b = 0; b < Dim; ++b)
      normInv += Dinv[a][b] * Dinv[a][b];
  delta = Kokkos::Experimental::sqrt(norm * normInv) / Dim;
}

}  // namespace

template <int Dim, class Space>
DomainDistortion domainDistortion(const ParticleSet<Dim, Space>& particles, const Comm& comm) {
  const auto R = particles.domain;
  const auto R0 = particles.domain0;
  const int n = static_cast<int>(particles.size());
  using Exec = typename Space::execution_space;
  using Loc = Kokkos::MaxLoc<double, int>;
  typename Loc::value_type worst{1.0, -1};
  double smallestJ = 1.0;
  if (n > 0) {
    Kokkos::parallel_reduce(
        "impm::domainDistortion", RangePolicy<Exec>(0, n),
        KOKKOS_LAMBDA(const int p, typename Loc::value_type& w) {
          double delta, J;
          shapeOf<Dim>(R, R0, p, delta, J);
          if (delta > w.val)
            w.val = delta, w.loc = p;
        },
        Loc(worst));
    Kokkos::parallel_reduce(
        "impm::smallestDomainJ", RangePolicy<Exec>(0, n),
        KOKKOS_LAMBDA(const int p, double& jmin) {
          double delta, J;
          shapeOf<Dim>(R, R0, p, delta, J);
          if (J < jmin)
            jmin = J;
        },
        Kokkos::Min<double>(smallestJ));
  }
  DomainDistortion out;
  const double mine = n > 0 ? worst.val : 1.0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, mine, Teuchos::outArg(out.worst));
  const double myJ = n > 0 ? smallestJ : 1.0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MIN, myJ, Teuchos::outArg(out.smallestJ));
  long long id = -1, chosen = -1;
  if (n > 0 && worst.loc >= 0 && mine == out.worst) {
    auto ids = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), particles.id);
    id = static_cast<long long>(ids(worst.loc));
  }
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, id, Teuchos::outArg(chosen));
  out.particle = chosen;
  return out;
}

template DomainDistortion domainDistortion<1, DefaultExecSpace>(const ParticleSet<1>&, const Comm&);
template DomainDistortion domainDistortion<2, DefaultExecSpace>(const ParticleSet<2>&, const Comm&);
template DomainDistortion domainDistortion<3, DefaultExecSpace>(const ParticleSet<3>&, const Comm&);

}  // namespace impm

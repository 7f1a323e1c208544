#include "assembly/Energy.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <algorithm>
#include <cstdint>
#include <cstring>

namespace impm {

namespace {

double sumAll(const Comm& comm, double local) {
  double global = 0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, local, Teuchos::outArg(global));
  return global;
}

}  // namespace

template <int Dim, class Space>
double kineticEnergy(const ParticleSet<Dim, Space>& particles, const Comm& comm) {
  auto m = particles.mass;
  auto v = particles.v;
  double local = 0;
  Kokkos::parallel_reduce(
      "impm::kineticEnergy", RangePolicy<Space>(0, particles.size()),
      KOKKOS_LAMBDA(const int p, double& sum) {
        for (int d = 0; d < Dim; ++d)
          sum += 0.5 * m(p) * v(p, d) * v(p, d);
      },
      local);
  return sumAll(comm, local);
}

double lumpedKineticEnergy(const Vector& mass, const Vector& v) {
  const auto m = mass.getLocalViewDevice(Tpetra::Access::ReadOnly);
  const auto w = v.getLocalViewDevice(Tpetra::Access::ReadOnly);
  double local = 0;
  Kokkos::parallel_reduce(
      "impm::lumpedKineticEnergy", RangePolicy<DefaultExecSpace>(0, m.extent(0)),
      KOKKOS_LAMBDA(const int k, double& sum) { sum += 0.5 * m(k, 0) * w(k, 0) * w(k, 0); }, local);
  return sumAll(*v.getMap()->getComm(), local);
}

namespace {

// sum_p V0_p A_p w_p on this rank.
template <int Dim>
double integrated(const ParticleSet<Dim>& particles, const typename ParticleSet<Dim>::Scalars& w) {
  auto V0 = particles.volume0;
  auto A = particles.section;
  double sum = 0;
  Kokkos::parallel_reduce(
      "impm::integratedDensity", RangePolicy<DefaultExecSpace>(0, particles.size()),
      KOKKOS_LAMBDA(const int p, double& s) { s += V0(p) * A(p) * w(p); }, sum);
  return sum;
}

}  // namespace

template <int Dim>
MaterialEnergies materialEnergies(const ParticleSet<Dim>& particles,
                                  const Materials<Dim>& materials, const Comm& comm,
                                  const typename ParticleSet<Dim>::Scalars& W,
                                  const typename ParticleSet<Dim>::Scalars& D) {
  const bool dissipates = std::any_of(materials.begin(), materials.end(),
                                      [](const auto& m) { return m->dissipates(); });
  if (dissipates)
    Kokkos::deep_copy(D, 0.0);  // a material that does not dissipate leaves its rows alone
  for (std::size_t k = 0; k < materials.size(); ++k) {
    const auto at = evaluationOf(particles, materials, static_cast<int>(k), particles.F);
    auto w = W, d = D;
    materials[k]->energyDensity(at, w);
    if (materials[k]->dissipates())
      materials[k]->dissipationDensity(at, d);
  }
  double local[2] = {integrated<Dim>(particles, W), dissipates ? integrated<Dim>(particles, D) : 0};
  double global[2] = {};
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, 2, local, global);
  return {global[0], global[1]};
}

template <int Dim, class Space>
bool carriesForces(const ParticleSet<Dim, Space>& particles) {
  // The bits of every value but the sign, or-ed together: an integer reduction that
  // vectorizes, where a comparison of doubles does not.
  const auto f = particles.force;
  std::uint64_t bits = 0;
  Kokkos::parallel_reduce(
      "impm::carriesForces", RangePolicy<Space>(0, particles.size()),
      KOKKOS_LAMBDA(const int p, std::uint64_t& any) {
        for (int d = 0; d < Dim; ++d) {
          std::uint64_t b;
          memcpy(&b, &f(p, d), sizeof b);
          any |= b << 1;
        }
      },
      Kokkos::BOr<std::uint64_t>(bits));
  return bits != 0;
}

template <int Dim, class Space>
double bodyForceWork(const ParticleSet<Dim, Space>& particles,
                     const typename ParticleSet<Dim, Space>::Vectors& uBefore, bool loaded,
                     double scale, const Comm& comm) {
  auto f = particles.force;
  auto u = particles.u;
  double local = 0;
  if (loaded)
    Kokkos::parallel_reduce(
        "impm::bodyForceWork", RangePolicy<Space>(0, particles.size()),
        KOKKOS_LAMBDA(const int p, double& sum) {
          for (int d = 0; d < Dim; ++d)
            sum += f(p, d) * (u(p, d) - uBefore(p, d));
        },
        local);
  return scale * sumAll(comm, local);
}

#define IMPM_INSTANTIATE(D)                                                                  \
  template double kineticEnergy<D, DefaultExecSpace>(const ParticleSet<D>&, const Comm&);    \
  template MaterialEnergies materialEnergies<D>(const ParticleSet<D>&, const Materials<D>&,  \
                                                const Comm&, const ParticleSet<D>::Scalars&, \
                                                const ParticleSet<D>::Scalars&);             \
  template bool carriesForces<D, DefaultExecSpace>(const ParticleSet<D>&);                   \
  template double bodyForceWork<D, DefaultExecSpace>(                                        \
      const ParticleSet<D>&, const ParticleSet<D>::Vectors&, bool, double, const Comm&);
IMPM_INSTANTIATE(1)
IMPM_INSTANTIATE(2)
IMPM_INSTANTIATE(3)
#undef IMPM_INSTANTIATE

}  // namespace impm

#include "assembly/Energy.hpp"

#include <Teuchos_CommHelpers.hpp>

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

// sum_p V0_p A_p w_p of a density w that every material computes on its particles.
template <int Dim>
double integrated(const ParticleSet<Dim>& particles, const Materials<Dim>& materials,
                  const Comm& comm,
                  void (Material<Dim>::*density)(const typename Material<Dim>::Evaluation&,
                                                 typename ParticleSet<Dim>::Scalars&) const) {
  typename ParticleSet<Dim>::Scalars w("density", particles.size());
  for (std::size_t k = 0; k < materials.size(); ++k)
    ((*materials[k]).*density)(evaluationOf(particles, materials, static_cast<int>(k), particles.F),
                               w);
  auto V0 = particles.volume0;
  auto A = particles.section;
  double local = 0;
  Kokkos::parallel_reduce(
      "impm::integratedDensity", RangePolicy<DefaultExecSpace>(0, particles.size()),
      KOKKOS_LAMBDA(const int p, double& sum) { sum += V0(p) * A(p) * w(p); }, local);
  return sumAll(comm, local);
}

template <int Dim>
double strainEnergy(const ParticleSet<Dim>& particles, const Materials<Dim>& materials,
                    const Comm& comm) {
  return integrated<Dim>(particles, materials, comm, &Material<Dim>::energyDensity);
}

template <int Dim>
double dissipatedEnergy(const ParticleSet<Dim>& particles, const Materials<Dim>& materials,
                        const Comm& comm) {
  return integrated<Dim>(particles, materials, comm, &Material<Dim>::dissipationDensity);
}

template <int Dim, class Space>
double bodyForceWork(const ParticleSet<Dim, Space>& particles,
                     const typename ParticleSet<Dim, Space>::Vectors& uBefore, double scale,
                     const Comm& comm) {
  auto f = particles.force;
  auto u = particles.u;
  double local = 0;
  Kokkos::parallel_reduce(
      "impm::bodyForceWork", RangePolicy<Space>(0, particles.size()),
      KOKKOS_LAMBDA(const int p, double& sum) {
        for (int d = 0; d < Dim; ++d)
          sum += f(p, d) * (u(p, d) - uBefore(p, d));
      },
      local);
  return scale * sumAll(comm, local);
}

#define IMPM_INSTANTIATE(D)                                                                     \
  template double kineticEnergy<D, DefaultExecSpace>(const ParticleSet<D>&, const Comm&);       \
  template double strainEnergy<D>(const ParticleSet<D>&, const Materials<D>&, const Comm&);     \
  template double dissipatedEnergy<D>(const ParticleSet<D>&, const Materials<D>&, const Comm&); \
  template double bodyForceWork<D, DefaultExecSpace>(                                           \
      const ParticleSet<D>&, const ParticleSet<D>::Vectors&, double, const Comm&);
IMPM_INSTANTIATE(1)
IMPM_INSTANTIATE(2)
#undef IMPM_INSTANTIATE

}  // namespace impm

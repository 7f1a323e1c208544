#include "material/FiniteStrainPlasticity.hpp"

#include "core/Parameters.hpp"
#include "material/DruckerPragerLaw.hpp"
#include "material/J2Law.hpp"

namespace impm {

namespace {

// The state tables: C_p^-1 (components xx, yy, zz, xy, yz, xz), alpha, dissipation.
template <int Dim>
struct StateTables {
  typename Material<Dim>::Table metric, alpha, dissipation;

  KOKKOS_INLINE_FUNCTION PlasticState at(int p) const {
    return {{metric(p, 0), metric(p, 1), metric(p, 2), metric(p, 3), metric(p, 4), metric(p, 5)},
            alpha(p, 0),
            dissipation(p, 0)};
  }
  template <class T>
  KOKKOS_INLINE_FUNCTION void store(int p, const Sym<T>& m, const T& a, const T& d) const {
    metric(p, 0) = valueOf(m.xx), metric(p, 1) = valueOf(m.yy), metric(p, 2) = valueOf(m.zz);
    metric(p, 3) = valueOf(m.xy), metric(p, 4) = valueOf(m.yz), metric(p, 5) = valueOf(m.xz);
    alpha(p, 0) = valueOf(a), dissipation(p, 0) = valueOf(d);
  }
};

template <int Dim>
StateTables<Dim> committed(const typename Material<Dim>::Evaluation& at) {
  return {at.variables.at(0), at.variables.at(1), at.variables.at(2)};
}

// F_p as the 3 x 3 deformation gradient (F_zz = 1 in 2-D).
template <int Dim>
KOKKOS_INLINE_FUNCTION void loadEmbedded(const typename Material<Dim>::Tensors& F, int p,
                                         double F3[3][3]) {
  double f[Dim][Dim];
  load<Dim>(F, p, f);
  embed<Dim>(f, F3);
}

// The committed elastic strain (1/2) ln(F C_p^-1 F^T) at particle p.
template <int Dim>
KOKKOS_INLINE_FUNCTION Sym<double> elasticStrain(const typename Material<Dim>::Tensors& F,
                                                 const StateTables<Dim>& state, int p) {
  double F3[3][3];
  loadEmbedded<Dim>(F, p, F3);
  return trialElasticStrain(F3, state.at(p).metric);
}

FieldSpec stateField(const std::string& name, const std::string& doc, FieldShape shape,
                     bool written) {
  FieldSpec spec;
  spec.name = name, spec.doc = doc, spec.shape = shape, spec.twoLevels = true;
  if (written)
    spec.columns = defaultColumns<3>(name, shape);  // scalars: the same in any dimension
  return spec;
}

}  // namespace

template <int Dim, class Law>
Teuchos::ParameterList FiniteStrainPlasticity<Dim, Law>::validParameters() {
  Teuchos::ParameterList valid;
  declareElasticConstants(valid);
  Law::declare(valid);
  return valid;
}

template <int Dim, class Law>
FiniteStrainPlasticity<Dim, Law>::FiniteStrainPlasticity(const std::string& name,
                                                         const Teuchos::ParameterList& params)
    : Material<Dim>(name, params.get<double>("Density")),
      parameters_(Law::read(params, lameOf(params), "Materials/" + name + "/")) {}

template <int Dim, class Law>
std::vector<typename Material<Dim>::Variable> FiniteStrainPlasticity<Dim, Law>::variables() const {
  return {{stateField("plastic_metric", "inverse plastic right Cauchy-Green tensor C_p^-1",
                      FieldShape::symmetric3x3, false),
           {1.0, 1.0, 1.0, 0.0, 0.0, 0.0}},
          {stateField("equivalent_plastic_strain", "accumulated equivalent plastic strain alpha",
                      FieldShape::scalar, true),
           {0.0}},
          {stateField("plastic_dissipation", "energy dissipated per unit reference volume",
                      FieldShape::scalar, true),
           {0.0}}};
}

template <int Dim, class Law>
void FiniteStrainPlasticity<Dim, Law>::firstPiola(const Evaluation& at, Tensors& P,
                                                  Tangents& A) const {
  const auto members = at.members;
  const auto F = at.F;
  const StateTables<Dim> n = committed<Dim>(at),
                         trial{at.trial.at(0), at.trial.at(1), at.trial.at(2)};
  const Parameters k = parameters_;
  const int count = static_cast<int>(members.extent(0));
  int firstBad = count;
  using D = Fad<Dim * Dim>;  // derivatives along F_ab, (a, b) -> Dim a + b
  Kokkos::parallel_reduce(
      "impm::FiniteStrainPlasticity", RangePolicy<ExecutionSpace>(0, count),
      KOKKOS_LAMBDA(const int i, int& bad) {
        const int p = members(i);
        double f[Dim][Dim], F3[3][3];
        load<Dim>(F, p, f);
        embed<Dim>(f, F3);
        if (!(determinantOf(F3) > 0.0)) {
          bad = i < bad ? i : bad;
          return;
        }
        D Fd[Dim][Dim], Fd3[3][3], Finv[3][3], Pd[Dim][Dim];
        for (int a = 0; a < Dim; ++a)
          for (int b = 0; b < Dim; ++b)
            Fd[a][b] = variable<Dim * Dim>(f[a][b], Dim * a + b);
        embed<Dim>(Fd, Fd3);
        const auto r = Law::returnMap(Fd3, n.at(p), k);
        inverseOf(Fd3, determinantOf(Fd3), Finv);
        piolaOfKirchhoff<Dim>(r.tau, Finv, Pd);
        double Pv[Dim][Dim], Av[Dim][Dim][Dim][Dim];
        for (int a = 0; a < Dim; ++a)
          for (int b = 0; b < Dim; ++b) {
            Pv[a][b] = valueOf(Pd[a][b]);
            for (int c = 0; c < Dim; ++c)
              for (int d = 0; d < Dim; ++d)
                Av[a][b][c][d] = derivativeOf(Pd[a][b], Dim * c + d);
          }
        store<Dim>(P, A, p, Pv, Av);
        const auto& e = r.elasticStrain;
        trial.store(p,
                    plasticMetricOf(F3, Sym<double>{valueOf(e.xx), valueOf(e.yy), valueOf(e.zz),
                                                    valueOf(e.xy), valueOf(e.yz), valueOf(e.xz)}),
                    valueOf(r.alpha), valueOf(r.dissipation));
      },
      Kokkos::Min<int>(firstBad));
  throwIfInverted<Dim>(*this, model(), at, firstBad);
}

template <int Dim, class Law>
void FiniteStrainPlasticity<Dim, Law>::energyDensity(const Evaluation& at, Scalars& W) const {
  const auto F = at.F;
  const StateTables<Dim> n = committed<Dim>(at);
  const Parameters k = parameters_;
  setForMembers<ExecutionSpace>(
      "impm::FiniteStrainPlasticity::energy", at.members, W, KOKKOS_LAMBDA(const int p) {
        return henckyEnergy(elasticStrain<Dim>(F, n, p), k.mu, k.lambda) +
               Law::hardeningEnergy(n.alpha(p, 0), k);
      });
}

template <int Dim, class Law>
void FiniteStrainPlasticity<Dim, Law>::dissipationDensity(const Evaluation& at, Scalars& D) const {
  const StateTables<Dim> n = committed<Dim>(at);
  setForMembers<ExecutionSpace>(
      "impm::FiniteStrainPlasticity::dissipation", at.members, D,
      KOKKOS_LAMBDA(const int p) { return n.dissipation(p, 0); });
}

template <int Dim, class Law>
void FiniteStrainPlasticity<Dim, Law>::outOfPlaneStress(const Evaluation& at,
                                                        Scalars& stressZZ) const {
  if constexpr (Dim == 2) {  // plane strain; a 3-D stress has its own zz component
    const auto F = at.F;
    const StateTables<Dim> n = committed<Dim>(at);
    const Parameters k = parameters_;
    setForMembers<ExecutionSpace>(
        "impm::FiniteStrainPlasticity::stressZZ", at.members, stressZZ, KOKKOS_LAMBDA(const int p) {
          const double tauZZ = henckyStress(elasticStrain<Dim>(F, n, p), k.mu, k.lambda).zz;
          return tauZZ / determinant<Dim>(F, p);
        });
  }
}

template class FiniteStrainPlasticity<2, J2Law>;
template class FiniteStrainPlasticity<2, DruckerPragerLaw>;
template class FiniteStrainPlasticity<3, J2Law>;
template class FiniteStrainPlasticity<3, DruckerPragerLaw>;

}  // namespace impm

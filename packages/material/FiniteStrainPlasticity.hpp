#pragma once
// Elastoplastic laws at finite strain, 2-D (plane strain) and 3-D, on Hencky elasticity and the
// exponential map (doc/theory.md, "Laws with history"): F = F_e F_p, eps_e = (1/2) ln b_e,
// tau = D : eps_e, and a return map on the logarithmic strain that each Law supplies
// (J2Law: von Mises; DruckerPragerLaw).  FiniteStrainPlasticity<Law> runs a Law through the
// Material interface: the state, the trial state, the stress, the tangent, the energies.
//
// The state of every law here, in declaration order:
//   plastic_metric             C_p^-1 = F_p^-1 F_p^-T (symmetric 3 x 3; checkpointed, not
//                              written): the trial b_e = F C_p^-1 F^T needs only the
//                              evaluation's F, under total and updated Lagrangian kinematics
//                              and after a restart alike (doc/design.md);
//   equivalent_plastic_strain  alpha (written);
//   plastic_dissipation        the energy dissipated per unit reference volume (written).
// The tangent is the exact derivative of the return (dual numbers along the Dim x Dim
// components of F): the algorithmic tangent.  A Law's return map acts on the 3 x 3 F (F_zz = 1
// in 2-D), so that one return serves both dimensions.
//
// A Law provides: model(); declare(valid) its parameters beyond E and nu; Parameters
// read(params, Lame); returnMap<T>(F, state, parameters) -> PlasticUpdate<T>; and
// hardeningEnergy(alpha, parameters), the stored energy beyond Hencky's.

#include <Teuchos_ParameterList.hpp>

#include <string>

#include "material/HenckyLaw.hpp"

namespace impm {

// The committed state of a particle.
struct PlasticState {
  Sym<double> metric;  // C_p^-1
  double alpha, dissipation;
};

// What a return map gives: the stress and the state at the end of the step.
template <class T>
struct PlasticUpdate {
  Sym<T> tau;            // Kirchhoff stress
  Sym<T> elasticStrain;  // eps_e = (1/2) ln b_e
  T alpha;               // equivalent plastic strain
  T dissipation;         // dissipated energy per unit reference volume
};

// The trial state of a step: the elastic strain and the Kirchhoff stress if the step were
// elastic, and the stress deviator.
template <class T>
struct Trial {
  Sym<T> eps, tau, s;
};

template <class T>
KOKKOS_INLINE_FUNCTION Trial<T> trialOf(const T F[3][3], const PlasticState& n, double mu,
                                        double lambda) {
  Trial<T> t;
  t.eps = trialElasticStrain(F, n.metric);
  t.tau = henckyStress(t.eps, mu, lambda);
  t.s = deviator(t.tau);
  return t;
}

// An elastic step: the trial state, the history unchanged.
template <class T>
KOKKOS_INLINE_FUNCTION PlasticUpdate<T> elasticUpdate(const Trial<T>& t, const PlasticState& n) {
  return {t.tau, t.eps, T(n.alpha), T(n.dissipation)};
}

// The equivalent plastic strain increment sqrt(2/3 d:d) of a plastic strain increment d,
// by value (its derivative is not needed: alpha enters the stress only through hardening,
// which the laws that use it differentiate themselves).
template <class T>
KOKKOS_INLINE_FUNCTION double equivalentIncrement(const Sym<T>& d) {
  return Kokkos::Experimental::sqrt(2.0 / 3.0 * valueOf(squaredNorm(d)));
}

template <int Dim, class Law>
class FiniteStrainPlasticity : public Material<Dim> {
 public:
  using Base = Material<Dim>;
  using typename Base::Evaluation;
  using typename Base::Scalars;
  using typename Base::Tangents;
  using typename Base::Tensors;
  using typename Base::Variable;
  using ExecutionSpace = typename Base::ExecutionSpace;
  static constexpr int dimension = Dim;
  using Parameters = typename Law::Parameters;
  static const char* model() { return Law::model(); }
  static Teuchos::ParameterList validParameters();

  FiniteStrainPlasticity(const std::string& name, const Teuchos::ParameterList& params);
  std::vector<Variable> variables() const override;
  void firstPiola(const Evaluation& at, Tensors& P, Tangents& A) const override;
  void energyDensity(const Evaluation& at, Scalars& W) const override;
  void dissipationDensity(const Evaluation& at, Scalars& D) const override;
  bool dissipates() const override { return true; }
  void outOfPlaneStress(const Evaluation& at, Scalars& stressZZ) const override;
  double maxModulus(const Evaluation& /*at*/) const override {
    return parameters_.lambda + 2.0 * parameters_.mu;
  }
  double youngModulus(const Evaluation& /*at*/) const override {
    return youngFromLame(parameters_.lambda, parameters_.mu);
  }

 private:
  Parameters parameters_;
};

}  // namespace impm

#pragma once
// 1-D elastic laws sigma = xi(eps, x) (primer 1.3-1.4) with eps = F - 1, as device functors
// over per-particle parameters (formulas of the reference position x, evaluated once into
// the law's parameter fields).  ElasticLaw1D<Law> runs any of them through the Material interface:
// the framework sees only P(F), dP/dF and the energy W(F).
//
//   linear          P = E (F - 1)                     (Hooke, eq. 1.1; also V2's law)
//   linear-finite   P = E (F - 1)                     (the same law: 1-D strain is F - 1)
//   cubic           P = E eps + C eps^3               (problem N1)
//   neo-hookean-1d  P = (E / 2) (F - 1 / F)           (problem T1; needs F > 0)
//   hencky-1d       P = E ln(F) / F                   (Hencky in uniaxial stress, nu = 0:
//                                                      Kirchhoff tau = E ln F; needs F > 0)

#include <Teuchos_ParameterList.hpp>

#include <string>
#include <vector>

#include "core/Formula.hpp"
#include "core/Parameters.hpp"
#include "material/Material.hpp"

namespace impm {

struct LawValue {
  double P, A, W;   // stress, tangent dP/dF, energy per unit reference volume
  bool admissible;  // false where the law is not defined (F <= 0 for neo-Hookean)
};

struct LinearLaw {
  static const char* model() { return "linear"; }
  static std::vector<std::string> parameters() { return {"E"}; }
  static constexpr bool linear = true;
  KOKKOS_INLINE_FUNCTION static LawValue evaluate(double F, const double* k) {
    const double e = F - 1.0;
    return {k[0] * e, k[0], 0.5 * k[0] * e * e, true};
  }
};

struct LinearFiniteLaw : LinearLaw {
  static const char* model() { return "linear-finite"; }
};

struct CubicLaw {
  static const char* model() { return "cubic"; }
  static std::vector<std::string> parameters() { return {"E", "C"}; }
  static constexpr bool linear = false;
  KOKKOS_INLINE_FUNCTION static LawValue evaluate(double F, const double* k) {
    const double e = F - 1.0;
    return {k[0] * e + k[1] * e * e * e, k[0] + 3.0 * k[1] * e * e,
            0.5 * k[0] * e * e + 0.25 * k[1] * e * e * e * e, true};
  }
};

struct NeoHookeanLaw1D {
  static const char* model() { return "neo-hookean-1d"; }
  static std::vector<std::string> parameters() { return {"E"}; }
  static constexpr bool linear = false;
  KOKKOS_INLINE_FUNCTION static LawValue evaluate(double F, const double* k) {
    if (!(F > 0.0))
      return {0.0, k[0], 0.0, false};
    return {0.5 * k[0] * (F - 1.0 / F), 0.5 * k[0] * (1.0 + 1.0 / (F * F)),
            0.5 * k[0] * (0.5 * (F * F - 1.0) - Kokkos::Experimental::log(F)), true};
  }
};

struct HenckyLaw1D {
  static const char* model() { return "hencky-1d"; }
  static std::vector<std::string> parameters() { return {"E"}; }
  static constexpr bool linear = false;
  KOKKOS_INLINE_FUNCTION static LawValue evaluate(double F, const double* k) {
    if (!(F > 0.0))
      return {0.0, k[0], 0.0, false};
    const double e = Kokkos::Experimental::log(F);
    return {k[0] * e / F, k[0] * (1.0 - e) / (F * F), 0.5 * k[0] * e * e, true};
  }
};

template <class Law>
class ElasticLaw1D : public Material<1> {
 public:
  static const char* model() { return Law::model(); }
  static Teuchos::ParameterList validParameters();

  ElasticLaw1D(const std::string& name, const Teuchos::ParameterList& params);
  // The law's parameters at each particle, E(X_p), C(X_p): stored, migrated, not written.
  std::vector<Variable> variables() const override;
  void initialize(const Evaluation& at) const override;
  void firstPiola(const Evaluation& at, Tensors& P, Tangents& A) const override;
  void energyDensity(const Evaluation& at, Scalars& W) const override;
  double maxModulus(const Evaluation& at) const override;
  bool isLinear() const override { return Law::linear; }

 private:
  std::vector<Formula> parameters_;
};

}  // namespace impm

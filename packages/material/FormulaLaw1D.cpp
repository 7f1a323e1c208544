#include "material/FormulaLaw1D.hpp"

#include <cmath>
#include <limits>
#include <sstream>

#include "core/Errors.hpp"
#include "core/Parameters.hpp"

namespace impm {

Teuchos::ParameterList FormulaLaw1D::validParameters() {
  Teuchos::ParameterList valid;
  declareString(valid, "Stress", "1e3*eps",
                "sigma(eps, x): the stress as a formula of the strain eps = F - 1 and the "
                "reference position x",
                true);
  declareString(valid, "Tangent", "",
                "dsigma/deps(eps, x) as a formula; empty: a central difference of Stress with "
                "step eps_machine^(1/3) max(|eps|, 1e-3)");
  return valid;
}

namespace {

Formula readFormula(const Teuchos::ParameterList& params, const std::string& name,
                    const std::string& material) {
  try {
    return Formula(params.get<std::string>(name), {"eps", "x"});
  } catch (const InputError& e) {
    throw InputError("Materials/" + material + "/" + name, e.what());
  }
}

}  // namespace

FormulaLaw1D::FormulaLaw1D(const std::string& name, const Teuchos::ParameterList& params)
    : Material<1>(name, params.get<double>("Density")),
      stress_(readFormula(params, "Stress", name)),
      analyticTangent_(!params.get<std::string>("Tangent").empty()) {
  if (analyticTangent_)
    tangent_ = readFormula(params, "Tangent", name);
}

double FormulaLaw1D::tangent(double e, double x) const {
  if (analyticTangent_)
    return tangent_(e, x);
  const double delta =
      std::cbrt(std::numeric_limits<double>::epsilon()) * std::max(std::abs(e), 1e-3);
  return (stress_(e + delta, x) - stress_(e - delta, x)) / (2 * delta);
}

namespace {

// The host copies a formula law works on: reference positions, members, deformation.
struct HostPoints {
  explicit HostPoints(const Material<1>::Evaluation& at)
      : X(Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), at.particles.X)),
        members(Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), at.members)),
        F(Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), at.F)) {}
  std::size_t size() const { return members.extent(0); }
  Material<1>::Particles::Vectors::HostMirror X;
  Material<1>::Members::HostMirror members;
  Material<1>::Tensors::HostMirror F;
};

}  // namespace

void FormulaLaw1D::initialize(const Evaluation& at) const {
  // The law must hold at rest: finite stress and a positive modulus at eps = 0.
  const HostPoints host(at);
  for (std::size_t i = 0; i < host.size(); ++i) {
    const double x = host.X(host.members(i), 0);
    const double s = stress(0.0, x), t = tangent(0.0, x);
    if (!std::isfinite(s) || !(t > 0)) {
      std::ostringstream msg;
      msg << "the law must give a finite stress and a positive tangent at eps = 0; at x = " << x
          << " it gives sigma = " << s << ", dsigma/deps = " << t;
      throw InputError("Materials/" + name() + "/Stress", msg.str());
    }
  }
}

void FormulaLaw1D::firstPiola(const Evaluation& at, Tensors& P, Tangents& A) const {
  const HostPoints host(at);
  auto Ph = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), P);
  auto Ah = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), A);
  for (std::size_t i = 0; i < host.size(); ++i) {
    const int p = host.members(i);
    const double e = host.F(p, 0, 0) - 1.0;
    Ph(p, 0, 0) = stress(e, host.X(p, 0));
    Ah(p, 0, 0, 0, 0) = tangent(e, host.X(p, 0));  // not finite: the step names the particle
  }
  Kokkos::deep_copy(P, Ph);
  Kokkos::deep_copy(A, Ah);
}

void FormulaLaw1D::energyDensity(const Evaluation& at, Scalars& W) const {
  // W(eps) = integral of sigma from 0 to eps, Simpson's rule on 32 intervals.
  const HostPoints host(at);
  auto Wh = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), W);
  const int n = 32;
  for (std::size_t i = 0; i < host.size(); ++i) {
    const int p = host.members(i);
    const double x = host.X(p, 0), e = host.F(p, 0, 0) - 1.0, h = e / n;
    double sum = stress(0.0, x) + stress(e, x);
    for (int k = 1; k < n; ++k)
      sum += (k % 2 ? 4.0 : 2.0) * stress(k * h, x);
    Wh(p) = sum * h / 3.0;
  }
  Kokkos::deep_copy(W, Wh);
}

double FormulaLaw1D::maxModulus(const Evaluation& at) const {
  const HostPoints host(at);
  double modulus = 0.0;
  for (std::size_t i = 0; i < host.size(); ++i)
    modulus = std::max(modulus, tangent(0.0, host.X(host.members(i), 0)));
  return modulus;
}

}  // namespace impm

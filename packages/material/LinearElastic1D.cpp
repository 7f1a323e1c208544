#include "material/LinearElastic1D.hpp"

#include "core/Errors.hpp"
#include "core/Parameters.hpp"
#include "material/MaterialPropertyFill.hpp"

namespace impm {

Teuchos::ParameterList LinearElastic1D::validParameters() {
  Teuchos::ParameterList valid;
  declareFormula(valid, "E", "1.0", {"x"},
                 "Young's (or constrained) modulus E(x), x the particle's reference position",
                 Bounds::positive(), true);
  return valid;
}

LinearElastic1D::LinearElastic1D(const std::string& name, const Teuchos::ParameterList& params)
    : Material<1>(name, params.get<double>("Density")), modulus_(formulaText(params, "E"), {"x"}) {}

void LinearElastic1D::initialize(Particles& particles, int index) const {
  fillPropertyFromFormula(particles, index, 0, modulus_, "Materials/" + name() + "/E",
                          Bounds::positive());
}

void LinearElastic1D::firstPiola(const Particles& particles, const Tensors& F, int index,
                                 Tensors& P, Tangents& A) const {
  auto material = particles.material;
  auto props = particles.props;
  Kokkos::parallel_for(
      "impm::LinearElastic1D", RangePolicy<DefaultExecSpace>(0, particles.size()),
      KOKKOS_LAMBDA(const int p) {
        if (material(p) != index)
          return;
        const double E = props(p, 0);
        P(p, 0, 0) = E * (F(p, 0, 0) - 1.0);
        A(p, 0, 0, 0, 0) = E;
      });
}

void LinearElastic1D::energyDensity(const Particles& particles, const Tensors& F, int index,
                                    Particles::Scalars& W) const {
  auto material = particles.material;
  auto props = particles.props;
  Kokkos::parallel_for(
      "impm::LinearElastic1D::energy", RangePolicy<DefaultExecSpace>(0, particles.size()),
      KOKKOS_LAMBDA(const int p) {
        if (material(p) != index)
          return;
        const double e = F(p, 0, 0) - 1.0;
        W(p) = 0.5 * props(p, 0) * e * e;
      });
}

double LinearElastic1D::maxModulus(const Particles& particles, int index) const {
  return maxProperty(particles, index, 0);
}

}  // namespace impm

#pragma once
// 1-D linear elasticity sigma = E(x) eps (primer eq. 1.1-1.2), eps = F - 1.  With the
// updated-Lagrangian kinematics this is P = E (F - 1), whose momentum balance is linear in
// reference coordinates (problem V2): one law serves small and large deformation.

#include <Teuchos_ParameterList.hpp>

#include "core/Formula.hpp"
#include "material/Material.hpp"

namespace impm {

class LinearElastic1D : public Material<1> {
 public:
  static const char* model() { return "linear"; }
  static Teuchos::ParameterList validParameters();

  LinearElastic1D(const std::string& name, const Teuchos::ParameterList& params);
  void initialize(Particles& particles, int index) const override;
  void firstPiola(const Particles& particles, const Tensors& F, int index, Tensors& P,
                  Tangents& A) const override;
  void energyDensity(const Particles& particles, const Tensors& F, int index,
                     Particles::Scalars& W) const override;
  double maxModulus(const Particles& particles, int index) const override;
  bool isLinear() const override { return true; }

 private:
  Formula modulus_;
};

}  // namespace impm

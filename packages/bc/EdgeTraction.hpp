#pragma once
// A traction on part of a 2-D body's boundary: a dead load t (force per unit reference
// length, plane strain per unit thickness) on the particle-domain faces that lie on the
// body's boundary inside a box.  Each such face, with reference length L0 and corners c1,
// c2 (the CPDI corners x_p +- r_1 +- r_2; for mpm, gimp and fem the same parallelogram of
// the particle's domain), adds
//   f_i -= lambda t L0 (N_i(c1) + N_i(c2)) / 2,
// the trapezoidal rule of the integral of N_i t over the face, exact for the tents, which
// are linear along a face on a grid line.  lambda is the load factor of static load steps.
// The faces are found in the reference configuration: a face is on the boundary when the
// point just beyond its midpoint is outside the body's shape.

#include <Teuchos_ParameterList.hpp>

#include <array>
#include <string>

#include <functional>
#include "assembly/Kinematics.hpp"
#include "core/Formula.hpp"
#include "solver/Contribution.hpp"

namespace impm {

class EdgeTraction : public Contribution<2> {
 public:
  static Teuchos::ParameterList validParameters();

  // body: index of the body the traction acts on; inside: whether a point lies in the
  // body's reference shape.
  EdgeTraction(const std::string& name, const Teuchos::ParameterList& params, int body,
               std::function<bool(const double*)> inside, Kinematics kinematics);

  void addResidual(const ContributionContext<2>& ctx, const HostValues& x,
                   const HostValuesMutable& f) const override;

 private:
  std::string name_;
  int body_;
  std::function<bool(const double*)> inside_;
  Kinematics kinematics_;
  std::array<double, 4> box_;
  std::array<Formula, 2> traction_;
};

}  // namespace impm

#pragma once
// A constitutive model treated as a black box (primer 1.3-1.4): given the deformation
// gradient F of each particle it returns the first Piola-Kirchhoff stress P(F) and its
// tangent A = dP/dF.  The framework never assumes Hooke's law; everything it needs from
// the material goes through this interface.
//
// In 1-D, F = dx/dX = 1 + eps with eps the engineering strain, and P is the axial force per
// unit (reference) section: a law sigma = xi(eps, x) of the primer is P = xi(F - 1, X).

#include <memory>
#include <string>

#include "core/ParticleSet.hpp"

namespace impm {

template <int Dim, class Space = DefaultExecSpace>
class Material {
 public:
  using Particles = ParticleSet<Dim, Space>;
  using Tensors = typename Particles::Tensors;
  using Tangents = Kokkos::View<double* [Dim][Dim][Dim][Dim], typename Space::memory_space>;

  Material(std::string name, double density) : name_(std::move(name)), density_(density) {}
  virtual ~Material() = default;

  const std::string& name() const { return name_; }
  double density() const { return density_; }

  // Stores position-dependent parameters (E(X_p), ...) of the particles whose material
  // index is `index` in particles.props; throws InputError when a value is inadmissible.
  virtual void initialize(Particles& particles, int index) const = 0;

  // P(F) and A = dP/dF for the particles whose material index is `index`; others untouched.
  virtual void firstPiola(const Particles& particles, const Tensors& F, int index, Tensors& P,
                          Tangents& A) const = 0;

  // Strain energy per unit reference volume W(F) for the particles of this material (for
  // the energy history; 1-D: per unit reference length and section).
  virtual void energyDensity(const Particles& particles, const Tensors& F, int index,
                             typename Particles::Scalars& W) const = 0;

  // Out-of-plane Cauchy stress sigma_zz of the particles of this material (2-D plane
  // strain; output only).  Laws without one leave it untouched.
  virtual void outOfPlaneStress(const Particles& /*particles*/, const Tensors& /*F*/, int /*index*/,
                                typename Particles::Scalars& /*stressZZ*/) const {}

  // True when P is affine in F (then a total-Lagrangian, or 1-D, step is a linear system).
  virtual bool isLinear() const { return false; }

  // Largest small-strain modulus over this material's particles (for wave speeds).
  virtual double maxModulus(const Particles& particles, int index) const = 0;

 private:
  std::string name_;
  double density_;
};

}  // namespace impm

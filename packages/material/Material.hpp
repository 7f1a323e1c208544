#pragma once
// A constitutive model treated as a black box (primer 1.3-1.4): given the deformation
// gradient F of each of its particles, and the state its particles carry from the last
// accepted step, it returns the first Piola-Kirchhoff stress P, its tangent A = dP/dF and the
// trial state at the end of the step.  The framework never assumes Hooke's law; everything
// it needs from the material goes through this interface.
//
// A law declares the per-particle variables it owns (variables()): two-level state such as
// a plastic strain (twoLevels: read at n, written as a trial value, committed by the
// framework when the step is accepted and dropped on a cutback) and parameters such as a
// modulus E(X_p) that it computes once (initialize()).  The framework stores them in the
// particle set, which migrates, writes and checkpoints them as their FieldSpec says; the
// law sees them as tables in the order it declared them.  doc/design.md walks through
// adding a law with state.
//
// In 1-D, F = dx/dX = 1 + eps with eps the engineering strain, and P is the axial force per
// unit (reference) section: a law sigma = xi(eps, x) of the primer is P = xi(F - 1, X).

#include <memory>
#include <string>
#include <vector>

#include "core/ParticleSet.hpp"

namespace impm {

// E = mu (3 lambda + 2 mu) / (lambda + mu), Young's modulus from Lame's constants.
inline double youngFromLame(double lambda, double mu) {
  return mu * (3.0 * lambda + 2.0 * mu) / (lambda + mu);
}

template <int Dim, class Space = DefaultExecSpace>
class Material {
 public:
  static constexpr int dimension = Dim;
  using ExecutionSpace = Space;  // where the law's kernels run
  using Particles = ParticleSet<Dim, Space>;
  using Scalars = typename Particles::Scalars;
  using Tensors = typename Particles::Tensors;
  using Table = typename Particles::Table;
  using Members = typename Particles::Indices;
  using Tangents = Kokkos::View<double* [Dim][Dim][Dim][Dim], typename Space::memory_space>;

  // A per-particle variable of the law, with the values it starts from (one per component;
  // empty: zeros).  Several materials may declare the same variable (a plastic strain); it is
  // then one field, and each material owns it on its own particles.
  struct Variable {
    FieldSpec spec;
    std::vector<double> initial;
  };

  // What one evaluation works on: the material's particles (indices into the fields), the
  // deformation gradient to evaluate at, the values of the law's variables in declaration
  // order (two-level ones at the last accepted step) and, for each two-level variable in
  // declaration order, the trial table the law writes.  The law reads and writes rows p =
  // members(i) only.
  struct Evaluation {
    const Particles& particles;
    Members members;
    Tensors F;
    std::vector<Table> variables;
    std::vector<Table> trial;
  };

  Material(std::string name, double density) : name_(std::move(name)), density_(density) {}
  virtual ~Material() = default;

  const std::string& name() const { return name_; }
  double density() const { return density_; }

  virtual std::vector<Variable> variables() const { return {}; }

  // Computes the parameters the law stores per particle (E(X_p), ...) for its particles;
  // throws InputError when a value is inadmissible.  Called at the start and at a restart.
  virtual void initialize(const Evaluation& /*at*/) const {}

  // P(F) and A = dP/dF, and the trial state, for the material's particles; others untouched.
  // Throws NumericalError when F is outside the law's domain.
  virtual void firstPiola(const Evaluation& at, Tensors& P, Tangents& A) const = 0;

  // Strain energy per unit reference volume W(F, state) (for the energy history; 1-D: per
  // unit reference length and section).
  virtual void energyDensity(const Evaluation& at, Scalars& W) const = 0;

  // Energy dissipated per unit reference volume since the start (plastic work that is not
  // stored), from the committed state; history-free laws dissipate nothing and leave D.
  virtual void dissipationDensity(const Evaluation& /*at*/, Scalars& /*D*/) const {}
  // True when dissipationDensity computes something (false: the energy history skips it).
  virtual bool dissipates() const { return false; }

  // Out-of-plane Cauchy stress sigma_zz (2-D plane strain; output only).  Laws without one
  // leave it untouched.
  virtual void outOfPlaneStress(const Evaluation& /*at*/, Scalars& /*stressZZ*/) const {}

  // The step was accepted: the trial state becomes the state.  The default copies every
  // two-level variable; a law that keeps more (a hardening history) overrides it.
  virtual void commit(const Evaluation& at) const;

  // True when P is affine in F (then a total-Lagrangian, or 1-D, step is a linear system).
  virtual bool isLinear() const { return false; }
  // True when the tangent has major symmetry, A_iJkL = A_kLiJ, as every hyperelastic law's
  // (P = dW/dF): the 2-D stiffness is then symmetric and CG solves it.
  virtual bool hasSymmetricTangent() const { return false; }

  // Largest small-strain modulus over this material's particles (for wave speeds).
  virtual double maxModulus(const Evaluation& at) const = 0;
  // The modulus that scales the ghost penalty: Young's modulus where the law has one.  The
  // P-wave modulus lambda + 2 mu grows without bound as nu -> 1/2, and the penalty scaled by
  // it locked a nearly incompressible body (e_u 0.22 against 1.7e-3 on Lame's cylinder at
  // nu = 0.4999 with F-bar).  The default, for laws with one modulus, is maxModulus.
  virtual double youngModulus(const Evaluation& at) const { return maxModulus(at); }

 private:
  std::string name_;
  double density_;
};

// out(p) = value(p) for the evaluated particles p = members(i): the kernel of every
// per-particle scalar a law reports (its energy, its dissipation, sigma_zz), value being the
// law's own formula.
template <class Space, class Members, class Scalars, class Value>
void setForMembers(const char* label, const Members& members, const Scalars& out,
                   const Value& value) {
  Kokkos::parallel_for(
      label, RangePolicy<Space>(0, members.extent(0)), KOKKOS_LAMBDA(const int i) {
        const int p = members(i);
        out(p) = value(p);
      });
}

template <int Dim, class Space>
void Material<Dim, Space>::commit(const Evaluation& at) const {
  const auto declared = variables();
  std::size_t k = 0;
  for (std::size_t j = 0; j < declared.size(); ++j) {
    if (!declared[j].spec.twoLevels)
      continue;
    const Table n = at.variables.at(j), trial = at.trial.at(k++);
    const auto members = at.members;
    const int width = static_cast<int>(n.extent(1));
    Kokkos::parallel_for(
        "impm::commitState", RangePolicy<Space>(0, members.extent(0)), KOKKOS_LAMBDA(const int i) {
          const int p = members(i);
          for (int c = 0; c < width; ++c)
            n(p, c) = trial(p, c);
        });
  }
}

}  // namespace impm

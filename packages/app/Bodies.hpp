#pragma once
// Bodies from the deck, turned into integration points: material points filling the body
// (mpm, gimp, cpdi) or Gauss points of the grid cells inside the body (fem).  Every rank
// generates the same global list (so particle ids do not depend on the number of ranks)
// and keeps the points that lie in its cells.

#include <Teuchos_ParameterList.hpp>

#include <algorithm>
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "app/shapes/Shape.hpp"
#include "basis/Method.hpp"
#include "core/Decomposition.hpp"
#include "core/Formula.hpp"
#include "material/MaterialState.hpp"

namespace impm {

Teuchos::ParameterList bodyValidParameters();

// Vector quantities have one formula per component.  Formula variables: 1-D x, X, t; 2-D
// x, y, X, Y, t (current and reference position, time).
template <int Dim>
struct Body {
  std::string name;
  int material = 0;  // index into the deck's Materials
  std::shared_ptr<const Shape<Dim>> shape;
  int particlesPerCell = 2;
  Formula section;                        // 1-D: A(x); 2-D: 1 (plane strain, unit thickness)
  Formula load;                           // 1-D distributed load f(x, X, t), per unit length
  std::array<Formula, Dim> bodyForce;     // body force b(x, X, t), per unit mass
  std::array<Formula, Dim> velocity;      // initial velocity v(x, X)
  std::array<Formula, Dim> displacement;  // initial displacement u0(X)
};

template <int Dim>
class Bodies {
 public:
  // Reads and checks Bodies/<name>; material names resolve to indices.  Throws InputError.
  Bodies(const Teuchos::ParameterList& deck, const std::vector<std::string>& materialNames,
         const GridGeometry<Dim>& grid);

  const std::vector<Body<Dim>>& list() const { return bodies_; }
  // Index of the body called `name`, or -1.
  int find(const std::string& name) const;

  // The integration points of every body that lie on `rank`, with the initial velocity, in
  // the order of their ids.  `displaced`: they also take the initial displacement
  // (x = X + u0, F = 1 + grad u0); otherwise the stepper applies it through the grid (total
  // Lagrangian).
  ParticleSet<Dim> createParticles(Method method, const Decomposition<Dim>& decomposition, int rank,
                                   const Materials<Dim>& materials, bool displaced) const;

  // Declares the fields of domains with corners (current and reference corners, side-set
  // face masks) when a body comes from a mesh and the method has particles; every particle
  // then carries corners (those of its parallelogram for the other bodies).  createParticles
  // calls it; a restart calls it on the empty set the checkpoint fills.
  void declareFields(ParticleSet<Dim>& particles, Method method) const;
  // True when the particles carry corners (declareFields declares them).
  bool hasCorners(Method method) const;

  // The initial displacement and velocity at node position x: those of the body that holds
  // x, or else of the nearest body (FEM's nodal initial conditions).
  void initialNodalState(const double* x, double* u, double* v) const;

  // Body names usable in column headers (spaces become underscores).
  std::vector<std::string> columnNames() const;

  // Sets particles.force to the loads at `time`: the distributed load (per unit length)
  // times the particle's length plus its mass times the body force (per unit mass).  Only
  // this sets the forces; `particles` is the same set at every call.
  void applyLoads(ParticleSet<Dim>& particles, double time);
  // Whether applyLoads reads the particles' positions (a load given as a formula).
  bool loadsReadPositions() const;

 private:
  // The corners of particle p, from seed k of `shape`.
  static void placeCorners(const ParticleSet<Dim, Kokkos::DefaultHostExecutionSpace>& ps,
                           std::size_t p, const Shape<Dim>& shape, std::size_t k,
                           const Seed<Dim>& seed, const double F[Dim][Dim]);

  // A body's loads when given as numbers (the common case, and zero when not given).
  struct ConstantLoads {
    bool all = true;  // false: a formula, or a value that is not finite
    double bodyForce[Dim] = {}, load = 0.0;
    bool operator==(const ConstantLoads& o) const {
      return all == o.all && load == o.load && std::equal(bodyForce, bodyForce + Dim, o.bodyForce);
    }
  };
  std::vector<ConstantLoads> constantLoads() const;

  GridGeometry<Dim> grid_;
  std::vector<Body<Dim>> bodies_;
  // The loads of the last applyLoads when every body's were numbers without a distributed
  // load (whose force scales with the particle's length); empty otherwise.
  std::vector<ConstantLoads> applied_;
};

}  // namespace impm

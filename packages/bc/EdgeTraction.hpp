#pragma once
// A load on part of a 2-D body's boundary, on the faces of the particle domains that lie on
// it: a dead traction t (force per unit reference length, plane strain per unit thickness)
// and a pressure p against the face's outward normal, per unit length of the reference or
// of the current face.  A face of a domain (corners c1, c2, counter-clockwise: the tracked
// corners of a mesh element, or the parallelogram x_p -+ r_1 -+ r_2) adds
//   f_i -= lambda (t L0 - p n L) (N_i(c1) + N_i(c2)) / 2,
// the trapezoidal rule of the integral of N_i over the face, which is the integral of the
// alternative basis of CPDI (linear between the corners) and exact for the tents on a face
// along a grid line.  lambda is the load factor of static load steps; n L is the outward
// normal times the length of the reference face or of the current face, at the Newton
// iterate (a follower load: its derivative is left out of the Jacobian, so Newton converges
// linearly, at a rate of about p / E, instead of quadratically).
//
// The loaded faces are either those of a side set of a mesh body (the bit of the particle's
// face mask), or the exposed faces inside a box: a face is exposed when the point just beyond
// its midpoint is outside the body's shape (an image body's stair-stepped boundary next to
// empty pixels).  Both are found in the reference configuration.

#include <Teuchos_ParameterList.hpp>

#include <array>
#include <functional>
#include <string>
#include <tuple>
#include <vector>

#include <tuple>
#include <vector>
#include "assembly/Kinematics.hpp"
#include "core/Formula.hpp"

#include "solver/Contribution.hpp"

namespace impm {

class EdgeTraction : public Contribution<2> {
 public:
  static Teuchos::ParameterList validParameters();

  // body: index of the body the traction acts on; inside: whether a point lies in the
  // body's reference shape; sideSet: the bit of the side set to load, or -1 (exposed faces).
  // initialLoadFactor: the load factor before the first step (0 in static runs, 1 otherwise).
  EdgeTraction(const std::string& name, const Teuchos::ParameterList& params, int body,
               std::function<bool(const double*)> inside, int sideSet, Kinematics kinematics,
               double initialLoadFactor);

  void addResidual(const ContributionContext<2>& ctx, const HostValues& x,
                   const HostValuesMutable& f) const override;
  // The step's work: each face end's share of the face force, averaged between the start and
  // the end of the step (the trapezoidal rule, as the body forces' work), times the end's
  // displacement increment.  The forces and the ends' nodes are those of the last residual
  // (Newton's, at the solution): by commit the particles, and so the faces, have moved.
  // Collective.
  void commit(const ContributionContext<2>& ctx, const HostValues& x) override;
  double work() const override { return work_; }
  std::vector<double> state() const override { return {committedTime_, committedLoad_, work_}; }
  void restore(const std::vector<double>& state) override;

 private:
  using HostParticles = ParticleSet<2, Kokkos::DefaultHostExecutionSpace>;
  // f(particle id, the face's ends in the map's configuration and at the start of the step,
  // its reference midpoint, normal and length) for every loaded face on this rank.
  template <class Fn>
  void forEachLoadedFace(const ContributionContext<2>& ctx, Fn&& f) const;
  static bool hasBit(double mask, int bit);
  // Whether face k of particle p, with reference midpoint mid and outward normal n0, is loaded.
  // faces: the particles' side-set masks (empty without Side Set).
  bool loaded(const HostParticles::Table& faces, std::size_t p, int k, const double mid[2],
              const double n0[2]) const;
  // The face's load (force on the whole face) at reference midpoint mid.
  void faceForce(const double mid[2], const double refNormal[2], const double nowNormal[2],
                 double length0, double time, double force[2]) const;

  std::string name_;
  int body_;
  std::function<bool(const double*)> inside_;
  int sideSet_;
  Kinematics kinematics_;
  std::array<double, 4> box_;
  std::array<Formula, 2> traction_;
  Formula pressure_;
  bool currentFace_ = false;
  double committedTime_ = 0.0, committedLoad_, work_ = 0.0;  // at the last commit
  // Each loaded face end of the last residual: its nodes' (overlap index, component, N) and
  // its share of the step's mean force.
  struct LoadedEnd {
    std::vector<std::tuple<LO, int, double>> nodes;
    double force[2] = {0.0, 0.0};
  };
  mutable std::vector<LoadedEnd> ends_;
};

}  // namespace impm

#include "bc/EdgeTraction.hpp"

#include <cmath>
#include <string>

#include <Teuchos_CommHelpers.hpp>
#include <sstream>

#include "basis/BuildMap.hpp"
#include "basis/CornerWeights.hpp"
#include "basis/Tent.hpp"
#include "core/Errors.hpp"
#include "core/Parameters.hpp"

namespace impm {

namespace {

const char* const kFaces[2] = {"reference", "current"};

// The corners of particle p's domain, counter-clockwise: in the reference configuration,
// where the step's map was built (the tents are evaluated there), and at the start of the
// step: the tracked corners, or the parallelogram X -+ r01 -+ r02 moved by x_p and F_p.
struct DomainCorners {
  double ref[4][2], map[4][2], start[4][2];
};

// The domains of a particle set, with the corner tables looked up once (not per face).
class DomainGeometry {
 public:
  using Host = ParticleSet<2, Kokkos::DefaultHostExecutionSpace>;
  DomainGeometry(const Host& host, bool total) : host_(host), total_(total) {
    tracked_ = host.has(kCornersField);
    if (tracked_)
      then_ = host.values(kReferenceCornersField), now_ = host.values(kCornersField);
  }

  DomainCorners operator()(std::size_t p) const {
    DomainCorners c;
    const double sign[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (int k = 0; k < 4; ++k) {
      if (tracked_) {
        for (int d = 0; d < 2; ++d)
          c.ref[k][d] = then_(p, 2 * k + d), c.start[k][d] = now_(p, 2 * k + d);
      } else {
        double half[2];
        for (int d = 0; d < 2; ++d) {
          half[d] = sign[k][0] * host_.domain0(p, d, 0) + sign[k][1] * host_.domain0(p, d, 1);
          c.ref[k][d] = host_.X(p, d) + half[d];
        }
        for (int d = 0; d < 2; ++d)
          c.start[k][d] = host_.x(p, d) + host_.F(p, d, 0) * half[0] + host_.F(p, d, 1) * half[1];
      }
      for (int d = 0; d < 2; ++d)
        c.map[k][d] = total_ ? c.ref[k][d] : c.start[k][d];
    }
    return c;
  }

 private:
  const Host& host_;
  bool total_, tracked_ = false;
  Host::Table then_, now_;
};

// Outward normal times length of the counter-clockwise edge a -> b.
void edgeNormal(const double a[2], const double b[2], double n[2]) {
  n[0] = b[1] - a[1], n[1] = a[0] - b[0];
}

// f(overlap index of component a, a, N_i) for the grid nodes around a face's end at `at`
// (where the step's map was built); throws when the map does not reach a node.
template <class Fn>
void forEachEndNode(const ContributionContext<2>& ctx, const double at[2], GlobalId particle,
                    const std::string& name, Fn&& f) {
  const auto& grid = ctx.grid;
  double g[2];
  int cell[2];
  for (int d = 0; d < 2; ++d) {
    g[d] = clipToGrid(grid, d, grid.gridCoord(d, at[d]));
    cell[d] = std::min(grid.cells[d] - 1, std::max(0, static_cast<int>(std::floor(g[d]))));
  }
  for (int j = 0; j <= 1; ++j)
    for (int i = 0; i <= 1; ++i) {
      const int node[2] = {cell[0] + i, cell[1] + j};
      // The map's threshold: a face end on a grid line up to round-off reaches the next
      // node by a weight the map drops as round-off, and so must the load.
      const double N = tent(g[0] - node[0]) * tent(g[1] - node[1]);
      if (N <= kNegligibleWeight)
        continue;
      const GlobalId nodeId = grid.nodeId(node);
      for (int a = 0; a < 2; ++a) {
        const LO lid = ctx.dofs.overlapMap()->getLocalElement(ctx.dofs.nodeDof(nodeId, a));
        if (lid == Teuchos::OrdinalTraits<LO>::invalid()) {
          std::ostringstream msg;
          msg << "Boundary Conditions/" << name << ": a loaded face of particle " << particle
              << " reaches grid node " << nodeId
              << ", which no integration point reaches (classic mpm's points: use gimp or "
                 "cpdi; gimp's boxes on a mesh body, which do not tile it: use cpdi, whose "
                 "domains are the elements)";
          throw NumericalError(msg.str());
        }
        f(lid, a, N);
      }
    }
}

}  // namespace

bool EdgeTraction::hasBit(double mask, int bit) {
  return (static_cast<long long>(mask) >> bit) & 1LL;
}

Teuchos::ParameterList EdgeTraction::validParameters() {
  Teuchos::ParameterList valid;
  declareDoubleArray(valid, "Region", {-1e300, 1e300, -1e300, 1e300}, {4},
                     "2-D: xmin, xmax, ymin, ymax of the box holding the loaded part of the "
                     "boundary, in the reference configuration (edges included); default: "
                     "everywhere",
                     Bounds::any());
  declareString(valid, "Side Set", "",
                "2-D: a side set of the body's mesh (its name, or its id where the file names "
                "none): the loaded faces; empty: the faces exposed to empty space in Region");
  for (const char* c : {"x", "y"})
    declareFormula(valid, std::string("Traction ") + c, "0", {"x", "y", "t"},
                   std::string("2-D: ") + c +
                       " component of the traction, force per unit "
                       "reference length (a dead load), a formula of the reference position x, y "
                       "and time t; ramped with the load factor in static load steps");
  declareFormula(valid, "Pressure", "0", {"x", "y", "t"},
                 "2-D: pressure on the faces (positive: pushing into the body), a formula of the "
                 "reference position x, y and time t; ramped with the load factor in static load "
                 "steps");
  declareChoice(valid, "Pressure Face", "reference", {kFaces[0], kFaces[1]},
                "2-D: the face whose normal and length the pressure acts on: reference (a dead "
                "load) or current (a follower load, the face as it is at the start of each "
                "step)");
  return valid;
}

EdgeTraction::EdgeTraction(const std::string& name, const Teuchos::ParameterList& params, int body,
                           std::function<bool(const double*)> inside, int sideSet,
                           Kinematics kinematics, double initialLoadFactor)
    : name_(name),
      body_(body),
      inside_(std::move(inside)),
      sideSet_(sideSet),
      kinematics_(kinematics),
      committedLoad_(initialLoadFactor) {
  const std::string path = "Boundary Conditions/" + name + "/";
  const auto& region = params.get<Teuchos::Array<double>>("Region");
  for (int k = 0; k < 4; ++k)
    box_[k] = region[k];
  if (!(box_[0] <= box_[1] && box_[2] <= box_[3]))
    throw InputError(path + "Region", "needs xmin <= xmax and ymin <= ymax");
  const auto formula = [&](const std::string& p) {
    try {
      return Formula(formulaText(params, p), {"x", "y", "t"});
    } catch (const InputError& e) {
      throw InputError(path + p, e.what());
    }
  };
  traction_ = {formula("Traction x"), formula("Traction y")};
  pressure_ = formula("Pressure");
  currentFace_ = params.get<std::string>("Pressure Face") == kFaces[1];
}

void EdgeTraction::faceForce(const double mid[2], const double refNormal[2],
                             const double nowNormal[2], double length0, double time,
                             double force[2]) const {
  const double p = pressure_(mid[0], mid[1], time);
  const double* n = currentFace_ ? nowNormal : refNormal;
  for (int a = 0; a < 2; ++a)
    force[a] = traction_[a](mid[0], mid[1], time) * length0 - p * n[a];
}

bool EdgeTraction::loaded(const HostParticles::Table& faces, std::size_t p, int k,
                          const double mid[2], const double n0[2]) const {
  const double tol = 1e-9;
  if (mid[0] < box_[0] - tol || mid[0] > box_[1] + tol || mid[1] < box_[2] - tol ||
      mid[1] > box_[3] + tol)
    return false;
  if (sideSet_ >= 0)
    return hasBit(faces(p, k), sideSet_);
  const double beyond[2] = {mid[0] + 1e-6 * n0[0], mid[1] + 1e-6 * n0[1]};
  return !inside_(beyond);
}

template <class Fn>
void EdgeTraction::forEachLoadedFace(const ContributionContext<2>& ctx, Fn&& f) const {
  const auto host = ctx.particles.mirror(Kokkos::DefaultHostExecutionSpace());
  const DomainGeometry domains(host, kinematics_ == Kinematics::totalLagrangian);
  const HostParticles::Table faces =
      sideSet_ >= 0 ? host.values(kFacesField) : HostParticles::Table();
  for (std::size_t p = 0; p < host.size(); ++p) {
    if (host.body(p) != body_)
      continue;
    const DomainCorners c = domains(p);
    for (int k = 0; k < 4; ++k) {
      const int ends[2] = {k, (k + 1) % 4};
      const double *a0 = c.ref[ends[0]], *b0 = c.ref[ends[1]];
      double n0[2];
      edgeNormal(a0, b0, n0);
      const double length0 = std::hypot(n0[0], n0[1]);
      const double mid[2] = {0.5 * (a0[0] + b0[0]), 0.5 * (a0[1] + b0[1])};
      if (length0 == 0.0 || !loaded(faces, p, k, mid, n0))  // 0: a triangle's collapsed edge
        continue;
      const double* map[2] = {c.map[ends[0]], c.map[ends[1]]};
      const double* start[2] = {c.start[ends[0]], c.start[ends[1]]};
      f(host.id(p), map, start, mid, n0, length0);
    }
  }
}

namespace {

// The face's ends at the start of the step moved by the increment x (`moved`), and each
// end's increment (`du`).
void movedEnds(const ContributionContext<2>& ctx, const HostValues& x, const double* const map[2],
               const double* const start[2], GlobalId particle, const std::string& name,
               double moved[2][2], double du[2][2]) {
  for (int e = 0; e < 2; ++e) {
    du[e][0] = du[e][1] = 0.0;
    forEachEndNode(ctx, map[e], particle, name,
                   [&](LO lid, int a, double N) { du[e][a] += N * x(lid, 0); });
    for (int d = 0; d < 2; ++d)
      moved[e][d] = start[e][d] + du[e][d];
  }
}

}  // namespace

void EdgeTraction::addResidual(const ContributionContext<2>& ctx, const HostValues& x,
                               const HostValuesMutable& f) const {
  ends_.clear();
  forEachLoadedFace(
      ctx, [&](GlobalId particle, const double* const map[2], const double* const start[2],
               const double mid[2], const double n0[2], double length0) {
        double now[2][2], du[2][2], n[2], nStart[2], force[2], before[2];
        movedEnds(ctx, x, map, start, particle, name_, now, du);
        edgeNormal(now[0], now[1], n);
        edgeNormal(start[0], start[1], nStart);
        faceForce(mid, n0, n, length0, ctx.time, force);
        faceForce(mid, n0, nStart, length0, committedTime_, before);
        for (int e = 0; e < 2; ++e) {
          LoadedEnd end;
          for (int a = 0; a < 2; ++a)
            end.force[a] = 0.25 * (committedLoad_ * before[a] + ctx.loadFactor * force[a]);
          forEachEndNode(ctx, map[e], particle, name_, [&](LO lid, int a, double N) {
            f(lid, 0) -= ctx.loadFactor * force[a] * 0.5 * N;
            end.nodes.push_back({lid, a, N});
          });
          ends_.push_back(std::move(end));
        }
      });
}

void EdgeTraction::commit(const ContributionContext<2>& ctx, const HostValues& x) {
  double work = 0.0;
  for (const LoadedEnd& end : ends_)
    for (const auto& [lid, a, N] : end.nodes)
      work += end.force[a] * N * x(lid, 0);
  double total = 0.0;
  Teuchos::reduceAll(*ctx.dofs.ownedMap()->getComm(), Teuchos::REDUCE_SUM, work,
                     Teuchos::outArg(total));
  work_ += total;
  committedTime_ = ctx.time;
  committedLoad_ = ctx.loadFactor;
  ends_.clear();
}

void EdgeTraction::restore(const std::vector<double>& state) {
  if (state.size() != 3)
    throw std::invalid_argument("a traction's state has 3 values, not " +
                                std::to_string(state.size()));
  committedTime_ = state[0], committedLoad_ = state[1], work_ = state[2];
}

}  // namespace impm

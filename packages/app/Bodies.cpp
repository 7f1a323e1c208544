#include "app/Bodies.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

#include "app/shapes/ShapeFactory.hpp"
#include "basis/CornerWeights.hpp"
#include "core/Axes.hpp"
#include "core/Diagnostics.hpp"
#include "core/Errors.hpp"
#include "core/Parameters.hpp"
#include "core/Tensor.hpp"

namespace impm {

namespace {

const std::vector<std::string> kVariables1D = {"x", "X", "t"};

// The formula variables of a Dim-D deck: current position, reference position, time.
template <int Dim>
const std::vector<std::string>& variables() {
  static const std::vector<std::string> names = positionTimeVariables<Dim>();
  return names;
}

// Values in the order of variables<Dim>().
template <int Dim>
std::array<double, 2 * Dim + 1> arguments(const double* x, const double* X, double t) {
  return positionTimeArguments<Dim>(x, X, t);
}

}  // namespace

Teuchos::ParameterList bodyValidParameters() {
  Teuchos::ParameterList valid;
  declareString(valid, "Material", "steel", "Name of the body's material (a Materials sublist)",
                true);
  declareShapeParameters(valid);
  declareInt(valid, "Particles Per Cell", 2,
             "Material points per grid cell and direction (mpm, gimp, cpdi): 2-D bodies get "
             "n x n per cell, at the centres of the sub-cells that lie in the shape; fem always "
             "uses 2 Gauss points per cell and direction",
             Bounds::atLeast(1));
  declareFormula(valid, "Section", "1", {"x"},
                 "1-D: cross-section area A(x) at the reference position x", Bounds::positive());
  declareFormula(valid, "Distributed Load", "0", kVariables1D,
                 "1-D: distributed load f (force per unit length, primer eq. 1.1) at current "
                 "position x, reference position X and time t");
  const struct {
    const char* name;
    const char* doc;
  } vectors[] = {
      {"Initial Velocity", "initial velocity (t = 0)"},
      {"Initial Displacement",
       "initial displacement u0 (a function of the reference position); particles start at "
       "X + u0 with F = I + grad u0 (centred differences of the formula)"},
      {"Body Force",
       "force per unit mass b (gravity, manufactured loads); adds m_p b to each particle"}};
  for (const auto& v : vectors) {
    declareFormula(valid, v.name, "0", kVariables1D,
                   std::string("1-D: ") + v.doc + ", a formula of x, X, t");
    for (int d = 0; d < 3; ++d)
      declareFormula(
          valid, std::string(v.name) + " " + axisName(d), "0", anyPositionTimeVariables(),
          std::string(d < 2 ? "2-D and 3-D: " : "3-D: ") + axisName(d) + " component of the " +
              v.doc + ", a formula of x, y, X, Y, t (and z, Z in 3-D)");
  }
  return valid;
}

namespace {

// A formula parameter of Bodies/<name>; errors name the parameter.
Formula readFormula(const Teuchos::ParameterList& p, const std::string& name,
                    const std::vector<std::string>& vars, const std::string& path) {
  try {
    return Formula(formulaText(p, name), vars);
  } catch (const InputError& e) {
    throw InputError(path + "/" + name, e.what());
  }
}

// Vector formula: "Name" in 1-D, "Name x", "Name y" (, "Name z") in 2-D (3-D); a deck that
// gives a form of another dimension (even as "0") is told which forms its grid takes.
template <int Dim>
std::array<Formula, Dim> readVector(const Teuchos::ParameterList& p, const std::string& name,
                                    const std::string& path) {
  std::array<Formula, Dim> f;
  std::vector<std::string> unused;
  if (Dim > 1)
    unused.push_back(name);
  for (int d = Dim == 1 ? 0 : Dim; d < 3; ++d)
    unused.push_back(name + " " + axisName(d));
  const std::string own =
      Dim == 1 ? "'" + name + "'" : "'" + name + " x' to '" + name + " " + axisName(Dim - 1) + "'";
  for (const auto& other : unused)
    if (setInDeck(p, other))
      throw InputError(path + "/" + other, "is not for this deck's " + std::to_string(Dim) +
                                               "-D grid (use " + own + ")");
  for (int d = 0; d < Dim; ++d)
    f[d] = readFormula(p, Dim == 1 ? name : name + " " + axisName(d), variables<Dim>(), path);
  return f;
}

// x_p = X_p + u0(X_p), F_p = I + grad u0 by centred differences of the formulas.
template <int Dim>
void initialDisplacement(const Body<Dim>& b, const double* X, double* u, double F[Dim][Dim]) {
  for (int a = 0; a < Dim; ++a) {
    u[a] = b.displacement[a](arguments<Dim>(X, X, 0.0));
    for (int c = 0; c < Dim; ++c) {
      double Xp[Dim], Xm[Dim];
      std::copy(X, X + Dim, Xp), std::copy(X, X + Dim, Xm);
      const double delta = 1e-6 * std::max(1.0, std::abs(X[c]));
      Xp[c] += delta, Xm[c] -= delta;
      F[a][c] = (a == c ? 1.0 : 0.0) + (b.displacement[a](arguments<Dim>(Xp, Xp, 0.0)) -
                                        b.displacement[a](arguments<Dim>(Xm, Xm, 0.0))) /
                                           (2 * delta);
    }
  }
}

}  // namespace

template <int Dim>
Bodies<Dim>::Bodies(const Teuchos::ParameterList& deck,
                    const std::vector<std::string>& materialNames, const GridGeometry<Dim>& grid)
    : grid_(grid) {
  const auto& list = deck.sublist("Bodies");
  for (auto it = list.begin(); it != list.end(); ++it) {
    const std::string& name = list.name(it);
    const auto& p = list.sublist(name);
    const std::string path = "Bodies/" + name;
    Body<Dim> b;
    b.name = name;
    const auto& material = p.get<std::string>("Material");
    b.material = -1;
    for (std::size_t m = 0; m < materialNames.size(); ++m)
      if (materialNames[m] == material)
        b.material = static_cast<int>(m);
    if (b.material < 0)
      throw InputError(path + "/Material", "no material called '" + material + "' in Materials");
    b.shape = createShape<Dim>(p, path);
    for (int d = 0; d < Dim; ++d) {
      const double tol = 1e-12 * grid.spacing[d];
      const double lo = b.shape->lower()[d], hi = b.shape->upper()[d];
      if (lo < grid.origin[d] - tol || hi > grid.upper(d) + tol) {
        std::ostringstream msg;
        msg << "the body [" << lo << ", " << hi << "] reaches outside the grid [" << grid.origin[d]
            << ", " << grid.upper(d) << "]";
        if (Dim > 1)
          msg << " along " << axisName(d);
        throw InputError(path + "/" + b.shape->placement(), msg.str());
      }
    }
    b.particlesPerCell = p.get<int>("Particles Per Cell");
    if (Dim == 1) {
      b.section = readFormula(p, "Section", {"x"}, path);
      b.load = readFormula(p, "Distributed Load", kVariables1D, path);
    } else {
      for (const char* one : {"Section", "Distributed Load"})
        if (setInDeck(p, one))
          throw InputError(path + "/" + one, Dim == 2
                                                 ? "is for 1-D bars; 2-D bodies are plane strain "
                                                   "with unit thickness (use Body Force x, y)"
                                                 : "is for 1-D bars (use Body Force x, y, z)");
      b.section = Formula(1.0);
      b.load = Formula(0.0);
    }
    b.bodyForce = readVector<Dim>(p, "Body Force", path);
    b.velocity = readVector<Dim>(p, "Initial Velocity", path);
    b.displacement = readVector<Dim>(p, "Initial Displacement", path);
    bodies_.push_back(std::move(b));
  }
  if (bodies_.empty())
    throw InputError("Bodies", "the deck defines no body");
}

template <int Dim>
int Bodies<Dim>::find(const std::string& name) const {
  for (std::size_t b = 0; b < bodies_.size(); ++b)
    if (bodies_[b].name == name)
      return static_cast<int>(b);
  return -1;
}

template <int Dim>
bool Bodies<Dim>::hasCorners(Method method) const {
  if (!isParticleMethod(method))
    return false;
  for (const auto& b : bodies_)
    if (b.shape->hasCorners())
      return true;
  return false;
}

template <int Dim>
void Bodies<Dim>::declareFields(ParticleSet<Dim>& particles, Method method) const {
  if (!hasCorners(method))
    return;
  FieldSpec corners;
  corners.name = kCornersField;
  corners.shape = FieldShape::corners;
  corners.doc = "2-D: the corners of the particle domain, counter-clockwise (mesh bodies)";
  corners.columns = defaultColumns<Dim>("c", FieldShape::corners);
  for (auto& c : corners.columns)
    c.exodus.clear();  // drawn by the domain file, not element variables
  FieldSpec reference = corners;
  reference.name = kReferenceCornersField;
  reference.doc = "2-D: the reference corners of the particle domain (mesh bodies)";
  reference.columns = defaultColumns<Dim>("c0", FieldShape::corners);
  for (auto& c : reference.columns)
    c.exodus.clear();
  FieldSpec faces;
  faces.name = kFacesField;
  faces.shape = FieldShape::faces;
  faces.doc = "bit k set: the domain's face lies on side set k of its mesh";
  for (const auto& spec : {corners, reference, faces})
    particles.declare(spec);
}

namespace {

// The reference corners of a seed's parallelogram x -+ r_1 -+ r_2, counter-clockwise.
template <int Dim>
void parallelogramCorners(const Seed<Dim>& seed, double corner[1 << Dim][Dim]) {
  for (int c = 0; c < (1 << Dim); ++c) {
    const int t = CornerWeights<Dim>::stored(c);  // stored <-> tensor: the same swap
    for (int a = 0; a < Dim; ++a) {
      corner[c][a] = seed.x[a];
      for (int k = 0; k < Dim; ++k)
        corner[c][a] += CornerWeights<Dim>::sign(t, k) * seed.half[a][k];
    }
  }
}

}  // namespace

template <int Dim>
ParticleSet<Dim> Bodies<Dim>::createParticles(Method method,
                                              const Decomposition<Dim>& decomposition, int rank,
                                              const Materials<Dim>& materials,
                                              bool displaced) const {
  // Every body's seeds, and which of them this rank keeps (not copied: an image of 16 million
  // pixels has as many seeds, and memory the process touches costs time).
  struct Local {
    GlobalId id;
    int body;
    std::size_t seed;
  };
  std::vector<std::vector<Seed<Dim>>> seedsOf(bodies_.size());
  std::vector<Local> mine;
  GlobalId nextId = 0;
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    auto& seeds = seedsOf[b];
    seeds = bodies_[b].shape->fill(grid_, bodies_[b].particlesPerCell, !isParticleMethod(method));
    if (seeds.empty())
      throw InputError("Bodies/" + bodies_[b].name,
                       "the body holds no integration point (smaller than a sub-cell?)");
    for (std::size_t k = 0; k < seeds.size(); ++k, ++nextId)
      if (decomposition.ownerOfPoint(seeds[k].x) == rank)
        mine.push_back({nextId, static_cast<int>(b), k});
  }
  ParticleSet<Dim> particles(mine.size());
  declareFields(particles, method);
  const bool corners = particles.has(kCornersField);
  auto ps = particles.mirror(Kokkos::DefaultHostExecutionSpace());
  for (std::size_t p = 0; p < mine.size(); ++p) {
    const Body<Dim>& b = bodies_[mine[p].body];
    const Seed<Dim>& seed = seedsOf[mine[p].body][mine[p].seed];
    ps.id(p) = mine[p].id;
    ps.body(p) = mine[p].body;
    ps.material(p) = b.material;
    double X[Dim], u[Dim] = {}, F[Dim][Dim] = {};
    for (int d = 0; d < Dim; ++d)
      X[d] = ps.X(p, d) = seed.x[d], F[d][d] = 1.0;
    ps.section(p) = b.section(seed.x[0]);
    if (!(ps.section(p) > 0))
      throw InputError("Bodies/" + b.name + "/Section", "must be > 0, but is " +
                                                            std::to_string(ps.section(p)) +
                                                            " at x = " + std::to_string(seed.x[0]));
    ps.volume0(p) = seed.volume;
    ps.mass(p) = materials[b.material]->density() * ps.section(p) * seed.volume;
    if (displaced)
      initialDisplacement<Dim>(b, X, u, F);
    const double J = determinant<Dim>(F);
    if (!(J > 0)) {
      std::ostringstream msg;
      msg << "gives det F <= 0 at X = (" << X[0];
      for (int d = 1; d < Dim; ++d)
        msg << ", " << X[d];
      throw InputError("Bodies/" + b.name + "/Initial Displacement", msg.str() + ")");
    }
    ps.volume(p) = J * seed.volume;
    double x[Dim];
    for (int a = 0; a < Dim; ++a) {
      ps.u(p, a) = u[a];
      x[a] = ps.x(p, a) = X[a] + u[a];
      for (int k = 0; k < Dim; ++k) {
        ps.F(p, a, k) = F[a][k];
        ps.domain0(p, a, k) = seed.half[a][k];
        double r = 0.0;  // r_k = F r0_k
        for (int c = 0; c < Dim; ++c)
          r += F[a][c] * seed.half[c][k];
        ps.domain(p, a, k) = r;
      }
    }
    if (corners)
      placeCorners(ps, p, *b.shape, mine[p].seed, seed, F);
    for (int a = 0; a < Dim; ++a)
      ps.v(p, a) = b.velocity[a](arguments<Dim>(x, X, 0.0));
  }
  particles.copyFrom(ps);
  return particles;
}

// x_c = x_p + F (X_c - X_p): the initial displacement is affine over the domain.
template <int Dim>
void Bodies<Dim>::placeCorners(const ParticleSet<Dim, Kokkos::DefaultHostExecutionSpace>& ps,
                               std::size_t p, const Shape<Dim>& shape, std::size_t k,
                               const Seed<Dim>& seed, const double F[Dim][Dim]) {
  const auto& now = ps.values(kCornersField);
  const auto& then = ps.values(kReferenceCornersField);
  const auto& faces = ps.values(kFacesField);
  double corner[1 << Dim][Dim], mask[2 * Dim] = {};
  if (shape.hasCorners())
    shape.seedCorners(k, corner, mask);
  else
    parallelogramCorners<Dim>(seed, corner);
  for (int c = 0; c < (1 << Dim); ++c)
    for (int a = 0; a < Dim; ++a) {
      then(p, c * Dim + a) = corner[c][a];
      double x = ps.x(p, a);
      for (int b = 0; b < Dim; ++b)
        x += F[a][b] * (corner[c][b] - seed.x[b]);
      now(p, c * Dim + a) = x;
    }
  for (int f = 0; f < 2 * Dim; ++f)
    faces(p, f) = mask[f];
}

template <int Dim>
void Bodies<Dim>::initialNodalState(const double* x, double* u, double* v) const {
  std::size_t best = 0;
  double distance = 1e300;
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    const double d = bodies_[b].shape->contains(x) ? -1.0 : bodies_[b].shape->boxDistance(x);
    if (d < distance)
      distance = d, best = b;
  }
  const auto args = arguments<Dim>(x, x, 0.0);
  for (int a = 0; a < Dim; ++a)
    u[a] = bodies_[best].displacement[a](args);
  double current[Dim];
  for (int a = 0; a < Dim; ++a)
    current[a] = x[a] + u[a];
  const auto vargs = arguments<Dim>(current, x, 0.0);
  for (int a = 0; a < Dim; ++a)
    v[a] = bodies_[best].velocity[a](vargs);
}

template <int Dim>
std::vector<std::string> Bodies<Dim>::columnNames() const {
  std::vector<std::string> names;
  for (const auto& b : bodies_) {
    std::string n = b.name;
    for (char& c : n)
      if (c == ' ' || c == ',')
        c = '_';
    names.push_back(n);
  }
  return names;
}

template <int Dim>
std::vector<typename Bodies<Dim>::ConstantLoads> Bodies<Dim>::constantLoads() const {
  std::vector<ConstantLoads> constants(bodies_.size());
  for (std::size_t k = 0; k < bodies_.size(); ++k) {
    const Body<Dim>& b = bodies_[k];
    ConstantLoads& c = constants[k];
    for (int a = 0; a < Dim; ++a)
      c.all = c.all && b.bodyForce[a].isConstant();
    c.all = c.all && (Dim > 1 || b.load.isConstant());
    if (!c.all)
      continue;
    for (int a = 0; a < Dim; ++a)
      c.bodyForce[a] = b.bodyForce[a](std::array<double, 0>{});
    c.load = Dim == 1 ? b.load(std::array<double, 0>{}) : 0.0;
    for (int a = 0; a < Dim; ++a)  // not finite: the general path names the particle
      c.all = c.all && std::isfinite(c.bodyForce[a]);
    c.all = c.all && std::isfinite(c.load);
  }
  return constants;
}

template <int Dim>
bool Bodies<Dim>::loadsReadPositions() const {
  const auto constants = constantLoads();
  return !std::all_of(constants.begin(), constants.end(),
                      [](const ConstantLoads& c) { return c.all; });
}

template <int Dim>
void Bodies<Dim>::applyLoads(ParticleSet<Dim>& particles, double time) {
  // Loads given as numbers need no formula per particle: this runs every step, as often as
  // a residual evaluation in explicit runs.  When they are the numbers of the last call and
  // do not involve a particle's length, the forces set then are still right (a particle's
  // mass does not change, and migration carries the forces along): nothing is done.
  const auto constants = constantLoads();
  const bool fixed = std::all_of(constants.begin(), constants.end(),
                                 [](const ConstantLoads& c) { return c.all && c.load == 0.0; });
  if (fixed && constants == applied_)
    return;
  applied_ = fixed ? constants : std::vector<ConstantLoads>();
  const auto host = particles.mirror(Kokkos::DefaultHostExecutionSpace());
  for (std::size_t p = 0; p < particles.size(); ++p) {
    const ConstantLoads& c = constants[host.body(p)];
    if (c.all) {
      for (int a = 0; a < Dim; ++a)
        host.force(p, a) = host.mass(p) * c.bodyForce[a];
      if constexpr (Dim == 1)
        host.force(p, 0) += c.load * host.volume(p);
      continue;
    }
    const Body<Dim>& b = bodies_[host.body(p)];
    double x[Dim], X[Dim];
    for (int d = 0; d < Dim; ++d)
      x[d] = host.x(p, d), X[d] = host.X(p, d);
    const auto args = arguments<Dim>(x, X, time);
    for (int a = 0; a < Dim; ++a)
      host.force(p, a) = host.mass(p) * b.bodyForce[a](args);
    if constexpr (Dim == 1)
      host.force(p, 0) += b.load(args) * host.volume(p);
    for (int a = 0; a < Dim; ++a)
      if (!std::isfinite(host.force(p, a))) {
        std::ostringstream msg;
        msg << (Dim == 1 ? "the distributed load or the body force" : "the body force")
            << " is not finite at " << particleLabel(host, p) << ", t = " << time;
        throw InputError("Bodies/" + b.name, msg.str());
      }
  }
  Kokkos::deep_copy(particles.force, host.force);
}

template class Bodies<1>;
template class Bodies<2>;
template class Bodies<3>;

}  // namespace impm

#include "app/Bodies.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/Errors.hpp"
#include "core/Parameters.hpp"

namespace impm {

Teuchos::ParameterList bodyValidParameters() {
  Teuchos::ParameterList valid;
  declareString(valid, "Material", "steel", "Name of the body's material (a Materials sublist)",
                true);
  declareChoice(valid, "Shape", "interval", {"interval"}, "Geometry of the body");
  declareInt(valid, "Particles Per Cell", 2,
             "Material points per grid cell and direction (mpm, gimp, cpdi); fem always uses "
             "2 Gauss points per cell and direction",
             Bounds::atLeast(1));
  declareFormula(valid, "Section", "1", {"x"},
                 "1-D: cross-section area A(x) at the reference position x", Bounds::positive());
  declareFormula(valid, "Initial Velocity", "0", {"x", "X"},
                 "1-D: initial velocity at current position x and reference position X");
  declareFormula(valid, "Initial Displacement", "0", {"X"},
                 "1-D: initial displacement u0(X); particles start at X + u0 with F = 1 + u0' "
                 "(a centred difference of the formula)");
  declareFormula(valid, "Body Force", "0", {"x", "X", "t"},
                 "Force per unit mass b (gravity, manufactured loads) at current position x, "
                 "reference position X and time t; adds m_p b to each particle");
  declareFormula(valid, "Distributed Load", "0", {"x", "X", "t"},
                 "1-D: distributed load f (force per unit length, primer eq. 1.1) at current "
                 "position x, reference position X and time t");
  auto& interval = valid.sublist("[Shape=interval]");
  declareDoubleArray(interval, "Extent", {0.0, 1.0}, {2},
                     "1-D: the body occupies [Extent[0], Extent[1]] in the reference "
                     "configuration",
                     Bounds::any(), true);
  return valid;
}

namespace {

struct Point {
  double x, halfLength, volume;
};

// Material points: equal particles filling [a, b], about `perCell` per grid cell.
std::vector<Point> materialPoints(const Body& b, double h) {
  const int n =
      std::max(1, static_cast<int>(std::lround(b.particlesPerCell * (b.upper - b.lower) / h)));
  const double length = (b.upper - b.lower) / n;
  std::vector<Point> points;
  for (int k = 0; k < n; ++k)
    points.push_back({b.lower + (k + 0.5) * length, length / 2, length});
  return points;
}

// Gauss points: two per cell, on the part of each cell inside [a, b] (the cut part of a
// cell that the body's end crosses, so that FEM integrates over the body exactly).
std::vector<Point> gaussPoints(const Body& b, const GridGeometry<1>& g) {
  std::vector<Point> points;
  for (int c = 0; c < g.cells[0]; ++c) {
    const double lo = std::max(b.lower, g.nodeCoord(0, c));
    const double hi = std::min(b.upper, g.nodeCoord(0, c + 1));
    if (hi - lo <= 1e-12 * g.spacing[0])
      continue;
    const double mid = 0.5 * (lo + hi), off = (hi - lo) / (2 * std::sqrt(3.0));
    points.push_back({mid - off, (hi - lo) / 4, (hi - lo) / 2});
    points.push_back({mid + off, (hi - lo) / 4, (hi - lo) / 2});
  }
  return points;
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
    Body b;
    b.name = name;
    const auto& material = p.get<std::string>("Material");
    b.material = -1;
    for (std::size_t m = 0; m < materialNames.size(); ++m)
      if (materialNames[m] == material)
        b.material = static_cast<int>(m);
    if (b.material < 0)
      throw InputError(path + "/Material", "no material called '" + material + "' in Materials");
    if (Dim != 1 || p.get<std::string>("Shape") != "interval")
      throw InputError(path + "/Shape", "shape '" + p.get<std::string>("Shape") +
                                            "' does not fit a " + std::to_string(Dim) + "-D grid");
    const auto& extent = p.get<Teuchos::Array<double>>("Extent");
    b.lower = extent[0], b.upper = extent[1];
    if (!(b.lower < b.upper))
      throw InputError(path + "/Extent", "the lower end must be below the upper end");
    if (b.lower < grid.origin[0] - 1e-12 * grid.spacing[0] ||
        b.upper > grid.upper(0) + 1e-12 * grid.spacing[0]) {
      std::ostringstream msg;
      msg << "the body [" << b.lower << ", " << b.upper << "] reaches outside the grid ["
          << grid.origin[0] << ", " << grid.upper(0) << "]";
      throw InputError(path + "/Extent", msg.str());
    }
    b.particlesPerCell = p.get<int>("Particles Per Cell");
    b.section = Formula(formulaText(p, "Section"), {"x"});
    b.load = Formula(formulaText(p, "Distributed Load"), {"x", "X", "t"});
    b.bodyForce = Formula(formulaText(p, "Body Force"), {"x", "X", "t"});
    b.velocity = Formula(formulaText(p, "Initial Velocity"), {"x", "X"});
    b.displacement = Formula(formulaText(p, "Initial Displacement"), {"X"});
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
ParticleSet<Dim> Bodies<Dim>::createParticles(
    Method method, const Decomposition<Dim>& decomposition, int rank,
    const std::vector<std::shared_ptr<Material<Dim>>>& materials, bool displaced) const {
  static_assert(Dim == 1, "2-D bodies are not implemented yet");
  struct Local {
    Point point;
    GlobalId id;
    int body;
  };
  std::vector<Local> mine;
  GlobalId nextId = 0;
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    const auto points = isParticleMethod(method) ? materialPoints(bodies_[b], grid_.spacing[0])
                                                 : gaussPoints(bodies_[b], grid_);
    for (const auto& pt : points) {
      if (decomposition.ownerOfPoint(&pt.x) == rank)
        mine.push_back({pt, nextId, static_cast<int>(b)});
      ++nextId;
    }
  }
  ParticleSet<Dim> ps(mine.size());
  auto id = Kokkos::create_mirror_view(ps.id);
  auto body = Kokkos::create_mirror_view(ps.body);
  auto material = Kokkos::create_mirror_view(ps.material);
  auto X = Kokkos::create_mirror_view(ps.X);
  auto volume = Kokkos::create_mirror_view(ps.volume);
  auto section = Kokkos::create_mirror_view(ps.section);
  auto mass = Kokkos::create_mirror_view(ps.mass);
  auto F = Kokkos::create_mirror_view(ps.F);
  auto domain = Kokkos::create_mirror_view(ps.domain);
  auto domain0 = Kokkos::create_mirror_view(ps.domain0);
  auto x = Kokkos::create_mirror_view(ps.x);
  auto u = Kokkos::create_mirror_view(ps.u);
  auto v = Kokkos::create_mirror_view(ps.v);
  auto volume0 = Kokkos::create_mirror_view(ps.volume0);
  for (std::size_t p = 0; p < mine.size(); ++p) {
    const Body& b = bodies_[mine[p].body];
    id(p) = mine[p].id;
    body(p) = mine[p].body;
    material(p) = b.material;
    X(p, 0) = mine[p].point.x;
    volume(p) = mine[p].point.volume;
    section(p) = b.section(mine[p].point.x);
    if (!(section(p) > 0))
      throw InputError("Bodies/" + b.name + "/Section",
                       "must be > 0, but is " + std::to_string(section(p)) +
                           " at x = " + std::to_string(mine[p].point.x));
    mass(p) = materials[b.material]->density() * section(p) * volume(p);
    volume0(p) = volume(p);
    domain0(p, 0, 0) = mine[p].point.halfLength;
    F(p, 0, 0) = 1.0;
    if (displaced && !b.displacement.isConstant()) {
      const double Xp = X(p, 0), delta = 1e-6 * std::max(1.0, std::abs(Xp));
      u(p, 0) = b.displacement(Xp);
      F(p, 0, 0) = 1.0 + (b.displacement(Xp + delta) - b.displacement(Xp - delta)) / (2 * delta);
      if (!(F(p, 0, 0) > 0))
        throw InputError("Bodies/" + b.name + "/Initial Displacement",
                         "gives F = 1 + du/dX <= 0 at X = " + std::to_string(Xp));
    }
    x(p, 0) = X(p, 0) + u(p, 0);
    volume(p) = F(p, 0, 0) * volume0(p);
    domain(p, 0, 0) = F(p, 0, 0) * domain0(p, 0, 0);
    v(p, 0) = b.velocity(x(p, 0), X(p, 0));
  }
  Kokkos::deep_copy(ps.id, id), Kokkos::deep_copy(ps.body, body);
  Kokkos::deep_copy(ps.material, material), Kokkos::deep_copy(ps.X, X);
  Kokkos::deep_copy(ps.x, x), Kokkos::deep_copy(ps.volume, volume);
  Kokkos::deep_copy(ps.volume0, volume0), Kokkos::deep_copy(ps.section, section);
  Kokkos::deep_copy(ps.mass, mass), Kokkos::deep_copy(ps.F, F);
  Kokkos::deep_copy(ps.domain, domain), Kokkos::deep_copy(ps.domain0, domain0);
  Kokkos::deep_copy(ps.u, u), Kokkos::deep_copy(ps.v, v);
  return ps;
}

template <int Dim>
void Bodies<Dim>::initialNodalState(const double* x, double* u, double* v) const {
  std::size_t best = 0;
  double distance = 1e300;
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    const double d = std::max({bodies_[b].lower - x[0], x[0] - bodies_[b].upper, 0.0});
    if (d < distance)
      distance = d, best = b;
  }
  u[0] = bodies_[best].displacement(x[0]);
  v[0] = bodies_[best].velocity(x[0] + u[0], x[0]);
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
void Bodies<Dim>::applyLoads(ParticleSet<Dim>& particles, double time) const {
  auto body = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), particles.body);
  auto X = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), particles.X);
  auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), particles.x);
  auto volume = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), particles.volume);
  auto mass = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), particles.mass);
  auto force = Kokkos::create_mirror_view(particles.force);
  for (std::size_t p = 0; p < particles.size(); ++p) {
    const Body& b = bodies_[body(p)];
    force(p, 0) =
        b.load(x(p, 0), X(p, 0), time) * volume(p) + mass(p) * b.bodyForce(x(p, 0), X(p, 0), time);
  }
  Kokkos::deep_copy(particles.force, force);
}

template class Bodies<1>;

}  // namespace impm

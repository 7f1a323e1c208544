#include "app/Bodies.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/Errors.hpp"
#include "core/Parameters.hpp"

namespace impm {

namespace {

const std::vector<std::string> kVariables1D = {"x", "X", "t"};
const std::vector<std::string> kVariables2D = {"x", "y", "X", "Y", "t"};
const char* const kComponents[2] = {"x", "y"};

// The formula variables of a Dim-D deck: current position, reference position, time.
template <int Dim>
const std::vector<std::string>& variables() {
  return Dim == 1 ? kVariables1D : kVariables2D;
}

// Values in the order of variables<Dim>().
template <int Dim>
std::vector<double> arguments(const double* x, const double* X, double t) {
  if constexpr (Dim == 1)
    return {x[0], X[0], t};
  else
    return {x[0], x[1], X[0], X[1], t};
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
    for (const char* c : kComponents)
      declareFormula(
          valid, std::string(v.name) + " " + c, "0", kVariables2D,
          std::string("2-D: ") + c + " component of the " + v.doc + ", a formula of x, y, X, Y, t");
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

// Vector formula: "Name" in 1-D, "Name x" and "Name y" in 2-D; the other form must be unset.
template <int Dim>
std::array<Formula, 2> readVector(const Teuchos::ParameterList& p, const std::string& name,
                                  const std::string& path) {
  std::array<Formula, 2> f;
  const std::string other = Dim == 1 ? name + " x" : name;
  if (formulaText(p, other) != "0")
    throw InputError(path + "/" + other,
                     Dim == 1 ? "is for 2-D grids; this grid is 1-D (use '" + name + "')"
                              : "is for 1-D grids; this grid is 2-D (use '" + name + " x' and '" +
                                    name + " y')");
  for (int d = 0; d < Dim; ++d)
    f[d] = readFormula(p, Dim == 1 ? name : name + " " + kComponents[d], variables<Dim>(), path);
  return f;
}

struct Point {
  double x[2], half[2], volume;
};

// 1-D material points: equal particles filling [a, b], about `perCell` per grid cell.
std::vector<Point> materialPoints(const Body& b, const GridGeometry<1>& g) {
  const double h = g.spacing[0];
  const int n =
      std::max(1, static_cast<int>(std::lround(b.particlesPerCell * (b.upper - b.lower) / h)));
  const double length = (b.upper - b.lower) / n;
  std::vector<Point> points;
  for (int k = 0; k < n; ++k)
    points.push_back({{b.lower + (k + 0.5) * length, 0.0}, {length / 2, 0.0}, length});
  return points;
}

// 1-D Gauss points: two per cell, on the part of each cell inside [a, b] (the cut part of a
// cell that the body's end crosses, so that FEM integrates over the body exactly).
std::vector<Point> gaussPoints(const Body& b, const GridGeometry<1>& g) {
  std::vector<Point> points;
  for (int c = 0; c < g.cells[0]; ++c) {
    const double lo = std::max(b.lower, g.nodeCoord(0, c));
    const double hi = std::min(b.upper, g.nodeCoord(0, c + 1));
    if (hi - lo <= 1e-12 * g.spacing[0])
      continue;
    const double mid = 0.5 * (lo + hi), off = (hi - lo) / (2 * std::sqrt(3.0));
    points.push_back({{mid - off, 0.0}, {(hi - lo) / 4, 0.0}, (hi - lo) / 2});
    points.push_back({{mid + off, 0.0}, {(hi - lo) / 4, 0.0}, (hi - lo) / 2});
  }
  return points;
}

// 2-D: n x n points per cell of the grid near the shape.  Material points sit at the centres
// of the n x n sub-cells that lie in the shape (a staircase of the boundary, exact for a
// rectangle on grid lines); Gauss points (n = 2, at +-1/sqrt(3) of the half-cell) fill the
// cells whose centre lies in the shape.
std::vector<Point> cellPoints(const Body& b, const GridGeometry<2>& g, bool gauss) {
  const int n = gauss ? 2 : b.particlesPerCell;
  int lo[2], hi[2];
  for (int d = 0; d < 2; ++d) {
    lo[d] = std::max(0, static_cast<int>(std::floor(g.gridCoord(d, b.shape.lower()[d]))));
    hi[d] = std::min(g.cells[d], static_cast<int>(std::ceil(g.gridCoord(d, b.shape.upper()[d]))));
  }
  const double hx = g.spacing[0], hy = g.spacing[1];
  std::vector<Point> points;
  for (int j = lo[1]; j < hi[1]; ++j)
    for (int i = lo[0]; i < hi[0]; ++i) {
      const double centre[2] = {g.nodeCoord(0, i) + hx / 2, g.nodeCoord(1, j) + hy / 2};
      if (gauss && !b.shape.contains(centre))
        continue;
      for (int s = 0; s < n; ++s)
        for (int r = 0; r < n; ++r) {
          Point pt{};
          const double off = 0.5 / std::sqrt(3.0);
          pt.x[0] =
              gauss ? centre[0] + (r ? off : -off) * hx : g.nodeCoord(0, i) + (r + 0.5) * hx / n;
          pt.x[1] =
              gauss ? centre[1] + (s ? off : -off) * hy : g.nodeCoord(1, j) + (s + 0.5) * hy / n;
          if (!gauss && !b.shape.contains(pt.x))
            continue;
          pt.half[0] = hx / (2 * n), pt.half[1] = hy / (2 * n);
          pt.volume = hx * hy / (n * n);
          points.push_back(pt);
        }
    }
  return points;
}

template <int Dim>
std::vector<Point> integrationPoints(const Body& b, const GridGeometry<Dim>& g, Method method) {
  if constexpr (Dim == 1)
    return isParticleMethod(method) ? materialPoints(b, g) : gaussPoints(b, g);
  else
    return cellPoints(b, g, !isParticleMethod(method));
}

// x_p = X_p + u0(X_p), F_p = I + grad u0 by centred differences of the formulas.
template <int Dim>
void initialDisplacement(const Body& b, const double* X, double* u, double F[Dim][Dim]) {
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
    Body b;
    b.name = name;
    const auto& material = p.get<std::string>("Material");
    b.material = -1;
    for (std::size_t m = 0; m < materialNames.size(); ++m)
      if (materialNames[m] == material)
        b.material = static_cast<int>(m);
    if (b.material < 0)
      throw InputError(path + "/Material", "no material called '" + material + "' in Materials");
    b.shape = Shape(p, path, Dim);
    b.lower = b.shape.lower()[0], b.upper = b.shape.upper()[0];
    for (int d = 0; d < Dim; ++d) {
      const double tol = 1e-12 * grid.spacing[d];
      if (b.shape.lower()[d] < grid.origin[d] - tol || b.shape.upper()[d] > grid.upper(d) + tol) {
        std::ostringstream msg;
        msg << "the body [" << b.shape.lower()[d] << ", " << b.shape.upper()[d]
            << "] reaches outside the grid [" << grid.origin[d] << ", " << grid.upper(d) << "]";
        if (Dim > 1)
          msg << " along " << kComponents[d];
        const Shape::Kind k = b.shape.kind();
        throw InputError(path + (k == Shape::Kind::interval    ? "/Extent"
                                 : k == Shape::Kind::rectangle ? "/Lower Corner"
                                 : k == Shape::Kind::disk      ? "/Center"
                                                               : "/Vertices"),
                         msg.str());
      }
    }
    b.particlesPerCell = p.get<int>("Particles Per Cell");
    if (Dim == 1) {
      b.section = readFormula(p, "Section", {"x"}, path);
      b.load = readFormula(p, "Distributed Load", kVariables1D, path);
    } else {
      for (const char* one : {"Section", "Distributed Load"})
        if (formulaText(p, one) != (std::string(one) == "Section" ? "1" : "0"))
          throw InputError(path + "/" + one,
                           "is for 1-D bars; 2-D bodies are plane strain "
                           "with unit thickness (use Body Force x, y)");
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
ParticleSet<Dim> Bodies<Dim>::createParticles(
    Method method, const Decomposition<Dim>& decomposition, int rank,
    const std::vector<std::shared_ptr<Material<Dim>>>& materials, bool displaced) const {
  struct Local {
    Point point;
    GlobalId id;
    int body;
  };
  std::vector<Local> mine;
  GlobalId nextId = 0;
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    const auto points = integrationPoints<Dim>(bodies_[b], grid_, method);
    if (points.empty())
      throw InputError("Bodies/" + bodies_[b].name,
                       "the body holds no integration point (smaller than a sub-cell?)");
    for (const auto& pt : points) {
      if (decomposition.ownerOfPoint(pt.x) == rank)
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
    const Point& pt = mine[p].point;
    id(p) = mine[p].id;
    body(p) = mine[p].body;
    material(p) = b.material;
    double Xp[Dim], up[Dim] = {}, Fp[Dim][Dim] = {};
    for (int d = 0; d < Dim; ++d) {
      Xp[d] = X(p, d) = pt.x[d];
      Fp[d][d] = 1.0;
      domain0(p, d, d) = pt.half[d];
    }
    section(p) = b.section(pt.x[0]);
    if (!(section(p) > 0))
      throw InputError("Bodies/" + b.name + "/Section", "must be > 0, but is " +
                                                            std::to_string(section(p)) +
                                                            " at x = " + std::to_string(pt.x[0]));
    volume0(p) = pt.volume;
    mass(p) = materials[b.material]->density() * section(p) * volume0(p);
    if (displaced)
      initialDisplacement<Dim>(b, Xp, up, Fp);
    double J = Fp[0][0];
    if constexpr (Dim == 2)
      J = Fp[0][0] * Fp[1][1] - Fp[0][1] * Fp[1][0];
    if (!(J > 0)) {
      std::ostringstream msg;
      msg << "gives det F <= 0 at X = (" << Xp[0];
      for (int d = 1; d < Dim; ++d)
        msg << ", " << Xp[d];
      throw InputError("Bodies/" + b.name + "/Initial Displacement", msg.str() + ")");
    }
    volume(p) = J * volume0(p);
    double xp[Dim];
    for (int a = 0; a < Dim; ++a) {
      u(p, a) = up[a];
      xp[a] = x(p, a) = Xp[a] + up[a];
      for (int c = 0; c < Dim; ++c) {
        F(p, a, c) = Fp[a][c];
        domain(p, a, c) = Fp[a][c] * pt.half[c];  // r_k = F r0_k, r0_k along axis k
      }
    }
    for (int a = 0; a < Dim; ++a)
      v(p, a) = b.velocity[a](arguments<Dim>(xp, Xp, 0.0));
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
    const double d = bodies_[b].shape.contains(x) ? -1.0 : bodies_[b].shape.boxDistance(x);
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
void Bodies<Dim>::applyLoads(ParticleSet<Dim>& particles, double time) const {
  auto body = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), particles.body);
  auto X = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), particles.X);
  auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), particles.x);
  auto volume = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), particles.volume);
  auto mass = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), particles.mass);
  auto force = Kokkos::create_mirror_view(particles.force);
  for (std::size_t p = 0; p < particles.size(); ++p) {
    const Body& b = bodies_[body(p)];
    double xp[Dim], Xp[Dim];
    for (int d = 0; d < Dim; ++d)
      xp[d] = x(p, d), Xp[d] = X(p, d);
    const auto args = arguments<Dim>(xp, Xp, time);
    for (int a = 0; a < Dim; ++a)
      force(p, a) = mass(p) * b.bodyForce[a](args);
    if (Dim == 1)
      force(p, 0) += b.load(args) * volume(p);
  }
  Kokkos::deep_copy(particles.force, force);
}

template class Bodies<1>;
template class Bodies<2>;

}  // namespace impm

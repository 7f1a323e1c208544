// The 1-D grid system end to end below the input layer: particles, map, Robin ends, the
// NOX/Stratimikos solve; and its Jacobian against finite differences of its residual.  A linear
// field must be reproduced to round-off (patch test) by every method whose quadrature is exact for
// it, on any number of ranks.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultComm.hpp>

#include "bc/DirichletNodes.hpp"
#include "bc/RobinEnd.hpp"
#include "core/Errors.hpp"
#include "core/Parameters.hpp"
#include "material/MaterialFactory.hpp"
#include "material/MaterialState.hpp"
#include "solver/GridSystem.hpp"
#include "solver/NewtonSolver.hpp"
#include "solver/ParticleAdvance.hpp"

namespace impm {
namespace {

// A bar's points, each {x, half-length, force}: volume twice the half-length, section 1,
// undeformed.
using BarPoint = std::array<double, 3>;
ParticleSet<1> barPointSet(const std::vector<BarPoint>& points) {
  ParticleSet<1> ps(points.size());
  auto X = Kokkos::create_mirror_view(ps.X);
  auto V = Kokkos::create_mirror_view(ps.volume);
  auto r = Kokkos::create_mirror_view(ps.domain);
  auto A = Kokkos::create_mirror_view(ps.section);
  auto F = Kokkos::create_mirror_view(ps.F);
  auto f = Kokkos::create_mirror_view(ps.force);
  for (std::size_t p = 0; p < points.size(); ++p) {
    X(p, 0) = points[p][0], r(p, 0, 0) = points[p][1], V(p) = 2 * points[p][1];
    A(p) = 1.0, F(p, 0, 0) = 1.0, f(p, 0) = points[p][2];
  }
  Kokkos::deep_copy(ps.X, X), Kokkos::deep_copy(ps.x, X), Kokkos::deep_copy(ps.volume, V);
  Kokkos::deep_copy(ps.domain, r), Kokkos::deep_copy(ps.section, A), Kokkos::deep_copy(ps.F, F);
  Kokkos::deep_copy(ps.domain0, r), Kokkos::deep_copy(ps.volume0, V);
  Kokkos::deep_copy(ps.force, f);
  return ps;
}

// Integration points of [0, 1] on this rank: two per cell, either Gauss points (fem) or
// particle centres with their half-lengths.
ParticleSet<1> barPoints(const NodeOwnership<1>& own, Method method, const Formula& load) {
  const auto& g = own.grid();
  const double h = g.spacing[0];
  const int rank = own.comm()->getRank();
  std::vector<BarPoint> points;
  for (int c = 0; c < g.cells[0]; ++c) {
    const double mid = (c + 0.5) * h;
    if (own.decomposition().ownerOfPoint(&mid) != rank)
      continue;
    const double off = method == Method::fem ? h / (2 * std::sqrt(3.0)) : h / 4;
    for (const double x : {mid - off, mid + off})
      points.push_back({x, h / 4, load(x) * h / 2});
  }
  return barPointSet(points);
}

// One linear material of modulus E(x) on every point, its variables declared and set.
Materials<1> linearMaterial(ParticleSet<1>& ps, const std::string& E) {
  Teuchos::ParameterList mat;
  mat.set("Model", std::string("linear")), mat.set("E", E);
  validateParameters(mat, materialValidParameters());
  Materials<1> materials = {createMaterial<1>("m", mat)};
  declareMaterialVariables(ps, materials), initializeMaterials(ps, materials, true);
  return materials;
}

std::shared_ptr<Contribution<1>> robin(const std::string& end, double a, double b, double g,
                                       double at) {
  Teuchos::ParameterList p;
  p.set("Body", std::string("bar")), p.set("End", end);
  p.set("alpha", a), p.set("beta", b), p.set("gamma", g);
  validateParameters(p, RobinEnd::validParameters());
  return std::make_shared<RobinEnd>(end, p, at, Kinematics::totalLagrangian);
}

TEST(BarSolve, PatchTestIsExact) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  for (Method method : {Method::fem, Method::mpm, Method::gimp, Method::cpdi}) {
    NodeOwnership<1> own(makeGridGeometry<1>({0.0}, {1.0}, {8}), comm);
    auto ps = barPoints(own, method, Formula(1.0));
    Materials<1> materials = linearMaterial(ps, "1 - x/2");
    std::vector<std::shared_ptr<Contribution<1>>> bcs = {robin("left", 0, 1, 0, 0.0),
                                                         robin("right", 1, 0, 1, 1.0)};
    auto system = Teuchos::rcp(
        new GridSystem<1>(own, method, Kinematics::totalLagrangian, ps, materials, bcs, 1.0, 1.0));
    Teuchos::ParameterList solverParams;
    validateParameters(solverParams, NewtonSolver::validParameters());
    NewtonSolver newton(solverParams, comm);
    auto x = system->initialGuess();
    const auto report = newton.solve(system, *x);
    ASSERT_TRUE(report.converged) << methodName(method);
    system->commit(*x);
    // u_i = 2 x_i at every active node, F(0) = -2.
    auto values = x->getData();
    const auto& map = *x->getMap();
    for (decltype(values.size()) k = 0; k < values.size(); ++k) {
      const GO dof = map.getGlobalElement(k);
      if (system->dofs().isExtraDof(dof))
        continue;
      EXPECT_NEAR(values[k], 2.0 * dof / 8.0, 1e-12) << methodName(method) << " dof " << dof;
    }
    EXPECT_NEAR(dynamic_cast<RobinEnd&>(*bcs[0]).force(), -2.0, 1e-12) << methodName(method);
    EXPECT_NEAR(dynamic_cast<RobinEnd&>(*bcs[1]).force(), 1.0, 1e-12) << methodName(method);
    EXPECT_LE(report.iterations(), 2) << methodName(method);
  }
}

// The points of `ps` for which keep(x, half-length) holds, with their half-lengths as set.
ParticleSet<1> somePoints(const ParticleSet<1>& ps,
                          const std::function<bool(double x, double& halfLength)>& keep) {
  auto X = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), ps.X);
  auto r = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), ps.domain);
  auto f = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), ps.force);
  std::vector<BarPoint> kept;
  for (std::size_t p = 0; p < ps.size(); ++p) {
    double half = r(p, 0, 0);
    if (keep(X(p, 0), half))
      kept.push_back({X(p, 0), half, f(p, 0)});
  }
  return barPointSet(kept);
}

// A static step whose particles left nodes keeps the last layout with those nodes retired
// (solver/SystemLayout.hpp): the same unknowns, the retired ones solved to zero and the
// others to what a layout built for the step gives.  A particle that couples two nodes the
// kept graph does not couple makes a new layout (its entries would otherwise be dropped),
// and so does a retired share above 5 % of the unknowns.
TEST(GridSystem, KeptLayoutRetiresLeftNodesAndRefusesNewPairs) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  NodeOwnership<1> own(makeGridGeometry<1>({0.0}, {1.0}, {32}), comm);
  const double h = 1.0 / 32;
  std::vector<std::shared_ptr<Contribution<1>>> bcs = {robin("left", 0, 1, 0, 0.0)};
  Teuchos::ParameterList solverParams;
  validateParameters(solverParams, NewtonSolver::validParameters());
  NewtonSolver newton(solverParams, comm);
  LayoutCache<1> layouts(true, true);  // retired nodes allowed
  const auto kinematics = Kinematics::updatedLagrangian;

  auto all = barPoints(own, Method::gimp, Formula(1.0));  // inside their cells
  auto allMaterials = linearMaterial(all, "1");
  GridSystem<1> first(own, Method::gimp, kinematics, all, allMaterials, bcs, 1.0, 1.0, nullptr,
                      &layouts);
  ASSERT_EQ(layouts.built(), 1);

  // The last cell's points gone: node 32 is left (1 of 34 unknowns).
  auto fewer = somePoints(all, [&](double x, double&) { return x < 31 * h; });
  auto fewerMaterials = linearMaterial(fewer, "1");
  auto kept = Teuchos::rcp(new GridSystem<1>(own, Method::gimp, kinematics, fewer, fewerMaterials,
                                             bcs, 1.0, 1.0, nullptr, &layouts));
  EXPECT_EQ(layouts.reused(), 1);
  EXPECT_EQ(layouts.reusedRetiring(), 1);
  EXPECT_TRUE(kept->unknownMap()->isSameAs(*first.unknownMap()));
  auto built = Teuchos::rcp(
      new GridSystem<1>(own, Method::gimp, kinematics, fewer, fewerMaterials, bcs, 1.0, 1.0));
  EXPECT_EQ(built->unknownMap()->getGlobalNumElements() + 1,
            kept->unknownMap()->getGlobalNumElements());
  auto xKept = kept->initialGuess(), xBuilt = built->initialGuess();
  ASSERT_TRUE(newton.solve(kept, *xKept).converged);
  ASSERT_TRUE(newton.solve(built, *xBuilt).converged);
  const auto& keptMap = *xKept->getMap();
  auto uKept = xKept->getData(), uBuilt = xBuilt->getData();
  for (decltype(uKept.size()) k = 0; k < uKept.size(); ++k) {
    const GO dof = keptMap.getGlobalElement(static_cast<LO>(k));
    const LO other = xBuilt->getMap()->getLocalElement(dof);
    if (dof == 32) {  // node 32, retired
      EXPECT_EQ(uKept[k], 0.0);
    } else if (!kept->dofs().isExtraDof(dof)) {
      EXPECT_NEAR(uKept[k], uBuilt[other], 1e-12 * std::abs(uBuilt[other])) << "dof " << dof;
    }
  }

  // A point of cell 2 grown to span cells 1 to 3 couples nodes 1 and 3: a new layout.
  auto wide = somePoints(fewer, [&](double x, double& half) {
    if (x > 2 * h && x < 2.5 * h)
      half = h;
    return true;
  });
  auto wideMaterials = linearMaterial(wide, "1");
  GridSystem<1> grown(own, Method::gimp, kinematics, wide, wideMaterials, bcs, 1.0, 1.0, nullptr,
                      &layouts);
  EXPECT_EQ(layouts.built(), 2);
  EXPECT_EQ(layouts.reused(), 1);

  // On 8 cells the left node is 1 of 10 unknowns: more than a kept layout may retire.
  NodeOwnership<1> coarse(makeGridGeometry<1>({0.0}, {1.0}, {8}), comm);
  LayoutCache<1> coarseLayouts(true, true);
  auto coarseAll = barPoints(coarse, Method::gimp, Formula(1.0));
  auto coarseAllMaterials = linearMaterial(coarseAll, "1");
  GridSystem<1> coarseFirst(coarse, Method::gimp, kinematics, coarseAll, coarseAllMaterials, bcs,
                            1.0, 1.0, nullptr, &coarseLayouts);
  auto coarseFewer = somePoints(coarseAll, [](double x, double&) { return x < 7.0 / 8; });
  auto coarseFewerMaterials = linearMaterial(coarseFewer, "1");
  GridSystem<1> coarseNext(coarse, Method::gimp, kinematics, coarseFewer, coarseFewerMaterials, bcs,
                           1.0, 1.0, nullptr, &coarseLayouts);
  EXPECT_EQ(coarseLayouts.built(), 2);
  EXPECT_EQ(coarseLayouts.reused(), 0);
}

// |J v - (R(x + e v) - R(x - e v)) / 2e| / |J v| at a random x of amplitude `amplitude` and a
// random direction v, e = 1e-6 (infinite when J v = 0: a Jacobian that vanishes is wrong).
double jacobianError(ResidualModel& system, double amplitude) {
  Vector x(system.unknownMap()), v(system.unknownMap()), Jv(system.unknownMap());
  Vector rp(system.unknownMap()), rm(system.unknownMap());
  x.randomize(-amplitude, amplitude);
  v.randomize(-1.0, 1.0);
  auto J = system.createJacobian();
  system.evaluate(x, nullptr, J.get());
  J->apply(v, Jv);
  const double eps = 1e-6;
  Vector xp(x, Teuchos::Copy), xm(x, Teuchos::Copy);
  xp.update(eps, v, 1.0), xm.update(-eps, v, 1.0);
  system.evaluate(xp, &rp, nullptr);
  system.evaluate(xm, &rm, nullptr);
  rp.update(-1.0 / (2 * eps), rm, 1.0 / (2 * eps));
  rp.update(-1.0, Jv, 1.0);
  const double scale = Jv.norm2();
  return scale > 0 ? rp.norm2() / scale : std::numeric_limits<double>::infinity();
}

// The Jacobian of the grid system is the derivative of its residual: central differences
// of R along random directions, on a bar whose particles were already deformed (so the
// push-forward of P and A to the start of the step is exercised) with Robin ends.
TEST(GridSystem, JacobianIsTheDerivativeOfTheResidual) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  NodeOwnership<1> own(makeGridGeometry<1>({-0.2}, {1.5}, {10}), comm);
  const int rank = comm->getRank();
  std::vector<double> centres;
  for (int p = 0; p < 15; ++p) {
    const double x = (p + 0.5) / 15.0;
    if (own.decomposition().ownerOfPoint(&x) == rank)
      centres.push_back(x);
  }
  ParticleSet<1> ps(centres.size());
  {
    auto X = Kokkos::create_mirror_view(ps.X);
    auto r = Kokkos::create_mirror_view(ps.domain);
    auto V = Kokkos::create_mirror_view(ps.volume);
    auto A = Kokkos::create_mirror_view(ps.section);
    auto F = Kokkos::create_mirror_view(ps.F);
    auto f = Kokkos::create_mirror_view(ps.force);
    for (std::size_t p = 0; p < centres.size(); ++p) {
      const double J = 1.0 + 0.3 * centres[p];
      X(p, 0) = centres[p], F(p, 0, 0) = J, V(p) = J / 15.0, r(p, 0, 0) = J / 30.0;
      A(p) = 1.0, f(p, 0) = 0.1;
    }
    Kokkos::deep_copy(ps.X, X), Kokkos::deep_copy(ps.x, X), Kokkos::deep_copy(ps.domain, r);
    Kokkos::deep_copy(ps.volume, V), Kokkos::deep_copy(ps.section, A), Kokkos::deep_copy(ps.F, F);
    Kokkos::deep_copy(ps.force, f);
  }
  Materials<1> materials = linearMaterial(ps, "1 + x");
  auto robin = [](const std::string& end, double a, double b, double at) {
    Teuchos::ParameterList p;
    p.set("Body", std::string("bar")), p.set("End", end), p.set("alpha", a), p.set("beta", b);
    validateParameters(p, RobinEnd::validParameters());
    return std::make_shared<RobinEnd>(end, p, at, Kinematics::updatedLagrangian);
  };
  std::vector<std::shared_ptr<Contribution<1>>> bcs = {robin("left", 0, 1, 0.0),
                                                       robin("right", 1, -2, 1.0)};
  for (Method method : {Method::mpm, Method::gimp, Method::cpdi}) {
    GridSystem<1> system(own, method, Kinematics::updatedLagrangian, ps, materials, bcs, 1.0, 1.0);
    EXPECT_LT(jacobianError(system, 0.01), 1e-7) << methodName(method);
  }
}

}  // namespace
}  // namespace impm

namespace impm {
namespace {

// The same check in 2-D (3-D) for every method, both kinematics and every law: particles of a
// square (cubic) block that was already sheared and stretched (F != I, domains F r0), so that the
// push-forward of P and A to the start of the step is exercised in updated Lagrangian runs.
// `kinematics`: the particles are on the rank of their map position (X in total, x in updated
// Lagrangian), as F-bar requires; the positions X otherwise.
template <int Dim>
ParticleSet<Dim> deformedBlock(const NodeOwnership<Dim>& own, Method method,
                               std::optional<Kinematics> kinematics = std::nullopt) {
  // A general stretch and shear (2-D: its in-plane block).
  const double F3[3][3] = {{1.06, 0.12, 0.03}, {-0.04, 0.93, 0.05}, {0.02, -0.06, 1.04}};
  double F[Dim][Dim];
  for (int a = 0; a < Dim; ++a)
    for (int b = 0; b < Dim; ++b)
      F[a][b] = F3[a][b];
  const int rank = own.comm()->getRank();
  // n^Dim particles in [0.3, 0.7]^Dim (fem: Gauss points of its cells)
  const int n = Dim == 2 ? 8 : 4;
  const auto placedAt = [&](const std::array<double, Dim>& at) {
    std::array<double, Dim> x;
    for (int a = 0; a < Dim; ++a) {
      x[a] = 0.5;
      for (int b = 0; b < Dim; ++b)
        x[a] += F[a][b] * (at[b] - 0.5);
    }
    return x;
  };
  std::vector<std::array<double, Dim>> X;
  int idx[Dim] = {};
  for (int count = 0; count < std::pow(n, Dim); ++count) {
    std::array<double, Dim> at;
    for (int d = 0, c = count; d < Dim; ++d, c /= n)
      idx[d] = c % n, at[d] = 0.3 + (idx[d] + 0.5) * 0.4 / n;
    // Updated Lagrangian: the particle sits at F X about the block's centre.
    const std::array<double, Dim> placed =
        kinematics == Kinematics::updatedLagrangian ? placedAt(at) : at;
    if (own.decomposition().ownerOfPoint(placed.data()) == rank)
      X.push_back(at);
  }
  ParticleSet<Dim, Kokkos::DefaultHostExecutionSpace> h(X.size());
  const double half = 0.2 / n;
  for (std::size_t p = 0; p < X.size(); ++p) {
    const auto x = placedAt(X[p]);
    for (int a = 0; a < Dim; ++a) {
      h.X(p, a) = X[p][a];
      h.x(p, a) = x[a];
      for (int b = 0; b < Dim; ++b) {
        h.F(p, a, b) = method == Method::fem ? (a == b) : F[a][b];
        h.domain0(p, a, b) = a == b ? half : 0.0;
        h.domain(p, a, b) = method == Method::fem ? h.domain0(p, a, b) : F[a][b] * half;
      }
      h.force(p, a) = 0.1 * (a + 1);
    }
    h.volume0(p) = std::pow(2 * half, Dim);
    h.volume(p) = h.volume0(p) * (method == Method::fem ? 1.0 : determinant<Dim>(F));
    h.section(p) = 1.0, h.mass(p) = h.volume0(p);
  }
  ParticleSet<Dim> ps;
  ps.copyFrom(h);
  return ps;
}

// The law `law` (E = 100, nu = 0.3; plastic laws yielding) on every particle of ps, its
// variables declared and initialized.
template <int Dim>
Materials<Dim> elasticOn(ParticleSet<Dim>& ps, const std::string& law) {
  Teuchos::ParameterList mat;
  mat.set("Model", law), mat.set("E", 100.0), mat.set("nu", 0.3);
  // The plastic laws yield at a fraction of the block's stress (about 5): every point is
  // plastic, away from the elastic-plastic kink.
  if (law == "j2")
    mat.set("Yield Stress", 0.5);
  if (law == "drucker-prager")
    mat.set("Cohesion", 0.2), mat.set("Friction Angle", 20.0), mat.set("Dilation Angle", 20.0);
  validateParameters(mat, materialValidParameters());
  Materials<Dim> materials = {createMaterial<Dim>("m", mat)};
  declareMaterialVariables(ps, materials), initializeMaterials(ps, materials, true);
  return materials;
}

TEST(GridSystem, JacobianIsTheDerivativeOfTheResidualIn2D) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  NodeOwnership<2> own(makeGridGeometry<2>({0.0, 0.0}, {1.0, 1.0}, {5, 5}), comm);
  for (const std::string law : {"linear-elastic", "neo-hookean"})
    for (Method method : {Method::fem, Method::mpm, Method::gimp, Method::cpdi})
      for (Kinematics kinematics : {Kinematics::totalLagrangian, Kinematics::updatedLagrangian}) {
        if (method == Method::fem && kinematics == Kinematics::updatedLagrangian)
          continue;  // fem integrates on the grid as a fixed mesh
        auto ps = deformedBlock<2>(own, method);
        const auto materials = elasticOn<2>(ps, law);
        const std::vector<std::shared_ptr<Contribution<2>>> none;
        GridSystem<2> system(own, method, kinematics, ps, materials, none, 1.0, 1.0);
        const std::string what =
            law + ", " + methodName(method) +
            (kinematics == Kinematics::totalLagrangian ? ", total" : ", updated");
        // Measured: 4e-12 to 7e-12 (linear-elastic), 2e-11 to 6e-11 (neo-hookean); the
        // central difference's truncation and round-off bound it near 1e-10.
        EXPECT_LT(jacobianError(system, 0.003), 1e-9) << what;
      }
}

// F-bar's tangent (the theta-scaled standard one and the coupling of each cell's nodes) is the
// derivative of its residual, for every method, both kinematics and the 2-D laws, with 4 x 4
// particles per cell (and domains that reach into the next cells with gimp and cpdi).
TEST(GridSystem, JacobianWithFBarIsTheDerivativeOfTheResidualIn2D) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  NodeOwnership<2> own(makeGridGeometry<2>({0.0, 0.0}, {1.0, 1.0}, {5, 5}), comm);
  for (const std::string law : {"linear-elastic", "neo-hookean", "hencky", "j2", "drucker-prager"})
    for (Method method : {Method::fem, Method::mpm, Method::gimp, Method::cpdi})
      for (Kinematics kinematics : {Kinematics::totalLagrangian, Kinematics::updatedLagrangian}) {
        if (method == Method::fem && kinematics == Kinematics::updatedLagrangian)
          continue;
        auto ps = deformedBlock<2>(own, method, kinematics);
        declareFBarFields(ps, FBar::cell, kinematics);
        const auto materials = elasticOn<2>(ps, law);
        const std::vector<std::shared_ptr<Contribution<2>>> none;
        GridSystem<2> system(own, method, kinematics, ps, materials, none, 1.0, 1.0, nullptr,
                             nullptr, NodeCoupling::shared, FBar::cell);
        const std::string what =
            law + ", " + methodName(method) +
            (kinematics == Kinematics::totalLagrangian ? ", total" : ", updated");
        EXPECT_FALSE(system.isLinear()) << what;
        // Measured: 8e-12 to 9e-11 (elastic laws), 5e-11 to 1.8e-8 (plastic ones: fem's
        // undeformed block has points near the yield surface, where the difference quotient
        // meets the kink); without the coupling term 0.04 to 0.17.
        const bool plastic = law == "j2" || law == "drucker-prager";
        EXPECT_LT(jacobianError(system, 0.003), plastic ? 1e-7 : 1e-9) << what;
      }
}

// 3-D: the Jacobian is the residual's derivative for every method, both kinematics and every
// law, with and without F-bar, on a sheared and stretched block of 4 x 4 x 4 particles.
TEST(GridSystem, JacobianIsTheDerivativeOfTheResidualIn3D) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  NodeOwnership<3> own(makeGridGeometry<3>({0.0, 0.0, 0.0}, {1.0, 1.0, 1.0}, {5, 5, 5}), comm);
  double worst[2] = {0.0, 0.0};  // elastic, plastic
  for (const std::string law : {"linear-elastic", "neo-hookean", "hencky", "j2", "drucker-prager"})
    for (Method method : {Method::fem, Method::mpm, Method::gimp, Method::cpdi})
      for (Kinematics kinematics : {Kinematics::totalLagrangian, Kinematics::updatedLagrangian})
        for (FBar fbar : {FBar::none, FBar::cell}) {
          if (method == Method::fem && kinematics == Kinematics::updatedLagrangian)
            continue;  // fem integrates on the grid as a fixed mesh
          auto ps = deformedBlock<3>(own, method, kinematics);
          declareFBarFields(ps, fbar, kinematics);
          const auto materials = elasticOn<3>(ps, law);
          const std::vector<std::shared_ptr<Contribution<3>>> none;
          GridSystem<3> system(own, method, kinematics, ps, materials, none, 1.0, 1.0, nullptr,
                               nullptr, NodeCoupling::shared, fbar);
          const std::string what =
              law + ", " + methodName(method) +
              (kinematics == Kinematics::totalLagrangian ? ", total" : ", updated") +
              (fbar == FBar::cell ? ", F-bar" : "");
          const bool plastic = law == "j2" || law == "drucker-prager";
          const double error = jacobianError(system, 0.003);
          worst[plastic] = std::max(worst[plastic], error);
          EXPECT_LT(error, plastic ? 1e-7 : 1e-9) << what;
        }
  std::cout << "  3-D Jacobian against central differences: largest relative error " << worst[0]
            << " (elastic laws), " << worst[1] << " (plastic laws)\n";
}

// The ghost penalty (assembly/GhostPenalty.hpp) in the residual and the Jacobian: the
// Jacobian stays the residual's derivative with a penalty large enough to dominate, and the
// penalty changes it (the block leaves empty cells around it, so some faces are cut).
TEST(GridSystem, JacobianWithGhostPenaltyIsTheDerivativeOfTheResidual) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  NodeOwnership<2> own(makeGridGeometry<2>({0.0, 0.0}, {1.0, 1.0}, {5, 5}), comm);
  const std::vector<std::shared_ptr<Contribution<2>>> none;
  for (Method method : {Method::mpm, Method::gimp, Method::cpdi}) {
    auto ps = deformedBlock(own, method, Kinematics::updatedLagrangian);
    const auto materials = elasticOn(ps, "neo-hookean");
    GridSystem<2> plain(own, method, Kinematics::updatedLagrangian, ps, materials, none, 1.0, 1.0);
    GridSystem<2> ghost(own, method, Kinematics::updatedLagrangian, ps, materials, none, 1.0, 1.0,
                        nullptr, nullptr, NodeCoupling::shared, FBar::none, 0.5);
    EXPECT_LT(jacobianError(ghost, 0.003), 1e-9) << methodName(method);
    // The same increment: the residuals differ by the penalty's force.
    Vector x(ghost.unknownMap()), r0(plain.unknownMap()), r1(ghost.unknownMap());
    x.randomize(-0.003, 0.003);
    Vector xPlain(plain.unknownMap());
    ASSERT_TRUE(plain.unknownMap()->isSameAs(*ghost.unknownMap())) << methodName(method);
    Tpetra::deep_copy(xPlain, x);
    plain.evaluate(xPlain, &r0, nullptr);
    ghost.evaluate(x, &r1, nullptr);
    r1.update(-1.0, r0, 1.0);
    EXPECT_GT(r1.norm2(), 1e-6 * r0.norm2()) << methodName(method);
  }
}

// A law whose stress is finite and whose tangent is not.
class NanTangentLaw : public Material<2> {
 public:
  NanTangentLaw() : Material<2>("nan tangent", 1.0) {}
  void firstPiola(const Evaluation& at, Tensors& P, Tangents& A) const override {
    const auto members = at.members;
    const auto F = at.F;
    Kokkos::parallel_for("nanTangent", RangePolicy<DefaultExecSpace>(0, members.extent(0)),
                         [=](const int i) {
                           const int p = members(i);
                           for (int a = 0; a < 2; ++a)
                             for (int b = 0; b < 2; ++b) {
                               P(p, a, b) = F(p, a, b) - (a == b ? 1.0 : 0.0);
                               for (int c = 0; c < 2; ++c)
                                 for (int d = 0; d < 2; ++d)
                                   A(p, a, b, c, d) = std::numeric_limits<double>::quiet_NaN();
                             }
                         });
  }
  void energyDensity(const Evaluation& at, Scalars& W) const override {
    const auto members = at.members;
    Kokkos::parallel_for("nanTangentEnergy", RangePolicy<DefaultExecSpace>(0, members.extent(0)),
                         [=](const int i) { W(members(i)) = 0.0; });
  }
  double maxModulus(const Evaluation&) const override { return 1.0; }
};

// A tangent that is not finite stops a step whose Jacobian would use it, naming it; an
// explicit step's frozen internal force assembles none, so it does not look.
TEST(GridSystem, NonFiniteTangentStopsOnlyStepsThatAssembleIt) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  NodeOwnership<2> own(makeGridGeometry<2>({0.0, 0.0}, {1.0, 1.0}, {5, 5}), comm);
  const std::vector<std::shared_ptr<Contribution<2>>> none;
  auto ps = deformedBlock(own, Method::gimp);
  Materials<2> materials = {std::make_shared<NanTangentLaw>()};
  declareMaterialVariables(ps, materials), initializeMaterials(ps, materials, true);
  for (bool frozen : {false, true}) {
    GridSystem<2> system(own, Method::gimp, Kinematics::updatedLagrangian, ps, materials, none, 1.0,
                         1.0);
    system.freezeInternalForce(frozen);
    Vector r(system.unknownMap());
    const auto evaluate = [&] { system.evaluate(Vector(system.unknownMap()), &r, nullptr); };
    if (!frozen) {
      try {
        evaluate();
        ADD_FAILURE() << "a non-finite tangent went unnoticed";
      } catch (const NumericalError& e) {
        EXPECT_NE(std::string(e.what()).find("the tangent of particle"), std::string::npos)
            << e.what();
      }
    } else {
      EXPECT_NO_THROW(evaluate());
      EXPECT_GT(r.normInf(), 0.0);  // the stress it holds makes a force
    }
  }
}

// An explicit step on a moving grid starts from the Cauchy stress the last particle update
// committed instead of evaluating the laws at du = 0: for laws without a trial state the
// step's frozen internal force is the same, bit for bit, in both ways.
TEST(GridSystem, ExplicitStepStartsFromTheCommittedStress) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  NodeOwnership<2> own(makeGridGeometry<2>({0.0, 0.0}, {1.0, 1.0}, {5, 5}), comm);
  const std::vector<std::shared_ptr<Contribution<2>>> none;
  for (const std::string law : {"linear-elastic", "neo-hookean"})
    for (Method method : {Method::gimp, Method::cpdi}) {
      const std::string what = law + ", " + methodName(method);
      auto ps = deformedBlock<2>(own, method);
      const auto materials = elasticOn<2>(ps, law);
      {  // a step: the particles move and commit a new stress
        GridSystem<2> step(own, method, Kinematics::updatedLagrangian, ps, materials, none, 1.0,
                           1.0);
        Vector du(step.unknownMap());
        du.randomize(-2e-3, 2e-3);
        advanceParticles(step, du, Kinematics::updatedLagrangian, ps);
        step.commit(du);
      }
      const auto startForce = [&](bool committed) {
        GridSystem<2> next(own, method, Kinematics::updatedLagrangian, ps, materials, none, 1.0,
                           1.0);
        next.freezeInternalForce(true);
        if (committed)
          next.startFromCommittedStress();
        Vector r(next.unknownMap());
        next.evaluate(Vector(next.unknownMap()), &r, nullptr);
        const auto values = r.getData();
        return std::vector<double>(values.begin(), values.end());
      };
      const auto evaluated = startForce(false), committed = startForce(true);
      EXPECT_EQ(evaluated, committed) << what;
      double largest = 0, anywhere = 0;  // a rank may hold no particle, and no force
      for (double f : evaluated)
        largest = std::max(largest, std::abs(f));
      Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, largest, Teuchos::outArg(anywhere));
      EXPECT_GT(anywhere, 1e-3) << what;  // a stress there to compare
    }
}

// With prescribed unknowns (nodes inside the block held in x, others moved in y) the
// Jacobian of a hyperelastic law is symmetric: the prescribed rows and their columns are
// eliminated alike, so CG may solve it.  Checked as w^T J v = v^T J w for random v, w.
TEST(GridSystem, PrescribedUnknownsKeepTheJacobianSymmetric) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  const auto grid = makeGridGeometry<2>({0.0, 0.0}, {1.0, 1.0}, {5, 5});
  NodeOwnership<2> own(grid, comm);
  std::vector<std::shared_ptr<Contribution<2>>> held;
  for (const auto& [box, component, value] :
       {std::tuple{Teuchos::tuple(0.35, 0.45, 0.35, 0.65), "x", "0"},
        std::tuple{Teuchos::tuple(0.55, 0.65, 0.35, 0.45), "y", "0.01 * t"}}) {
    Teuchos::ParameterList bc;
    bc.set("Face", "box"), bc.set("Box", Teuchos::Array<double>(box));
    bc.set("Component", component), bc.set("Value", value);
    validateParameters(bc, DirichletNodes<2>::validParameters());
    held.push_back(std::make_shared<DirichletNodes<2>>(component, bc, grid, 0.0));
  }
  for (const std::string law : {"linear-elastic", "neo-hookean", "hencky"})
    for (Method method : {Method::fem, Method::gimp, Method::cpdi}) {
      const auto kinematics =
          method == Method::fem ? Kinematics::totalLagrangian : Kinematics::updatedLagrangian;
      auto ps = deformedBlock<2>(own, method);
      const auto materials = elasticOn<2>(ps, law);
      ASSERT_TRUE(materials[0]->hasSymmetricTangent()) << law;
      GridSystem<2> system(own, method, kinematics, ps, materials, held, 1.0, 1.0);
      Vector x(system.unknownMap()), v(system.unknownMap()), w(system.unknownMap());
      Vector Jv(system.unknownMap()), Jw(system.unknownMap());
      x.randomize(-0.003, 0.003), v.randomize(-1.0, 1.0), w.randomize(-1.0, 1.0);
      system.imposeConstraints(x);
      auto J = system.createJacobian();
      system.evaluate(x, nullptr, J.get());
      J->apply(v, Jv), J->apply(w, Jw);
      const double asymmetry = std::abs(w.dot(Jv) - v.dot(Jw)) / (Jv.norm2() * w.norm2());
      // Measured: below 1e-16; with the columns kept, 3e-3 to 9e-2.
      EXPECT_LT(asymmetry, 1e-13) << law << ", " << methodName(method);
    }
}

// The system keeps its prescribed rows between evaluations; their increments (the value at
// the system's time minus the committed one) must follow setTime and commit.  One node held
// at u_y = 0.01 t: 0.01 at t = 1 from the start, 0.02 at t = 2, 0 once t = 2 is committed.
TEST(GridSystem, PrescribedIncrementsFollowTheTimeAndTheCommit) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  const auto grid = makeGridGeometry<2>({0.0, 0.0}, {1.0, 1.0}, {5, 5});
  NodeOwnership<2> own(grid, comm);
  Teuchos::ParameterList bc;
  bc.set("Face", "box"),
      bc.set("Box", Teuchos::Array<double>(Teuchos::tuple(0.55, 0.65, 0.35, 0.45)));
  bc.set("Component", "y"), bc.set("Value", "0.01 * t");
  validateParameters(bc, DirichletNodes<2>::validParameters());
  std::vector<std::shared_ptr<Contribution<2>>> held{
      std::make_shared<DirichletNodes<2>>("y", bc, grid, 0.0)};
  auto ps = deformedBlock(own, Method::fem);
  const auto materials = elasticOn(ps, "linear-elastic");
  GridSystem<2> system(own, Method::fem, Kinematics::totalLagrangian, ps, materials, held, 1.0,
                       1.0);
  const auto prescribed = [&] {
    Vector x(system.unknownMap());
    system.imposeConstraints(x);
    return x.normInf();  // the one held value; every other entry stays 0
  };
  EXPECT_NEAR(prescribed(), 0.01, 1e-15);
  EXPECT_NEAR(prescribed(), 0.01, 1e-15);  // the kept rows, asked again
  system.setTime(2.0, 1.0);
  EXPECT_NEAR(prescribed(), 0.02, 1e-15);
  Vector x(system.unknownMap());
  system.imposeConstraints(x);
  Vector r(system.unknownMap());
  system.evaluate(x, &r, nullptr);
  system.commit(x);
  EXPECT_EQ(prescribed(), 0.0);
}

}  // namespace
}  // namespace impm

namespace impm {
namespace {

// R(x) with the inertia (mass, c0, r), for the acceleration a = c0 x - r given per row.
Vector residualWith(GridSystem<1>& system, MassType mass, const Vector& x,
                    const std::function<double(GO)>& a) {
  const double c0 = 4.0;
  auto r = Teuchos::rcp(new Vector(system.unknownMap()));
  {
    auto xv = x.getLocalViewHost(Tpetra::Access::ReadOnly);
    auto rv = r->getLocalViewHost(Tpetra::Access::ReadWrite);
    for (std::size_t k = 0; k < rv.extent(0); ++k)
      rv(k, 0) = c0 * xv(k, 0) - a(system.unknownMap()->getGlobalElement(static_cast<LO>(k)));
  }
  system.setInertia({mass, c0, r});
  Vector R(system.unknownMap());
  system.evaluate(x, &R, nullptr);
  return R;
}

// The lumped inertia, m_i a_i on the grid, against the consistent mass's sum over the
// particles: for a uniform acceleration the two are the same (the rows of the consistent
// mass sum to the lumped one), m_i then weighs any acceleration row by row, and the
// Jacobian holds c0 m_i.
TEST(GridSystem, LumpedInertiaIsTheParticlesMassTimesTheAcceleration) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  NodeOwnership<1> own(makeGridGeometry<1>({0.0}, {1.0}, {8}), comm);
  for (Method method : {Method::fem, Method::gimp}) {
    auto ps = barPoints(own, method, Formula(0.0));
    {
      auto X = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), ps.X);
      auto V = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), ps.volume);
      auto m = Kokkos::create_mirror_view(ps.mass);
      for (std::size_t p = 0; p < ps.size(); ++p)
        m(p) = (1.0 + X(p, 0)) * V(p);
      Kokkos::deep_copy(ps.mass, m);
    }
    Materials<1> materials = linearMaterial(ps, "1 + x");
    std::vector<std::shared_ptr<Contribution<1>>> bcs = {robin("left", 0, 1, 0, 0.0),
                                                         robin("right", 1, 0, 1, 1.0)};
    GridSystem<1> system(own, method, Kinematics::totalLagrangian, ps, materials, bcs, 1.0, 1.0);
    Vector x(system.unknownMap());
    x.randomize(-0.01, 0.01);
    Vector R0(system.unknownMap());
    system.evaluate(x, &R0, nullptr);
    const auto one = [](GO) { return 1.0; };
    const auto varying = [](GO dof) { return 1.0 + 0.5 * std::sin(1.0 + dof); };
    Vector consistent = residualWith(system, MassType::consistent, x, one);
    Vector lumped = residualWith(system, MassType::lumped, x, one);
    Vector weighed = residualWith(system, MassType::lumped, x, varying);
    for (Vector* v : {&consistent, &lumped, &weighed})
      v->update(-1.0, R0, 1.0);  // M a alone
    const auto mass = system.lumpedMass();
    auto c = consistent.getData(), l = lumped.getData(), w = weighed.getData(), m = mass->getData();
    double total = 0.0;
    for (decltype(c.size()) k = 0; k < c.size(); ++k) {
      const GO dof = system.unknownMap()->getGlobalElement(static_cast<LO>(k));
      EXPECT_NEAR(l[k], c[k], 1e-14) << methodName(method) << " dof " << dof;
      EXPECT_NEAR(m[k], c[k], 1e-14) << methodName(method) << " dof " << dof;
      EXPECT_NEAR(w[k], c[k] * varying(dof), 1e-14) << methodName(method) << " dof " << dof;
      total += m[k];
    }
    // The bar's mass: the integral of 1 + x over [0, 1] (exact for both quadratures).
    double sum = 0.0;
    Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, total, Teuchos::outArg(sum));
    EXPECT_NEAR(sum, 1.5, 1e-14) << methodName(method);
    // And the Jacobian's c0 m_i on the diagonal is the residual's derivative.
    EXPECT_LT(jacobianError(system, 0.01), 1e-7) << methodName(method);
  }
}

// The external force enters where particles carry forces, as read when the system is built
// and when its time is set: on several ranks rank 0's particles never do, the others' (and
// one rank's) only after setTime.
TEST(GridSystem, ExternalForceIsReadWhenTheTimeIsSet) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  NodeOwnership<1> own(makeGridGeometry<1>({0.0}, {1.0}, {8}), comm);
  auto ps = barPoints(own, Method::fem, Formula(0.0));
  Materials<1> materials = linearMaterial(ps, "1");
  std::vector<std::shared_ptr<Contribution<1>>> none;
  GridSystem<1> system(own, Method::fem, Kinematics::totalLagrangian, ps, materials, none, 1.0,
                       1.0);
  EXPECT_FALSE(system.particlesCarryForces());
  Vector x(system.unknownMap());
  x.randomize(-0.01, 0.01);
  Vector unloaded(system.unknownMap()), loaded(system.unknownMap());
  system.evaluate(x, &unloaded, nullptr);
  const bool carries = comm->getSize() == 1 || comm->getRank() != 0;
  if (carries)
    Kokkos::deep_copy(ps.force, 0.25);
  system.setTime(1.0, 2.0);
  EXPECT_EQ(system.particlesCarryForces(), carries);
  system.evaluate(x, &loaded, nullptr);
  loaded.update(-1.0, unloaded, 1.0);  // -2 sum_p phi_ip f_p
  double local = 0.0, sum = 0.0;
  for (double v : loaded.getData())
    local += v;
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, local, Teuchos::outArg(sum));
  const double count = static_cast<double>(carries ? ps.size() : 0);
  double particles = 0.0;
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, count, Teuchos::outArg(particles));
  EXPECT_NEAR(sum, -2.0 * 0.25 * particles, 1e-13);
  EXPECT_GT(particles, 0.0);
}

}  // namespace
}  // namespace impm

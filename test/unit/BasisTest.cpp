// The particle-grid map: partition of unity and linear completeness (eq. 1.8b-c, 1.79-1.80)
// of phi_ip and G_ip for every scheme, on regular and random particle layouts in 1-D and
// 2-D; exactness of the GIMP average; CPDI particles spanning several cells (eq. 1.40);
// CPDI2 quadrilaterals and CPTI triangles (tracked corners).

#include <gtest/gtest.h>

#include <random>

#include "basis/CornerWeights.hpp"
#include "basis/Method.hpp"
#include "basis/Tent.hpp"
#include "core/Errors.hpp"

namespace impm {
namespace {

template <int Dim>
GridGeometry<Dim> unitGrid(int cells) {
  std::array<double, Dim> origin, length;
  std::array<int, Dim> n;
  origin.fill(0.0), length.fill(1.0), n.fill(cells);
  return makeGridGeometry<Dim>(origin, length, n);
}

// Random particles well inside the grid: centres, and domains up to `maxSpan` cells wide
// (for CPDI a random parallelogram in 2-D).
template <int Dim>
ParticleSet<Dim> randomParticles(const GridGeometry<Dim>& grid, int n, double maxSpan, bool skew,
                                 unsigned seed) {
  ParticleSet<Dim> ps(n);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  auto x = Kokkos::create_mirror_view(ps.x);
  auto r = Kokkos::create_mirror_view(ps.domain);
  auto id = Kokkos::create_mirror_view(ps.id);
  for (int p = 0; p < n; ++p) {
    id(p) = p;
    for (int d = 0; d < Dim; ++d) {
      const double h = grid.spacing[d];
      const double margin = maxSpan * h * (skew ? 2.0 : 1.0);
      x(p, d) = grid.origin[d] + margin + unit(rng) * (grid.upper(d) - grid.origin[d] - 2 * margin);
      for (int k = 0; k < Dim; ++k)
        r(p, d, k) = (d == k) ? (0.05 + unit(rng) * maxSpan / 2) * h
                              : (skew ? (unit(rng) - 0.5) * maxSpan * h / 2 : 0.0);
    }
  }
  Kokkos::deep_copy(ps.x, x);
  Kokkos::deep_copy(ps.domain, r);
  Kokkos::deep_copy(ps.id, id);
  return ps;
}

template <int Dim>
void expectPartitionOfUnityAndCompleteness(Method method, const GridGeometry<Dim>& grid,
                                           const ParticleSet<Dim>& ps, double tol) {
  const auto map = buildParticleGridMap(method, grid, ps);
  auto rowPtr = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), map.rowPtr);
  auto node = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), map.node);
  auto phi = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), map.phi);
  auto grad = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), map.grad);
  auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), ps.x);
  for (std::size_t p = 0; p < ps.size(); ++p) {
    double sumPhi = 0, sumPhiX[Dim] = {}, sumG[Dim] = {}, sumGX[Dim][Dim] = {};
    for (std::size_t k = rowPtr(p); k < rowPtr(p + 1); ++k) {
      int idx[Dim];
      grid.nodeIndex(node(k), idx);
      double xi[Dim];
      for (int d = 0; d < Dim; ++d)
        xi[d] = grid.nodeCoord(d, idx[d]);
      sumPhi += phi(k);
      for (int d = 0; d < Dim; ++d) {
        sumPhiX[d] += phi(k) * xi[d];
        sumG[d] += grad(k, d);
        for (int e = 0; e < Dim; ++e)
          sumGX[e][d] += xi[e] * grad(k, d);
      }
    }
    EXPECT_NEAR(sumPhi, 1.0, tol) << methodName(method) << " particle " << p;
    for (int d = 0; d < Dim; ++d) {
      EXPECT_NEAR(sumPhiX[d], x(p, d), tol) << methodName(method) << " particle " << p;
      EXPECT_NEAR(sumG[d] * grid.spacing[d], 0.0, tol) << methodName(method) << " particle " << p;
      for (int e = 0; e < Dim; ++e)
        EXPECT_NEAR(sumGX[e][d], e == d ? 1.0 : 0.0, tol) << methodName(method) << " p " << p;
    }
  }
}

TEST(Tent, IntegralAndAverage) {
  EXPECT_DOUBLE_EQ(tent(0.0), 1.0);
  EXPECT_DOUBLE_EQ(tent(0.25), 0.75);
  EXPECT_DOUBLE_EQ(tent(-1.5), 0.0);
  EXPECT_DOUBLE_EQ(tentIntegral(1.0), 1.0);
  EXPECT_DOUBLE_EQ(tentIntegral(0.0), 0.5);
  EXPECT_DOUBLE_EQ(tentAverage(-1.0, 1.0), 0.5);
  EXPECT_DOUBLE_EQ(tentAverage(0.5, 0.5), 0.5);
}

TEST(ParticleGridMap, PartitionOfUnityAndCompleteness1D) {
  const auto grid = unitGrid<1>(10);
  for (Method m : {Method::mpm, Method::gimp, Method::cpdi})
    for (double span : {0.5, 1.5, 3.5})
      expectPartitionOfUnityAndCompleteness(m, grid, randomParticles(grid, 200, span, false, 7),
                                            1e-12);
}

TEST(ParticleGridMap, PartitionOfUnityAndCompleteness2D) {
  const auto grid = unitGrid<2>(8);
  for (Method m : {Method::mpm, Method::gimp, Method::cpdi})
    expectPartitionOfUnityAndCompleteness(m, grid, randomParticles(grid, 200, 1.5, false, 11),
                                          1e-12);
  // CPDI parallelograms (sheared domains) keep both properties.
  expectPartitionOfUnityAndCompleteness(Method::cpdi, grid,
                                        randomParticles(grid, 200, 1.5, true, 13), 1e-12);
}

// A GIMP box whose stretch changed sign (F_xx < 0 under large shear) is a named numerical
// failure, not a map of meaningless weights.
TEST(ParticleGridMap, InsideOutGimpBoxIsANamedFailure) {
  const auto grid = unitGrid<2>(4);
  auto ps = randomParticles<2>(grid, 5, 0.5, false, 7);
  EXPECT_NO_THROW(buildParticleGridMap(Method::gimp, grid, ps));
  auto r = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), ps.domain);
  r(3, 0, 0) = -0.01;
  Kokkos::deep_copy(ps.domain, r);
  try {
    buildParticleGridMap(Method::gimp, grid, ps);
    FAIL() << "no error";
  } catch (const NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("particle 3"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("inside out"), std::string::npos) << e.what();
  }
}

TEST(ParticleGridMap, GimpIsTheExactTentAverage) {
  // A particle [0.13, 0.41] on a grid of spacing 0.1 straddles nodes 0.2, 0.3 and 0.4.
  const auto grid = unitGrid<1>(10);
  ParticleSet<1> ps(1);
  auto x = Kokkos::create_mirror_view(ps.x);
  auto r = Kokkos::create_mirror_view(ps.domain);
  x(0, 0) = 0.27, r(0, 0, 0) = 0.14;
  Kokkos::deep_copy(ps.x, x), Kokkos::deep_copy(ps.domain, r);
  const auto map = buildParticleGridMap(Method::gimp, grid, ps);
  auto node = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), map.node);
  auto phi = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), map.phi);
  auto grad = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), map.grad);
  ASSERT_EQ(map.numEntries(), 5u);  // nodes 1..5
  for (std::size_t k = 0; k < map.numEntries(); ++k) {
    // Midpoint rule with many points: exact up to O(1/n^2) on the kinks.
    const int n = 200000;
    double avg = 0, avgGrad = 0;
    for (int q = 0; q < n; ++q) {
      const double xq = 0.13 + (q + 0.5) * 0.28 / n;
      const double s = xq / 0.1 - node(k);
      avg += tent(s) / n;
      avgGrad += (s > -1 && s < 0 ? 10.0 : (s > 0 && s < 1 ? -10.0 : 0.0)) / n;
    }
    EXPECT_NEAR(phi(k), avg, 1e-9) << "node " << node(k);
    EXPECT_NEAR(grad(k, 0), avgGrad, 1e-3) << "node " << node(k);
  }
}

TEST(ParticleGridMap, CpdiParticleSpanningManyCellsTouchesOnlyCornerCells) {
  // A particle [0.05, 0.43] spans 4+ cells of spacing 0.1; its corners lie in cells 0 and 4.
  const auto grid = unitGrid<1>(10);
  ParticleSet<1> ps(1);
  auto x = Kokkos::create_mirror_view(ps.x);
  auto r = Kokkos::create_mirror_view(ps.domain);
  x(0, 0) = 0.24, r(0, 0, 0) = 0.19;
  Kokkos::deep_copy(ps.x, x), Kokkos::deep_copy(ps.domain, r);
  const auto map = buildParticleGridMap(Method::cpdi, grid, ps);
  auto node = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), map.node);
  auto phi = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), map.phi);
  auto grad = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), map.grad);
  ASSERT_EQ(map.numEntries(), 4u);
  const GlobalId expected[4] = {0, 1, 4, 5};
  // N_i at the corners 0.05 and 0.43: node 0: 0.5, node 1: 0.5, node 4: 0.7, node 5: 0.3.
  const double atLeft[4] = {0.5, 0.5, 0, 0}, atRight[4] = {0, 0, 0.7, 0.3};
  for (int k = 0; k < 4; ++k) {
    EXPECT_EQ(node(k), expected[k]);
    EXPECT_NEAR(phi(k), 0.5 * (atLeft[k] + atRight[k]), 1e-14);
    EXPECT_NEAR(grad(k, 0), (atRight[k] - atLeft[k]) / 0.38, 1e-12);
  }
  expectPartitionOfUnityAndCompleteness(Method::cpdi, grid, ps, 1e-14);
}

// The entries are written where each particle's node box reserves room and moved together
// when some box node has a negligible weight: every row must still be that particle's own.
TEST(ParticleGridMap, RowsWithLeftOutBoxNodesAreEachParticlesOwn) {
  const auto grid = unitGrid<1>(10);
  const double centre[3] = {0.24, 0.55, 0.8}, half[3] = {0.19, 0.025, 0.15};
  ParticleSet<1> ps(3);
  auto x = Kokkos::create_mirror_view(ps.x);
  auto r = Kokkos::create_mirror_view(ps.domain);
  for (int p = 0; p < 3; ++p)
    x(p, 0) = centre[p], r(p, 0, 0) = half[p];
  Kokkos::deep_copy(ps.x, x), Kokkos::deep_copy(ps.domain, r);
  for (Method m : {Method::gimp, Method::cpdi}) {
    const auto map = buildParticleGridMap(m, grid, ps);
    auto rowPtr = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), map.rowPtr);
    auto node = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), map.node);
    auto phi = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), map.phi);
    auto grad = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), map.grad);
    ASSERT_EQ(rowPtr(3), map.numEntries()) << methodName(m);
    for (int p = 0; p < 3; ++p) {
      ParticleSet<1> one(1);
      Kokkos::deep_copy(Kokkos::subview(one.x, 0, 0), centre[p]);
      Kokkos::deep_copy(Kokkos::subview(one.domain, 0, 0, 0), half[p]);
      const auto alone = buildParticleGridMap(m, grid, one);
      auto node1 = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), alone.node);
      auto phi1 = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), alone.phi);
      auto grad1 = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), alone.grad);
      ASSERT_EQ(rowPtr(p + 1) - rowPtr(p), alone.numEntries()) << methodName(m) << " " << p;
      for (std::size_t k = 0; k < alone.numEntries(); ++k) {
        EXPECT_EQ(node(rowPtr(p) + k), node1(k));
        EXPECT_EQ(phi(rowPtr(p) + k), phi1(k));
        EXPECT_EQ(grad(rowPtr(p) + k, 0), grad1(k, 0));
      }
    }
  }
  // CPDI's first and last particles reach the nodes of their corners' cells only (4 of the
  // 6 and of the 5 nodes of their boxes), so the rows were moved: 4 + 2 + 4 entries.
  EXPECT_EQ(buildParticleGridMap(Method::cpdi, grid, ps).numEntries(), 10u);
}

TEST(ParticleGridMap, DomainEndOnANodeDoesNotActivateTheNextNode) {
  // Two particles filling [0, 0.1] exactly: nodes 0 and 1 only, despite round-off.
  const auto grid = unitGrid<1>(10);
  ParticleSet<1> ps(2);
  auto x = Kokkos::create_mirror_view(ps.x);
  auto r = Kokkos::create_mirror_view(ps.domain);
  x(0, 0) = 0.025, x(1, 0) = 0.075, r(0, 0, 0) = r(1, 0, 0) = 0.025;
  Kokkos::deep_copy(ps.x, x), Kokkos::deep_copy(ps.domain, r);
  for (Method m : {Method::mpm, Method::gimp, Method::cpdi}) {
    const auto map = buildParticleGridMap(m, grid, ps);
    auto node = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), map.node);
    for (std::size_t k = 0; k < map.numEntries(); ++k)
      EXPECT_LE(node(k), 1) << methodName(m);
  }
}

TEST(ParticleGridMap, ParticleOutsideTheGridIsReported) {
  const auto grid = unitGrid<1>(10);
  ParticleSet<1> ps(3);
  auto x = Kokkos::create_mirror_view(ps.x);
  auto r = Kokkos::create_mirror_view(ps.domain);
  auto id = Kokkos::create_mirror_view(ps.id);
  for (int p = 0; p < 3; ++p)
    x(p, 0) = 0.5 + 0.3 * p, r(p, 0, 0) = 0.05, id(p) = 100 + p;
  Kokkos::deep_copy(ps.x, x), Kokkos::deep_copy(ps.domain, r), Kokkos::deep_copy(ps.id, id);
  for (Method m : {Method::mpm, Method::gimp, Method::cpdi}) {
    try {
      buildParticleGridMap(m, grid, ps);
      FAIL() << "no error for " << methodName(m);
    } catch (const NumericalError& e) {
      EXPECT_NE(std::string(e.what()).find("particle 102"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace impm

namespace impm {
namespace {

// Particles with tracked corners: random convex quadrilaterals (a parallelogram whose corners
// move by up to a fifth of its size) and, every third, triangles (the last corner repeated);
// x_p is the polygon's centroid, which the average of x over the domain reproduces.
ParticleSet<2> cornerParticles(const GridGeometry<2>& grid, int n, unsigned seed) {
  ParticleSet<2> ps(n);
  FieldSpec spec;
  spec.name = kCornersField, spec.shape = FieldShape::corners;
  ps.declare(spec);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  auto x = Kokkos::create_mirror_view(ps.x);
  auto c = Kokkos::create_mirror_view(ps.values(kCornersField));
  const double h = grid.spacing[0];
  for (int p = 0; p < n; ++p) {
    const double centre[2] = {0.3 + 0.4 * unit(rng), 0.3 + 0.4 * unit(rng)};
    const double size = (0.3 + 2.0 * unit(rng)) * h;
    const double sign[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    double q[4][2];
    for (int k = 0; k < 4; ++k)
      for (int d = 0; d < 2; ++d)
        q[k][d] = centre[d] + sign[k][d] * size / 2 + (unit(rng) - 0.5) * 0.4 * size;
    if (p % 3 == 0)
      q[3][0] = q[2][0], q[3][1] = q[2][1];
    double area = 0, cx = 0, cy = 0;
    for (int k = 0; k < 4; ++k) {
      const double* a = q[k];
      const double* b = q[(k + 1) % 4];
      const double w = a[0] * b[1] - b[0] * a[1];
      area += w, cx += (a[0] + b[0]) * w, cy += (a[1] + b[1]) * w;
      c(p, 2 * k) = q[k][0], c(p, 2 * k + 1) = q[k][1];
    }
    x(p, 0) = cx / (3 * area), x(p, 1) = cy / (3 * area);
  }
  Kokkos::deep_copy(ps.x, x);
  Kokkos::deep_copy(ps.values(kCornersField), c);
  return ps;
}

TEST(CornerWeights, PartitionOfUnityAndCompletenessOnQuadrilateralsAndTriangles) {
  const auto grid = unitGrid<2>(8);
  expectPartitionOfUnityAndCompleteness(Method::cpdi, grid, cornerParticles(grid, 300, 5), 1e-12);
}

TEST(CornerWeights, ParallelogramGivesCpdiAndTriangleGivesCpti) {
  const auto grid = unitGrid<2>(4);
  ParticleSet<2> ps(1);
  auto x = Kokkos::create_mirror_view(ps.x);
  auto r = Kokkos::create_mirror_view(ps.domain);
  x(0, 0) = 0.41, x(0, 1) = 0.52;
  r(0, 0, 0) = 0.2, r(0, 1, 0) = 0.05, r(0, 0, 1) = -0.07, r(0, 1, 1) = 0.16;
  Kokkos::deep_copy(ps.x, x), Kokkos::deep_copy(ps.domain, r);
  CpdiWeights<2> cpdi(grid, ps);
  FieldSpec spec;
  spec.name = kCornersField, spec.shape = FieldShape::corners;
  ps.declare(spec);
  auto c = ps.values(kCornersField);
  const double sign[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  for (int k = 0; k < 4; ++k)
    for (int d = 0; d < 2; ++d)
      c(0, 2 * k + d) = x(0, d) + sign[k][0] * r(0, d, 0) + sign[k][1] * r(0, d, 1);
  CornerWeights<2> corners(grid, ps, c);
  int lo[2], hi[2];
  CpdiWeights<2>::Particle cpdiAt;
  CornerWeights<2>::Particle cornersAt;
  ASSERT_TRUE(cpdi.nodeBox(0, cpdiAt, lo, hi, 0.0));
  ASSERT_TRUE(corners.nodeBox(0, cornersAt, lo, hi, 0.0));
  for (int j = 0; j <= 4; ++j)
    for (int i = 0; i <= 4; ++i) {
      const int node[2] = {i, j};
      double phi1, phi2, g1[2], g2[2];
      cpdi.evaluate(cpdiAt, lo, node, phi1, g1);
      corners.evaluate(cornersAt, lo, node, phi2, g2);
      EXPECT_NEAR(phi1, phi2, 1e-14);
      for (int d = 0; d < 2; ++d)
        EXPECT_NEAR(g1[d], g2[d], 1e-12);
    }
  // A triangle: w_c = 1/3 (CPTI), g_c the inward edge normals over twice the area.
  const double t[3][2] = {{0.1, 0.2}, {0.8, 0.35}, {0.3, 0.9}};
  for (int k = 0; k < 4; ++k)
    for (int d = 0; d < 2; ++d)
      c(0, 2 * k + d) = t[k < 3 ? k : 2][d];
  double w[4], g[4][2];
  corners.cornerWeights(0, w, g);
  const double area2 =
      (t[1][0] - t[0][0]) * (t[2][1] - t[0][1]) - (t[2][0] - t[0][0]) * (t[1][1] - t[0][1]);
  // Tensor corners 0, 1 are stored 0, 1; tensor 2 and 3 are both the third corner.
  EXPECT_NEAR(w[0], 1.0 / 3, 1e-14);
  EXPECT_NEAR(w[1], 1.0 / 3, 1e-14);
  EXPECT_NEAR(w[2] + w[3], 1.0 / 3, 1e-14);
  // grad lambda_0 = (y1 - y2, x2 - x1) / (2A).
  EXPECT_NEAR(g[0][0], (t[1][1] - t[2][1]) / area2, 1e-12);
  EXPECT_NEAR(g[0][1], (t[2][0] - t[1][0]) / area2, 1e-12);
  EXPECT_NEAR(g[2][0] + g[3][0], (t[0][1] - t[1][1]) / area2, 1e-12);
}

}  // namespace
}  // namespace impm

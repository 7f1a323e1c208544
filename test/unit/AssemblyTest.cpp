// assembly: the deformation gradient from grid displacements (both kinematics), the
// grid-to-particle update (eq. 1.23), the internal force's translation invariance, and the
// body forces' work.

#include <gtest/gtest.h>

#include <array>
#include <set>

#include <Teuchos_DefaultComm.hpp>

#include "assembly/Energy.hpp"
#include "assembly/EntryDofs.hpp"
#include "assembly/Forces.hpp"
#include "assembly/Graph.hpp"
#include "assembly/Kinematics.hpp"
#include "assembly/Mass.hpp"
#include "assembly/ParticleUpdate.hpp"
#include "assembly/RowAccumulator.hpp"
#include "basis/Method.hpp"
#include "core/NodeOwnership.hpp"

namespace impm {
namespace {

struct Fixture {
  GridGeometry<1> grid = makeGridGeometry<1>({0.0}, {1.0}, {4});
  ParticleSet<1> ps{6};
  ParticleGridMap<1> map;
  Kokkos::View<LO*> lids;  // node id == DOF index here
  Fixture(Method method) {
    auto x = Kokkos::create_mirror_view(ps.x);
    auto r = Kokkos::create_mirror_view(ps.domain);
    auto V = Kokkos::create_mirror_view(ps.volume);
    auto A = Kokkos::create_mirror_view(ps.section);
    auto F = Kokkos::create_mirror_view(ps.F);
    for (int p = 0; p < 6; ++p) {
      x(p, 0) = 0.1 + 0.15 * p, r(p, 0, 0) = 0.07, V(p) = 0.14, A(p) = 1.0;
      F(p, 0, 0) = 1.0 + 0.1 * p;  // some prior deformation
    }
    Kokkos::deep_copy(ps.x, x), Kokkos::deep_copy(ps.X, x), Kokkos::deep_copy(ps.domain, r);
    Kokkos::deep_copy(ps.domain0, r), Kokkos::deep_copy(ps.volume, V);
    Kokkos::deep_copy(ps.volume0, V), Kokkos::deep_copy(ps.section, A), Kokkos::deep_copy(ps.F, F);
    map = buildParticleGridMap(method, grid, ps);
    lids = Kokkos::View<LO*>("lids", map.numEntries());
    auto node = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), map.node);
    auto l = Kokkos::create_mirror_view(lids);
    for (std::size_t k = 0; k < map.numEntries(); ++k)
      l(k) = static_cast<LO>(node(k));
    Kokkos::deep_copy(lids, l);
  }
  // Grid displacement du_i = a x_i + b.
  Kokkos::View<double**, Kokkos::LayoutLeft> linearField(double a, double b) {
    Kokkos::View<double**, Kokkos::LayoutLeft> du("du", 5, 1);
    auto h = Kokkos::create_mirror_view(du);
    for (int i = 0; i < 5; ++i)
      h(i, 0) = a * grid.nodeCoord(0, i) + b;
    Kokkos::deep_copy(du, h);
    return du;
  }
};

// The body forces' work over a step, sum_p f_p . (u_p - u_p^before) over all ranks, and the
// test that lets a rank whose particles carry no force skip it: any non-zero component
// counts, however small (a subnormal one), a negative zero does not (it does no work).
TEST(Energy, BodyForceWorkIsSkippedOnlyWithoutForces) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  ParticleSet<2> ps(5);
  ParticleSet<2>::Vectors before("u before", 5);
  auto f = Kokkos::create_mirror_view(ps.force);
  auto u = Kokkos::create_mirror_view(ps.u), u0 = Kokkos::create_mirror_view(before);
  const auto carries = [&](double f31) {
    f(3, 1) = f31;
    Kokkos::deep_copy(ps.force, f);
    return carriesForces(ps);
  };
  EXPECT_FALSE(carries(0.0));
  EXPECT_FALSE(carries(-0.0));
  EXPECT_TRUE(carries(-1e-310));
  double work = 0.0;
  for (int p = 0; p < 5; ++p)
    for (int d = 0; d < 2; ++d) {
      f(p, d) = 1.0 + p - 2.0 * d, u(p, d) = 0.5 * p + d, u0(p, d) = 0.25 * d;
      work += f(p, d) * (u(p, d) - u0(p, d));
    }
  Kokkos::deep_copy(ps.force, f), Kokkos::deep_copy(ps.u, u), Kokkos::deep_copy(before, u0);
  const double ranks = comm->getSize();
  EXPECT_NEAR(bodyForceWork<2>(ps, before, true, 3.0, *comm), 3.0 * ranks * work, 1e-12);
  // Without forces on rank 0 the others' work is still summed (the call stays collective).
  const bool loaded = comm->getRank() != 0;
  EXPECT_NEAR(bodyForceWork<2>(ps, before, loaded, 1.0, *comm), (ranks - 1) * work, 1e-12);
}

TEST(Kinematics, LinearGridFieldGivesHomogeneousDeformation) {
  for (Method method : {Method::mpm, Method::gimp, Method::cpdi}) {
    Fixture f(method);
    auto du = f.linearField(0.2, 0.05);
    ParticleSet<1>::Tensors Ftl("F", 6), Ful("F", 6);
    trialDeformationGradient<1>(Kinematics::totalLagrangian, f.map, f.lids, du, f.ps.F, Ftl);
    trialDeformationGradient<1>(Kinematics::updatedLagrangian, f.map, f.lids, du, f.ps.F, Ful);
    auto tl = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), Ftl);
    auto ul = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), Ful);
    for (int p = 0; p < 6; ++p) {
      const double Fn = 1.0 + 0.1 * p;
      EXPECT_NEAR(tl(p, 0, 0), Fn + 0.2, 1e-14) << methodName(method);  // F^n + grad du
      EXPECT_NEAR(ul(p, 0, 0), 1.2 * Fn, 1e-14) << methodName(method);  // (1 + grad du) F^n
    }
  }
}

TEST(ParticleUpdate, MovesParticlesWithTheGridAndScalesDomains) {
  Fixture f(Method::cpdi);
  auto du = f.linearField(0.2, 0.05);
  ParticleSet<1>::Tensors F("F", 6), P("P", 6);
  trialDeformationGradient<1>(Kinematics::updatedLagrangian, f.map, f.lids, du, f.ps.F, F);
  Kokkos::deep_copy(P, 3.0);
  commitDeformation<1>(Kinematics::updatedLagrangian, F, P, f.ps);
  displaceParticles<1>(f.map, f.lids, du, f.ps);
  auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), f.ps.x);
  auto u = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), f.ps.u);
  auto V = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), f.ps.volume);
  auto r = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), f.ps.domain);
  auto s = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), f.ps.stress);
  for (int p = 0; p < 6; ++p) {
    const double X = 0.1 + 0.15 * p, Fp = 1.2 * (1.0 + 0.1 * p);
    EXPECT_NEAR(u(p, 0), 0.2 * X + 0.05, 1e-14);  // u_p = sum phi_ip u_i, exact for linear u
    EXPECT_NEAR(x(p, 0), 1.2 * X + 0.05, 1e-14);
    EXPECT_NEAR(V(p), Fp * 0.14, 1e-14);        // V = J V0
    EXPECT_NEAR(r(p, 0, 0), Fp * 0.07, 1e-14);  // r = F r0
    EXPECT_NEAR(s(p, 0, 0), 3.0, 1e-14);        // 1-D: P F / J = P
  }
  // Total Lagrangian: the domain is drawn for output from the particles' F alone.
  Kokkos::deep_copy(f.ps.domain, 0.0);
  followDeformation<1>(f.ps);
  Kokkos::deep_copy(r, f.ps.domain);
  for (int p = 0; p < 6; ++p)
    EXPECT_NEAR(r(p, 0, 0), 1.2 * (1.0 + 0.1 * p) * 0.07, 1e-14);
}

TEST(Forces, InternalForceSumsToZero) {
  // sum_i G_ip = 0: a stress state exerts no net force on the grid.
  for (Method method : {Method::fem, Method::mpm, Method::gimp, Method::cpdi}) {
    Fixture f(method);
    ParticleSet<1>::Tensors P("P", 6);
    auto h = Kokkos::create_mirror_view(P);
    for (int p = 0; p < 6; ++p)
      h(p, 0, 0) = 1.0 + p * p;
    Kokkos::deep_copy(P, h);
    Kokkos::View<double**, Kokkos::LayoutLeft> fint("f", 5, 1);
    addInternalForce<1>(f.map, f.lids, f.ps, P, fint);
    auto fh = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), fint);
    double sum = 0, size = 0;
    for (int i = 0; i < 5; ++i)
      sum += fh(i, 0), size += std::abs(fh(i, 0));
    EXPECT_GT(size, 1.0);
    EXPECT_NEAR(sum, 0.0, 1e-13 * size) << methodName(method);
  }
}
}  // namespace
}  // namespace impm

namespace impm {
namespace {

TEST(Mass, ConsistentRowsSumToTheLumpedMassAndInertiaMatchesTheMatrix) {
  for (Method method : {Method::mpm, Method::gimp, Method::cpdi}) {
    Fixture f(method);
    auto m = Kokkos::create_mirror_view(f.ps.mass);
    for (int p = 0; p < 6; ++p)
      m(p) = 1.0 + 0.5 * p;
    Kokkos::deep_copy(f.ps.mass, m);
    // Lumped mass, and M times a grid field a computed particle-wise (consistent).
    Kokkos::View<double**, Kokkos::LayoutLeft> lumped("m", 5, 1), ma("Ma", 5, 1), ones("1", 5, 1);
    Kokkos::deep_copy(ones, 1.0);
    addLumpedMass<1>(f.map, f.lids, f.ps.mass, lumped);
    addConsistentInertiaForce<1>(f.map, f.lids, f.ps.mass, ones, ma);
    auto l = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), lumped);
    auto c = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), ma);
    double total = 0;
    for (int i = 0; i < 5; ++i) {
      EXPECT_NEAR(c(i, 0), l(i, 0), 1e-14) << methodName(method);  // rows of M sum to m_i
      total += l(i, 0);
    }
    EXPECT_NEAR(total, 1.0 * 6 + 0.5 * 15, 1e-13) << methodName(method);  // mass is conserved
    // Momentum: sum_i (sum_p m_p phi_ip v_p) = sum_p m_p v_p.
    Kokkos::deep_copy(f.ps.v, 2.0);
    Kokkos::View<double**, Kokkos::LayoutLeft> p("p", 5, 1);
    particleToGrid<1>(f.map, f.lids, f.ps.mass, f.ps.v, p);
    auto ph = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p);
    double momentum = 0;
    for (int i = 0; i < 5; ++i)
      momentum += ph(i, 0);
    EXPECT_NEAR(momentum, 2.0 * total, 1e-13) << methodName(method);
  }
}

TEST(GridToParticle, FlipAddsTheChangePicTakesTheField) {
  Fixture f(Method::cpdi);
  Kokkos::deep_copy(f.ps.v, 1.0);
  auto vOld = f.linearField(0.0, 0.5), vNew = f.linearField(0.0, 0.75);
  auto aNew = f.linearField(2.0, 0.0);
  gridToParticleVelocity<1>(f.map, f.lids, vOld, vNew, aNew, 1.0, f.ps);  // FLIP
  auto v = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), f.ps.v);
  auto a = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), f.ps.a);
  for (int p = 0; p < 6; ++p) {
    EXPECT_NEAR(v(p, 0), 1.25, 1e-14);
    EXPECT_NEAR(a(p, 0), 2.0 * (0.1 + 0.15 * p), 1e-14);  // linear fields are reproduced
  }
  gridToParticleVelocity<1>(f.map, f.lids, vOld, vNew, aNew, 0.0, f.ps);  // PIC
  v = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), f.ps.v);
  for (int p = 0; p < 6; ++p)
    EXPECT_NEAR(v(p, 0), 0.75, 1e-14);
}

namespace {

using HostMatrix = KokkosSparse::CrsMatrix<double, int, Kokkos::DefaultHostExecutionSpace>;

// A matrix of `columnCount` columns with the rows' columns given (row i: columns[rowMap[i]]
// to columns[rowMap[i + 1] - 1]) and zero values.
HostMatrix zeroMatrix(const std::vector<int>& rowMap, const std::vector<int>& columns,
                      int columnCount) {
  const int rows = static_cast<int>(rowMap.size()) - 1, entries = rowMap.back();
  typename HostMatrix::row_map_type::non_const_type ptr("ptr", rows + 1);
  typename HostMatrix::index_type::non_const_type col("col", entries);
  typename HostMatrix::values_type::non_const_type values("values", entries);
  for (int i = 0; i <= rows; ++i)
    ptr(i) = rowMap[i];
  for (int k = 0; k < entries; ++k)
    col(k) = columns[k];
  return HostMatrix("K", rows, columnCount, entries, values, ptr, col);
}

}  // namespace

// The accumulator must add exactly what KokkosSparse's own search adds, whatever the order
// of the columns: increasing (the fast path), decreasing (wrapping around every time),
// repeated, and absent from the row (ignored).
TEST(RowAccumulator, AddsWhatSumIntoValuesAddsInAnyColumnOrder) {
  using Matrix = HostMatrix;
  // row 0: columns 1 3 4 8; row 1: columns 0 2 5
  const auto fresh = [] { return zeroMatrix({0, 4, 7}, {1, 3, 4, 8, 0, 2, 5}, 9); };
  const std::vector<std::pair<int, double>> adds = {{1, 1.0},   {3, 2.0},  {8, 4.0},  {4, 8.0},
                                                    {1, 16.0},  {7, 32.0}, {8, 64.0}, {1, 128.0},
                                                    {5, 256.0}, {0, 512.0}};
  Matrix expected = fresh(), actual = fresh();
  for (int row = 0; row < 2; ++row) {
    RowAccumulator<Matrix> sum(actual, row);
    for (const auto& [c, v] : adds) {
      const double value = v * (row + 1);
      expected.sumIntoValues(row, &c, 1, &value, false, false);
      sum.add(c, value);
    }
  }
  for (int k = 0; k < 7; ++k)
    EXPECT_EQ(actual.values(k), expected.values(k)) << "entry " << k;
  EXPECT_EQ(actual.values(0), 145.0);   // column 1 of row 0: 1 + 16 + 128
  EXPECT_EQ(actual.values(2), 8.0);     // column 4; column 7 is not in the row
  EXPECT_EQ(actual.values(4), 1024.0);  // row 1, column 0, after column 5
}

// A node's rows take each column's position from the first row; where the second row's
// columns differ (here an extra column 2 shifts its others), it must still add exactly what
// sumIntoValues adds, and columns absent from one row or both are ignored there.
TEST(NodeRowsAccumulator, AddsWhatSumIntoValuesAddsWhereTheRowsDiffer) {
  using Matrix = HostMatrix;
  // a node's rows 1 (columns 1 3 4 8 9) and 2 (columns 1 2 3 4) after an unrelated row 0
  const auto fresh = [] {
    return zeroMatrix({0, 4, 9, 13}, {0, 5, 6, 7, 1, 3, 4, 8, 9, 1, 2, 3, 4}, 10);
  };
  const std::vector<std::pair<int, double>> adds = {{1, 1.0},   {3, 2.0},  {4, 4.0},  {8, 8.0},
                                                    {2, 16.0},  {9, 32.0}, {1, 64.0}, {0, 128.0},
                                                    {4, 256.0}, {3, 512.0}};
  Matrix expected = fresh(), actual = fresh();
  NodeRowsAccumulator<Matrix, 2> sum(actual, 1);
  for (const auto& [c, v] : adds) {
    const double values[2] = {v, 3.0 * v};
    for (int a = 0; a < 2; ++a)
      expected.sumIntoValues(1 + a, &c, 1, &values[a], false, false);
    sum.add(c, values);
  }
  for (int k = 0; k < 13; ++k)
    EXPECT_EQ(actual.values(k), expected.values(k)) << "entry " << k;
  EXPECT_EQ(actual.values(4), 65.0);          // row 1, column 1: 1 + 64
  EXPECT_EQ(actual.values(10), 3.0 * 16.0);   // row 2, column 2, which row 1 lacks
  EXPECT_EQ(actual.values(12), 3.0 * 260.0);  // row 2, column 4: 3 (4 + 256)
  EXPECT_EQ(actual.values(0), 0.0);           // the rows before are not touched
}

// The updated-Lagrangian tangent An is the derivative of the step-start stress Pn = P(f Fn)
// Fn^T / J_n with respect to the step's increment f.  For a linear law P = M : F, Pn is
// linear in f, so An_aBcD must equal Pn(f + e_cD) - Pn(f) to round-off, whatever Fn is.
TEST(Kinematics, StepStartTangentIsTheDerivativeOfStepStartStress) {
  constexpr int D = 2;
  const double Fn0[D][D] = {{1.3, 0.2}, {-0.1, 0.8}}, f[D][D] = {{1.05, 0.03}, {0.02, 0.97}};
  double M[D][D][D][D];
  for (int k = 0; k < 16; ++k)  // no symmetry to hide a transposed index
    (&M[0][0][0][0])[k] = 0.1 * k * k - 0.7 * k + 0.3;
  const int cases = 1 + D * D;  // f, then f + e_cD
  ParticleSet<D>::Tensors Fn("Fn", cases), P("P", cases), Pn("Pn", cases);
  Tangents<D> A("A", cases), An("An", cases);
  for (int q = 0; q < cases; ++q) {
    double fq[D][D];
    for (int a = 0; a < D; ++a)
      for (int b = 0; b < D; ++b)
        fq[a][b] = f[a][b] + (q > 0 && (q - 1) == a * D + b ? 1.0 : 0.0);
    double F[D][D] = {};
    for (int a = 0; a < D; ++a)
      for (int b = 0; b < D; ++b)
        for (int c = 0; c < D; ++c)
          F[a][b] += fq[a][c] * Fn0[c][b];
    for (int a = 0; a < D; ++a)
      for (int b = 0; b < D; ++b) {
        Fn(q, a, b) = Fn0[a][b];
        P(q, a, b) = 0;
        for (int c = 0; c < D; ++c)
          for (int e = 0; e < D; ++e) {
            P(q, a, b) += M[a][b][c][e] * F[c][e];
            A(q, a, b, c, e) = M[a][b][c][e];
          }
      }
  }
  stressRelativeToStepStart<D>(Kinematics::updatedLagrangian, Fn, P, A, Pn, An);
  for (int c = 0; c < D; ++c)
    for (int d = 0; d < D; ++d)
      for (int a = 0; a < D; ++a)
        for (int b = 0; b < D; ++b)
          EXPECT_NEAR(An(0, a, b, c, d), Pn(1 + c * D + d, a, b) - Pn(0, a, b), 1e-12)
              << a << b << c << d;
  // In place, as the step does it (An is A): the same tangent, bit for bit.
  stressRelativeToStepStart<D>(Kinematics::updatedLagrangian, Fn, P, A, Pn, A);
  for (int k = 0; k < 16; ++k)
    EXPECT_EQ(A.data()[k], An.data()[k]) << k;
}

// The entries' overlap indices come from a table over the range of their nodes when it is
// narrow, from the map's lookup otherwise: both must be the map's local index, in 1-D and
// 2-D (a node's first component).
template <int Dim>
void expectEntryDofsOfTheOverlapMap(const std::vector<GlobalId>& nodes) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  std::array<int, Dim> cells;
  cells.fill(Dim == 1 ? 2000 : 100);
  std::array<double, Dim> lower{}, upper;
  upper.fill(1.0);
  NodeOwnership<Dim> own(makeGridGeometry<Dim>(lower, upper, cells), comm);
  ParticleGridMap<Dim> map;
  map.rowPtr = decltype(map.rowPtr)("rowPtr", 2);
  map.rowPtr(1) = nodes.size();
  map.node = decltype(map.node)("node", nodes.size());
  for (std::size_t k = 0; k < nodes.size(); ++k)
    map.node(k) = nodes[k];
  DofMap<Dim> dofs(own, nodes, {});
  const auto lids = entryDofs(map, *dofs.overlapMap());
  for (std::size_t k = 0; k < nodes.size(); ++k)
    EXPECT_EQ(lids(k), dofs.overlapMap()->getLocalElement(nodes[k] * Dim)) << "entry " << k;
}

TEST(EntryDofs, AreTheOverlapMapsIndicesOfNarrowAndWideNodeRanges) {
  const GlobalId rank = Teuchos::DefaultComm<int>::getComm()->getRank();
  expectEntryDofsOfTheOverlapMap<1>({7 + rank, 5, 6, 5, 9, 8, 7, 6});  // narrow: tabled
  expectEntryDofsOfTheOverlapMap<1>({1900, 3, 1900, 1000 + rank});     // wide: looked up
  expectEntryDofsOfTheOverlapMap<2>({203, 202, 204 + rank, 203, 205, 202});
  expectEntryDofsOfTheOverlapMap<2>({10000, 12, 101 + rank});
}

// Every rank's particles couple a hub node with nodes no other rank touches, so the hub's
// owner learns most of the hub row's columns only from the other ranks' shared rows: the
// column map made ahead of the graph must hold them, or the owned row loses them.
TEST(Graph, OwnedRowsHoldTheColumnsOfEveryRanksParticles) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  const int size = comm->getSize(), rank = comm->getRank();
  constexpr GlobalId hub = 1;
  NodeOwnership<1> own(makeGridGeometry<1>({0.0}, {1.0}, {4 * size + 4}), comm);
  // Particle q of every rank touches {hub, 2 + 4 r + q} and {2 + 4 r + q, 3 + 4 r + q}.
  std::vector<std::vector<GlobalId>> all;  // the particles of every rank, rank by rank
  for (int r = 0; r < size; ++r)
    for (GlobalId q = 0; q < 2; ++q) {
      const GlobalId a = 2 + 4 * r + 2 * q;
      all.push_back({hub, a}), all.push_back({a, a + 1});
    }
  const std::size_t first = 4 * rank, count = 4;
  ParticleGridMap<1> map;
  map.rowPtr = decltype(map.rowPtr)("rowPtr", count + 1);
  map.node = decltype(map.node)("node", 2 * count);
  map.phi = decltype(map.phi)("phi", 2 * count);
  map.grad = decltype(map.grad)("grad", 2 * count);
  std::vector<GlobalId> touched;
  for (std::size_t p = 0; p < count; ++p) {
    map.rowPtr(p + 1) = 2 * (p + 1);
    for (int k = 0; k < 2; ++k)
      map.node(2 * p + k) = all[first + p][k], touched.push_back(all[first + p][k]);
  }
  DofMap<1> dofs(own, touched, {});
  const auto rows = entryDofs(map, *dofs.overlapMap());
  const auto graph = buildGraph(map, rows, dofs, {});

  // The assembly's rule: an overlap-map index is the same unknown's column index.
  const auto& overlap = *dofs.overlapMap();
  for (LO i = 0; i < static_cast<LO>(overlap.getNodeNumElements()); ++i)
    EXPECT_EQ(graph->getColMap()->getGlobalElement(i), overlap.getGlobalElement(i));

  const auto owned = dofs.ownedMap()->getNodeElementList();
  for (const GO row : owned) {
    std::set<GO> expected;
    for (const auto& nodes : all)
      if (std::find(nodes.begin(), nodes.end(), row) != nodes.end())
        expected.insert(nodes.begin(), nodes.end());
    Teuchos::Array<GO> cols(graph->getNumEntriesInGlobalRow(row));
    std::size_t n = 0;
    graph->getGlobalRowCopy(row, cols(), n);
    EXPECT_EQ(std::set<GO>(cols.begin(), cols.begin() + n), expected) << "row " << row;
  }

  // Each node coupled with itself only (an explicit step's lumped mass), and every rank
  // coupling the hub with its first particle's other node: those couplings reach the hub's
  // owner, and every other row holds its own column alone.
  const GlobalId mine = 2 + 4 * rank;
  const auto diagonal = buildGraph(map, rows, dofs, {{hub, mine}}, NodeCoupling::self);
  for (const GO row : owned) {
    std::set<GO> expected{row};
    for (int r = 0; r < size && row == hub; ++r)
      expected.insert(2 + 4 * r);
    Teuchos::Array<GO> cols(diagonal->getNumEntriesInGlobalRow(row));
    std::size_t n = 0;
    diagonal->getGlobalRowCopy(row, cols(), n);
    EXPECT_EQ(std::set<GO>(cols.begin(), cols.begin() + n), expected) << "row " << row;
  }
}

}  // namespace
}  // namespace impm

// material: the 1-D laws through the first-Piola interface (stress, tangent = dP/dF and
// energy with dW/dF = P for every model), position-dependent parameters, the formula law's
// finite-difference tangent, and clear errors for inadmissible values.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>

#include "core/Errors.hpp"
#include "core/Parameters.hpp"
#include "material/HenckyLaw.hpp"
#include "material/MaterialFactory.hpp"
#include "material/MaterialState.hpp"

namespace impm {
namespace {

std::shared_ptr<Material<1>> material(Teuchos::ParameterList p) {
  validateParameters(p, materialValidParameters());
  return createMaterial<1>("m", p);
}

std::shared_ptr<Material<1>> linear(const std::string& E) {
  Teuchos::ParameterList p;
  p.set("Model", std::string("linear"));
  p.set("E", E);
  return material(p);
}

ParticleSet<1> particlesAt(const std::vector<double>& X) {
  ParticleSet<1> ps(X.size());
  auto h = Kokkos::create_mirror_view(ps.X);
  for (std::size_t p = 0; p < X.size(); ++p)
    h(p, 0) = X[p];
  Kokkos::deep_copy(ps.X, h);
  return ps;
}

// The particles with the materials' variables, initialised (fresh start).
template <int Dim>
void prepare(ParticleSet<Dim>& ps, const Materials<Dim>& materials) {
  declareMaterialVariables(ps, materials);
  initializeMaterials(ps, materials, true);
}

struct LawValues {
  std::vector<double> P, A, W;
};

// P, dP/dF and W of material m at particles with reference positions X and stretches F.
LawValues evaluate(const std::shared_ptr<Material<1>>& m, const std::vector<double>& X,
                   const std::vector<double>& F) {
  auto ps = particlesAt(X);
  const Materials<1> materials = {m};
  prepare(ps, materials);
  const std::size_t n = X.size();
  ParticleSet<1>::Tensors Fv("F", n), P("P", n);
  Material<1>::Tangents A("A", n);
  ParticleSet<1>::Scalars W("W", n);
  auto Fh = Kokkos::create_mirror_view(Fv);
  for (std::size_t p = 0; p < n; ++p)
    Fh(p, 0, 0) = F[p];
  Kokkos::deep_copy(Fv, Fh);
  m->firstPiola(evaluationOf(ps, materials, 0, Fv), P, A);
  m->energyDensity(evaluationOf(ps, materials, 0, Fv), W);
  auto Ph = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), P);
  auto Ah = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), A);
  auto Wh = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), W);
  LawValues v;
  for (std::size_t p = 0; p < n; ++p)
    v.P.push_back(Ph(p, 0, 0)), v.A.push_back(Ah(p, 0, 0, 0, 0)), v.W.push_back(Wh(p));
  return v;
}

Teuchos::ParameterList model(const std::string& name) {
  Teuchos::ParameterList p;
  p.set("Model", name);
  if (name == "formula") {
    p.set("Stress", std::string("(1 + x)*eps + 10*eps^3"));
  } else {
    p.set("E", std::string("1 + x"));
    if (name == "cubic")
      p.set("C", 10.0);
  }
  return p;
}

// Every model: W(1) = 0, P(1) = 0, dW/dF = P and dP/dF = A (central differences of the
// values the material returns, step 1e-5: truncation error about 1e-10).
class EveryLaw : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryLaw, TangentAndEnergyAreConsistentWithTheStress) {
  auto m = material(model(GetParam()));
  const double h = 1e-5;
  for (double F : {0.7, 1.0, 1.13, 1.6}) {
    const std::vector<double> X = {0.3, 0.3, 0.3};
    const auto v = evaluate(m, X, {F - h, F, F + h});
    EXPECT_NEAR(v.A[1], (v.P[2] - v.P[0]) / (2 * h), 1e-7 * std::max(1.0, std::abs(v.A[1])))
        << GetParam() << " at F = " << F;
    EXPECT_NEAR(v.P[1], (v.W[2] - v.W[0]) / (2 * h), 1e-7 * std::max(1.0, std::abs(v.P[1])))
        << GetParam() << " at F = " << F;
  }
  const auto rest = evaluate(m, {0.3}, {1.0});
  EXPECT_NEAR(rest.P[0], 0.0, 1e-15) << GetParam();
  EXPECT_NEAR(rest.W[0], 0.0, 1e-15) << GetParam();
  EXPECT_NEAR(rest.A[0], 1.3, 1e-9) << GetParam() << ": the small-strain modulus E(x)";
}

INSTANTIATE_TEST_SUITE_P(Material, EveryLaw,
                         ::testing::Values("linear", "linear-finite", "cubic", "neo-hookean-1d",
                                           "hencky-1d", "formula"));

TEST(ElasticLaws1D, ClosedFormValues) {
  const double e = 0.2, F = 1.0 + e, E = 1.5;  // at x = 0.5
  auto cubic = evaluate(material(model("cubic")), {0.5}, {F});
  EXPECT_NEAR(cubic.P[0], E * e + 10 * e * e * e, 1e-15);
  EXPECT_NEAR(cubic.A[0], E + 30 * e * e, 1e-14);
  auto neo = evaluate(material(model("neo-hookean-1d")), {0.5}, {F});
  EXPECT_NEAR(neo.P[0], 0.5 * E * (F - 1 / F), 1e-15);
  EXPECT_NEAR(neo.A[0], 0.5 * E * (1 + 1 / (F * F)), 1e-15);
  EXPECT_TRUE(material(model("linear"))->isLinear());
  EXPECT_FALSE(material(model("cubic"))->isLinear());
  EXPECT_FALSE(material(model("formula"))->isLinear());
}

TEST(ElasticLaws1D, NeoHookeanRefusesNonPositiveStretch) {
  auto m = material(model("neo-hookean-1d"));
  try {
    evaluate(m, {0.1, 0.2}, {0.5, -0.25});
    FAIL() << "no error";
  } catch (const NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("not defined at F = -0.25"), std::string::npos)
        << e.what();
  }
}

// The central difference of the formula law with step delta = eps_mach^(1/3) max(|eps|,
// 1e-3) has truncation error sigma''' delta^2 / 6 and round-off error about eps_mach
// |exp(3 eps)| / delta (the formula subtracts 1 from exp(3 eps)); the test asserts that
// bound, and that it stays below 1e-7 of the tangent even at eps = 0, where the floor
// makes delta smallest (6e-9).
TEST(FormulaLaw1D, FiniteDifferenceTangentIsAccurate) {
  auto p = model("formula");
  p.set("Stress", std::string("exp(3*eps) - 1 + x*eps"));
  auto m = material(p);
  const double machine = std::numeric_limits<double>::epsilon();
  for (double e : {0.0, 1e-6, -0.01, 0.4}) {
    const auto v = evaluate(m, {0.5}, {1.0 + e});
    const double exact = 3 * std::exp(3 * e) + 0.5;
    const double delta = std::cbrt(machine) * std::max(std::abs(e), 1e-3);
    const double bound =
        2 * machine * std::exp(3 * e) / delta + 27 * std::exp(3 * e) * delta * delta / 6;
    EXPECT_LT(bound, 1e-7 * exact) << "eps = " << e;
    EXPECT_NEAR(v.A[0], exact, bound) << "eps = " << e;
    EXPECT_NEAR(v.P[0], std::exp(3 * e) - 1 + 0.5 * e, 1e-14) << "eps = " << e;
  }
}

TEST(FormulaLaw1D, GivenTangentIsUsed) {
  auto p = model("formula");
  p.set("Tangent", std::string("42"));
  const auto v = evaluate(material(p), {0.5}, {1.2});
  EXPECT_DOUBLE_EQ(v.A[0], 42.0);
}

// A law must be stiff at rest (the first Newton step and the explicit time step need it).
TEST(FormulaLaw1D, LawWithoutStiffnessAtRestIsAnInputError) {
  for (const auto& [stress, tangent] : std::vector<std::pair<std::string, std::string>>{
           {"eps^3", "3*eps^2"}, {"-eps", ""}, {"1/eps", ""}}) {
    auto p = model("formula");
    p.set("Stress", stress);
    p.set("Tangent", tangent);
    auto m = material(p);
    auto ps = particlesAt({0.5});
    try {
      prepare(ps, Materials<1>{m});
      FAIL() << "no error for " << stress;
    } catch (const InputError& e) {
      EXPECT_EQ(e.path(), "Materials/m/Stress") << stress;
    }
  }
}

TEST(LinearLaw, StressAndTangentFromF) {
  auto m = linear("2 + x");
  auto ps = particlesAt({0.0, 0.5, 1.0});
  const Materials<1> materials = {m};
  prepare(ps, materials);
  ParticleSet<1>::Tensors F("F", 3), P("P", 3);
  Material<1>::Tangents A("A", 3);
  auto Fh = Kokkos::create_mirror_view(F);
  Fh(0, 0, 0) = 1.0, Fh(1, 0, 0) = 1.1, Fh(2, 0, 0) = 0.8;
  Kokkos::deep_copy(F, Fh);
  m->firstPiola(evaluationOf(ps, materials, 0, F), P, A);
  auto Ph = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), P);
  auto Ah = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), A);
  EXPECT_DOUBLE_EQ(Ph(0, 0, 0), 0.0);
  EXPECT_NEAR(Ph(1, 0, 0), 2.5 * 0.1, 1e-15);
  EXPECT_NEAR(Ph(2, 0, 0), 3.0 * -0.2, 1e-15);
  EXPECT_DOUBLE_EQ(Ah(1, 0, 0, 0, 0), 2.5);
  EXPECT_DOUBLE_EQ(m->maxModulus(evaluationOf(ps, materials, 0, F)), 3.0);
}

TEST(LinearLaw, OnlyItsOwnParticles) {
  auto m = linear("5");
  auto ps = particlesAt({0.0, 1.0});
  auto mat = Kokkos::create_mirror_view(ps.material);
  mat(1) = 1;
  Kokkos::deep_copy(ps.material, mat);
  const Materials<1> materials = {m, linear("9")};
  prepare(ps, materials);
  ParticleSet<1>::Tensors F("F", 2), P("P", 2);
  Material<1>::Tangents A("A", 2);
  Kokkos::deep_copy(F, 2.0);
  Kokkos::deep_copy(P, -7.0);
  m->firstPiola(evaluationOf(ps, materials, 0, F), P, A);
  auto Ph = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), P);
  EXPECT_DOUBLE_EQ(Ph(0, 0, 0), 5.0);
  EXPECT_DOUBLE_EQ(Ph(1, 0, 0), -7.0);
}

TEST(LinearLaw, NonPositiveModulusAtAParticleNamesThePath) {
  auto m = linear("1 - 2*x");
  auto ps = particlesAt({0.25, 0.75});
  try {
    prepare(ps, Materials<1>{m});
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.path(), "Materials/m/E");
    EXPECT_NE(std::string(e.what()).find("at x = 0.75"), std::string::npos) << e.what();
  }
}

TEST(MaterialFactory, ModelOfAnotherDimensionIsRejected) {
  Teuchos::ParameterList p;
  p.set("Model", std::string("linear"));
  p.set("E", 1.0);
  validateParameters(p, materialValidParameters());
  EXPECT_THROW(createMaterial<2>("m", p), InputError);
}

}  // namespace
}  // namespace impm

namespace impm {
namespace {

// 2-D laws: at a general F (stretch, shear, rotation), A = dP/dF and P = dW/dF by central
// differences of the values the material returns (step 1e-6); at F = I, P = 0, W = 0 and
// the small-strain tangent lambda d_ab d_cd + mu (d_ac d_bd + d_ad d_bc).
class EveryPlaneStrainLaw : public ::testing::TestWithParam<std::string> {};

// Any dimension: P, A = dP/dF and W of a model at deformation gradients F (row-major).
template <int Dim>
struct DimValues {
  std::vector<std::vector<double>> P, A;
  std::vector<double> W, stressZZ;
};

template <int Dim>
DimValues<Dim> evaluateIn(const std::string& model, const std::vector<std::vector<double>>& F) {
  Teuchos::ParameterList p;
  p.set("Model", model);
  p.set("E", 1000.0);
  p.set("nu", 0.3);
  validateParameters(p, materialValidParameters());
  auto m = createMaterial<Dim>("m", p);
  const std::size_t n = F.size();
  ParticleSet<Dim> ps(n);
  const Materials<Dim> materials = {m};
  prepare(ps, materials);
  typename ParticleSet<Dim>::Tensors Fv("F", n), P("P", n);
  typename Material<Dim>::Tangents A("A", n);
  typename ParticleSet<Dim>::Scalars W("W", n), szz("szz", n);
  auto Fh = Kokkos::create_mirror_view(Fv);
  for (std::size_t q = 0; q < n; ++q)
    for (int k = 0; k < Dim * Dim; ++k)
      Fh(q, k / Dim, k % Dim) = F[q][k];
  Kokkos::deep_copy(Fv, Fh);
  const auto at = evaluationOf(ps, materials, 0, Fv);
  m->firstPiola(at, P, A);
  m->energyDensity(at, W);
  m->outOfPlaneStress(at, szz);
  auto Ph = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), P);
  auto Ah = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), A);
  auto Wh = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), W);
  auto Sh = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), szz);
  DimValues<Dim> v;
  for (std::size_t q = 0; q < n; ++q) {
    std::vector<double> Pq, Aq;
    for (int a = 0; a < Dim; ++a)
      for (int b = 0; b < Dim; ++b) {
        Pq.push_back(Ph(q, a, b));
        for (int c = 0; c < Dim; ++c)
          for (int d = 0; d < Dim; ++d)
            Aq.push_back(Ah(q, a, b, c, d));
      }
    v.P.push_back(Pq), v.A.push_back(Aq), v.W.push_back(Wh(q)), v.stressZZ.push_back(Sh(q));
  }
  return v;
}

TEST_P(EveryPlaneStrainLaw, TangentAndEnergyAreConsistentWithTheStress) {
  const std::vector<double> F = {1.12, 0.23, -0.17, 0.86};  // J = 1.0023
  const double h = 1e-6;
  std::vector<std::vector<double>> Fs = {F};
  for (int cd = 0; cd < 4; ++cd)
    for (double s : {-1.0, 1.0}) {
      auto G = F;
      G[cd] += s * h;
      Fs.push_back(G);
    }
  const auto v = evaluateIn<2>(GetParam(), Fs);
  for (int cd = 0; cd < 4; ++cd) {
    const std::size_t minus = 1 + 2 * cd, plus = 2 + 2 * cd;
    for (int ab = 0; ab < 4; ++ab)
      EXPECT_NEAR(v.A[0][ab * 4 + cd], (v.P[plus][ab] - v.P[minus][ab]) / (2 * h), 1e-5)
          << GetParam() << ": A[" << ab << "][" << cd << "]";
    EXPECT_NEAR(v.P[0][cd], (v.W[plus] - v.W[minus]) / (2 * h), 1e-5) << GetParam();
  }
  const auto rest = evaluateIn<2>(GetParam(), {{1.0, 0.0, 0.0, 1.0}});
  const double mu = 1000 / 2.6, lambda = 300 / (1.3 * 0.4);
  for (int k = 0; k < 4; ++k)
    EXPECT_NEAR(rest.P[0][k], 0.0, 1e-12);
  EXPECT_NEAR(rest.W[0], 0.0, 1e-12);
  EXPECT_NEAR(rest.stressZZ[0], 0.0, 1e-12);
  for (int k = 0; k < 16; ++k) {
    const int a = k / 8, b = (k / 4) % 2, c = (k / 2) % 2, d = k % 2;
    const double expected =
        lambda * (a == b) * (c == d) + mu * ((a == c) * (b == d) + (a == d) * (b == c));
    EXPECT_NEAR(rest.A[0][k], expected, 1e-9) << GetParam() << " at F = I, entry " << k;
  }
}

// Hencky's written-out tangent against the dual-number derivative of the same evaluation,
// where the two in-plane stretches are equal, close (either side of the ln series'
// threshold r/m = 1e-5 and of the tangent's r/m = 0.1) and far apart.  The dual numbers
// differentiate g1 = (ln(m + r) - ln(m - r))/(2r) through a quotient that cancels as r -> 0
// (about 1e-16 (m/r)^2 relative), hence no point between 1e-5 and 1e-3.
// P and A = dP/dF of Hencky's law by dual numbers through ln b (the reference the written
// tangent is checked against).
template <int Dim>
void henckyByDuals(const double F[Dim][Dim], const Lame& k, double P[Dim][Dim],
                   double A[Dim][Dim][Dim][Dim]) {
  using D = Fad<Dim * Dim>;
  D Fd[Dim][Dim], F3[3][3], Finv[3][3], Pd[Dim][Dim];
  for (int a = 0; a < Dim; ++a)
    for (int b = 0; b < Dim; ++b)
      Fd[a][b] = variable<Dim * Dim>(F[a][b], Dim * a + b);
  embed<Dim>(Fd, F3);
  inverseOf(F3, determinantOf(F3), Finv);
  const auto eps = scaled(isotropicFunction<Logarithm>(congruence(F3, identityOf<double>())), 0.5);
  piolaOfKirchhoff<Dim>(henckyStress(eps, k.mu, k.lambda), Finv, Pd);
  for (int a = 0; a < Dim; ++a)
    for (int b = 0; b < Dim; ++b) {
      P[a][b] = valueOf(Pd[a][b]);
      for (int c = 0; c < Dim; ++c)
        for (int d = 0; d < Dim; ++d)
          A[a][b][c][d] = derivativeOf(Pd[a][b], Dim * c + d);
    }
}

TEST(Hencky, TangentIsTheExactDerivativeOfTheStress) {
  const Lame k{1000 / 2.6, 300 / (1.3 * 0.4)};
  const auto rotation = [](double t, double R[2][2]) {
    R[0][0] = std::cos(t), R[0][1] = -std::sin(t), R[1][0] = std::sin(t), R[1][1] = std::cos(t);
  };
  for (double rho : {0.0, 1e-7, 1e-3, 0.05, 0.099, 0.101, 0.3, 0.8})
    for (double scale : {0.7, 1.3}) {
      // F = R1 diag(s1, s2) R2: b's in-plane eigenvalues s1^2, s2^2 have r/m = rho.
      const double s2 = scale, s1 = scale * std::sqrt((1 + rho) / (1 - rho));
      double R1[2][2], R2[2][2], F[2][2];
      rotation(0.4, R1), rotation(-1.1, R2);
      for (int a = 0; a < 2; ++a)
        for (int b = 0; b < 2; ++b)
          F[a][b] = R1[a][0] * s1 * R2[0][b] + R1[a][1] * s2 * R2[1][b];
      double P[2][2], A[2][2][2][2];
      henckyByDuals<2>(F, k, P, A);
      const auto v = HenckyLaw::evaluate<2>(F, k);
      double largest = 0;
      for (int i = 0; i < 16; ++i)
        largest = std::max(largest, std::abs(A[i / 8][(i / 4) % 2][(i / 2) % 2][i % 2]));
      for (int i = 0; i < 16; ++i) {
        const int a = i / 8, b = (i / 4) % 2, c = (i / 2) % 2, d = i % 2;
        EXPECT_NEAR(v.A[a][b][c][d], A[a][b][c][d], 1e-10 * largest)
            << "r/m = " << rho << ", scale " << scale << ", entry " << i;
      }
      for (int i = 0; i < 4; ++i)
        EXPECT_NEAR(v.P[i / 2][i % 2], P[i / 2][i % 2], 1e-13 * largest);
    }
}

INSTANTIATE_TEST_SUITE_P(Material, EveryPlaneStrainLaw,
                         ::testing::Values("linear-elastic", "neo-hookean", "hencky"));

TEST(NeoHookean, UniaxialPlaneStrainClosedForm) {
  // F = diag(s, 1): P_xx = mu (s - 1/s) + lambda ln s / s, sigma_zz = lambda ln s / s.
  const double s = 0.8, mu = 1000 / 2.6, lambda = 300 / (1.3 * 0.4);
  const auto v = evaluateIn<2>("neo-hookean", {{s, 0.0, 0.0, 1.0}});
  EXPECT_NEAR(v.P[0][0], mu * (s - 1 / s) + lambda * std::log(s) / s, 1e-12 * 1000);
  EXPECT_NEAR(v.P[0][3], lambda * std::log(s), 1e-12 * 1000);
  EXPECT_NEAR(v.stressZZ[0], lambda * std::log(s) / s, 1e-12 * 1000);
}

TEST(NeoHookean, InvertedParticleIsANumericalError) {
  EXPECT_THROW(evaluateIn<2>("neo-hookean", {{-0.5, 0.0, 0.0, 1.0}}), NumericalError);
}

}  // namespace
}  // namespace impm

namespace impm {
namespace {

// A general 3-D F: stretch, shear and rotation, J = det F = 0.97...
const std::vector<double> kGeneralF3 = {1.12, 0.23, -0.05, -0.17, 0.86, 0.11, 0.08, -0.14, 1.03};

// 3-D laws: A = dP/dF and P = dW/dF by central differences (step 1e-6) at a general F; at
// F = I, P = 0, W = 0 and the small-strain tangent.
class Every3DLaw : public ::testing::TestWithParam<std::string> {};

TEST_P(Every3DLaw, TangentAndEnergyAreConsistentWithTheStress) {
  const double h = 1e-6;
  std::vector<std::vector<double>> Fs = {kGeneralF3};
  for (int cd = 0; cd < 9; ++cd)
    for (double s : {-1.0, 1.0}) {
      auto G = kGeneralF3;
      G[cd] += s * h;
      Fs.push_back(G);
    }
  const auto v = evaluateIn<3>(GetParam(), Fs);
  for (int cd = 0; cd < 9; ++cd) {
    const std::size_t minus = 1 + 2 * cd, plus = 2 + 2 * cd;
    for (int ab = 0; ab < 9; ++ab)
      EXPECT_NEAR(v.A[0][ab * 9 + cd], (v.P[plus][ab] - v.P[minus][ab]) / (2 * h), 1e-5)
          << GetParam() << ": A[" << ab << "][" << cd << "]";
    EXPECT_NEAR(v.P[0][cd], (v.W[plus] - v.W[minus]) / (2 * h), 1e-5) << GetParam();
  }
  const auto rest = evaluateIn<3>(GetParam(), {{1, 0, 0, 0, 1, 0, 0, 0, 1}});
  const double mu = 1000 / 2.6, lambda = 300 / (1.3 * 0.4);
  for (int k = 0; k < 9; ++k)
    EXPECT_NEAR(rest.P[0][k], 0.0, 1e-12);
  EXPECT_NEAR(rest.W[0], 0.0, 1e-12);
  for (int k = 0; k < 81; ++k) {
    const int a = k / 27, b = (k / 9) % 3, c = (k / 3) % 3, d = k % 3;
    const double expected =
        lambda * (a == b) * (c == d) + mu * ((a == c) * (b == d) + (a == d) * (b == c));
    EXPECT_NEAR(rest.A[0][k], expected, 1e-9) << GetParam() << " at F = I, entry " << k;
  }
}

// Plane strain is the 3-D law at F_zz = 1: the 2-D P, A and W equal the in-plane entries of
// the 3-D law's at F = [[F2, 0], [0, 1]], and the 2-D sigma_zz is the 3-D P_zz / J, to
// round-off.
TEST_P(Every3DLaw, PlaneStrainIsTheThreeDimensionalLawAtUnitOutOfPlaneStretch) {
  const std::vector<double> F2 = {1.12, 0.23, -0.17, 0.86};
  const std::vector<double> F3 = {F2[0], F2[1], 0.0, F2[2], F2[3], 0.0, 0.0, 0.0, 1.0};
  const auto two = evaluateIn<2>(GetParam(), {F2});
  const auto three = evaluateIn<3>(GetParam(), {F3});
  const double scale = 1000.0;
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) {
      EXPECT_NEAR(two.P[0][2 * a + b], three.P[0][3 * a + b], 1e-13 * scale) << a << b;
      for (int c = 0; c < 2; ++c)
        for (int d = 0; d < 2; ++d)
          EXPECT_NEAR(two.A[0][8 * a + 4 * b + 2 * c + d], three.A[0][27 * a + 9 * b + 3 * c + d],
                      1e-13 * scale)
              << a << b << c << d;
    }
  EXPECT_NEAR(two.W[0], three.W[0], 1e-13 * scale);
  const double J = F2[0] * F2[3] - F2[1] * F2[2];
  EXPECT_NEAR(two.stressZZ[0], three.P[0][8] / J, 1e-13 * scale);
}

INSTANTIATE_TEST_SUITE_P(Material, Every3DLaw,
                         ::testing::Values("linear-elastic", "neo-hookean", "hencky"));

// Objectivity of the finite-strain 3-D laws: a rotation Q superposed on F gives P(Q F) =
// Q P(F) and the same energy, for a rotation about an axis that is no coordinate axis.
TEST(Material3D, FiniteStrainLawsAreObjective) {
  const double angle = 0.7, n[3] = {1.0 / 3.0, 2.0 / 3.0, 2.0 / 3.0};  // unit axis
  double Q[3][3];
  const double c = std::cos(angle), s = std::sin(angle);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const double cross = (i == j) ? 0.0 : ((j == (i + 1) % 3) ? -n[(i + 2) % 3] : n[(i + 1) % 3]);
      Q[i][j] = c * (i == j) + (1 - c) * n[i] * n[j] + s * cross;
    }
  std::vector<double> QF(9, 0.0);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        QF[3 * i + j] += Q[i][k] * kGeneralF3[3 * k + j];
  for (const char* model : {"neo-hookean", "hencky"}) {
    const auto v = evaluateIn<3>(model, {kGeneralF3, QF});
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        double QP = 0.0;
        for (int k = 0; k < 3; ++k)
          QP += Q[i][k] * v.P[0][3 * k + j];
        EXPECT_NEAR(v.P[1][3 * i + j], QP, 1e-10) << model << " " << i << j;
      }
    EXPECT_NEAR(v.W[1], v.W[0], 1e-10) << model;
  }
}

// Hencky's 3-D tangent at stretches with three, two and no equal principal values, and values
// that nearly coincide (either side of the divided differences' series threshold 1e-5):
// against central differences of the stress (the stress from eigenvalues alone, the tangent
// by the Daleckii-Krein formula), and the written-out tangent against the dual numbers.
TEST(Hencky, ThreeDimensionalTangentIsSmoothAtRepeatedStretches) {
  const Lame k{1000 / 2.6, 300 / (1.3 * 0.4)};
  // Rotations about two general axes (Rodrigues).
  const auto rotation = [](double angle, const double n[3], double R[3][3]) {
    const double c = std::cos(angle), s = std::sin(angle);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const double cross =
            (i == j) ? 0.0 : ((j == (i + 1) % 3) ? -n[(i + 2) % 3] : n[(i + 1) % 3]);
        R[i][j] = c * (i == j) + (1 - c) * n[i] * n[j] + s * cross;
      }
  };
  const double n1[3] = {1.0 / 3.0, 2.0 / 3.0, 2.0 / 3.0}, n2[3] = {0.6, 0.0, -0.8};
  double R1[3][3], R2[3][3];
  rotation(0.9, n1, R1), rotation(-0.5, n2, R2);
  const double stretches[][3] = {{1.0, 1.0, 1.0},        {0.9, 0.9, 0.9},
                                 {1.2, 1.2, 0.8},        {0.85, 1.1, 1.1},
                                 {1.1, 1.1 + 1e-7, 0.9}, {1.1, 1.1 * (1 + 1e-4), 0.9},
                                 {1.05, 0.95, 1.2}};
  for (const auto& st : stretches) {
    double F[3][3];
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) {
        F[a][b] = 0.0;
        for (int m = 0; m < 3; ++m)
          F[a][b] += R1[a][m] * st[m] * R2[m][b];
      }
    const auto v = HenckyLaw::evaluate<3>(F, k);
    double P[3][3], A[3][3][3][3];
    henckyByDuals<3>(F, k, P, A);
    const double h = 1e-6;
    for (int c = 0; c < 3; ++c)
      for (int d = 0; d < 3; ++d) {
        double Fp[3][3], Fm[3][3];
        std::copy(&F[0][0], &F[0][0] + 9, &Fp[0][0]);
        std::copy(&F[0][0], &F[0][0] + 9, &Fm[0][0]);
        Fp[c][d] += h, Fm[c][d] -= h;
        const auto vp = HenckyLaw::evaluate<3>(Fp, k), vm = HenckyLaw::evaluate<3>(Fm, k);
        for (int a = 0; a < 3; ++a)
          for (int b = 0; b < 3; ++b) {
            EXPECT_NEAR(v.A[a][b][c][d], (vp.P[a][b] - vm.P[a][b]) / (2 * h), 1e-5 * 1000)
                << "stretches " << st[0] << " " << st[1] << " " << st[2];
            EXPECT_NEAR(v.A[a][b][c][d], A[a][b][c][d], 1e-10 * 1000);
          }
      }
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b)
        EXPECT_NEAR(v.P[a][b], P[a][b], 1e-12 * 1000);
  }
}

// A 2-D model that has no 3-D form is refused by name in a 3-D deck.
TEST(Material3D, ModelsWithoutAThreeDimensionalFormAreNamed) {
  Teuchos::ParameterList p;
  p.set("Model", std::string("linear"));
  p.set("E", 1000.0);
  validateParameters(p, materialValidParameters());
  try {
    createMaterial<3>("m", p);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("is not a 3-D model"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace impm

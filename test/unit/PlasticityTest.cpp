// material: the laws with history (j2 in plane strain, j2-1d) and Hencky elasticity, at
// single points: tangents against central differences at elastic and plastic states, the
// return map on the yield surface with the flow along the deviatoric stress, j2 without
// yield equal to hencky, objectivity, and a plane-strain compression path against an
// independent integration of the same law written here.

#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "core/Errors.hpp"
#include "core/Parameters.hpp"
#include "material/MaterialFactory.hpp"
#include "material/MaterialState.hpp"

namespace impm {
namespace {

using Matrix = std::array<double, 4>;  // (a, b) at 2a + b

constexpr double kE = 1000.0, kNu = 0.3, kYield = 10.0, kH = 50.0;
const double kMu = kE / (2 * (1 + kNu)), kLambda = kE * kNu / ((1 + kNu) * (1 - 2 * kNu));

// A law of the tests' elastic constants: j2 with yield stress and hardening modulus,
// drucker-prager with c = 1, phi = 30, psi = 10 degrees, any other model as it is.
template <int Dim>
std::shared_ptr<Material<Dim>> plasticLaw(const std::string& model, double yield = kYield,
                                          double H = kH) {
  Teuchos::ParameterList p;
  p.set("Model", model);
  p.set("E", kE);
  p.set("nu", kNu);
  if (model == "j2") {
    p.set("Yield Stress", yield);
    p.set("Hardening Modulus", H);
  } else if (model == "drucker-prager") {
    p.set("Cohesion", 1.0);
    p.set("Friction Angle", 30.0);
    p.set("Dilation Angle", 10.0);
  }
  validateParameters(p, materialValidParameters());
  return createMaterial<Dim>("m", p);
}

std::shared_ptr<Material<2>> planeStrainLaw(const std::string& model, double yield = kYield,
                                            double H = kH) {
  return plasticLaw<2>(model, yield, H);
}

// A material point of any dimension (several copies, to evaluate perturbed F in one call)
// carried along a deformation path: F row-major (Dim * Dim entries), evaluated at trial F,
// every copy committed to copy 0's trial state.
template <int Dim>
class PointIn {
 public:
  explicit PointIn(std::shared_ptr<Material<Dim>> law, std::size_t copies)
      : materials_{std::move(law)}, particles_(copies) {
    declareMaterialVariables(particles_, materials_);
    initializeMaterials(particles_, materials_, true);
    trial_ = std::make_unique<TrialState<Dim>>(particles_, materials_);
  }
  // P (row-major) and A (a, b, c, d row-major) at every copy.
  std::pair<std::vector<std::vector<double>>, std::vector<std::vector<double>>> evaluate(
      const std::vector<std::vector<double>>& F) {
    const std::size_t n = particles_.size();
    typename ParticleSet<Dim>::Tensors Fv("F", n), P("P", n);
    typename Material<Dim>::Tangents A("A", n);
    auto Fh = Kokkos::create_mirror_view(Fv);
    for (std::size_t q = 0; q < n; ++q)
      for (int k = 0; k < Dim * Dim; ++k)
        Fh(q, k / Dim, k % Dim) = F.at(q)[k];
    Kokkos::deep_copy(Fv, Fh);
    materials_[0]->firstPiola(evaluationOf(particles_, materials_, 0, Fv, trial_->of(0)), P, A);
    auto Ph = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), P);
    auto Ah = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), A);
    std::vector<std::vector<double>> Ps(n), As(n);
    for (std::size_t q = 0; q < n; ++q)
      for (int a = 0; a < Dim; ++a)
        for (int b = 0; b < Dim; ++b) {
          Ps[q].push_back(Ph(q, a, b));
          for (int c = 0; c < Dim; ++c)
            for (int d = 0; d < Dim; ++d)
              As[q].push_back(Ah(q, a, b, c, d));
        }
    return {Ps, As};
  }
  void commit() {
    for (const auto& t : trial_->of(0)) {
      auto h = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), t);
      for (std::size_t q = 1; q < h.extent(0); ++q)
        for (std::size_t c = 0; c < h.extent(1); ++c)
          h(q, c) = h(0, c);
      Kokkos::deep_copy(t, h);
    }
    commitMaterialState(particles_, materials_, *trial_);
  }
  double committed(const std::string& name, int c) const {
    auto h = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), particles_.values(name));
    return h(0, c);
  }
  // Component c of trial variable k of copy 0.
  double trial(std::size_t k, int c) const {
    auto h = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), trial_->of(0).at(k));
    return h(0, c);
  }

 private:
  Materials<Dim> materials_;
  ParticleSet<Dim> particles_;
  std::unique_ptr<TrialState<Dim>> trial_;
};

// The 2-D point with P and A as fixed-size arrays.
class Point : public PointIn<2> {
 public:
  using PointIn<2>::PointIn;
  struct Values {
    std::vector<Matrix> P;
    std::vector<std::array<double, 16>> A;
  };
  Values evaluate(const std::vector<Matrix>& F) {
    std::vector<std::vector<double>> rows;
    for (const auto& f : F)
      rows.emplace_back(f.begin(), f.end());
    const auto [P, A] = PointIn<2>::evaluate(rows);
    Values v;
    for (std::size_t q = 0; q < P.size(); ++q) {
      Matrix Pq;
      std::array<double, 16> Aq;
      std::copy(P[q].begin(), P[q].end(), Pq.begin());
      std::copy(A[q].begin(), A[q].end(), Aq.begin());
      v.P.push_back(Pq), v.A.push_back(Aq);
    }
    return v;
  }
};

// Largest |A - dP/dF (central differences, step h)| relative to max |A|, at F from the
// point's committed state.
double tangentError(Point& point, const Matrix& F, double h = 1e-6) {
  std::vector<Matrix> Fs = {F};
  for (int cd = 0; cd < 4; ++cd)
    for (double s : {-1.0, 1.0}) {
      Matrix G = F;
      G[cd] += s * h;
      Fs.push_back(G);
    }
  const auto v = point.evaluate(Fs);
  double worst = 0, scale = 0;
  for (int k = 0; k < 16; ++k)
    scale = std::max(scale, std::abs(v.A[0][k]));
  for (int cd = 0; cd < 4; ++cd)
    for (int ab = 0; ab < 4; ++ab) {
      const double fd = (v.P[2 + 2 * cd][ab] - v.P[1 + 2 * cd][ab]) / (2 * h);
      worst = std::max(worst, std::abs(v.A[0][ab * 4 + cd] - fd));
    }
  return worst / scale;
}

std::vector<Matrix> copies(const Matrix& F, std::size_t n) {
  return std::vector<Matrix>(n, F);
}

// Plane-strain compression F = diag(1, s) in `steps` equal steps of s, committed each step.
void compress(Point& point, double s, int steps, std::size_t n) {
  for (int i = 1; i <= steps; ++i) {
    const double si = 1.0 + (s - 1.0) * i / steps;
    point.evaluate(copies({1.0, 0.0, 0.0, si}, n));
    point.commit();
  }
}

// The Kirchhoff stress tau = P F^T (in-plane) of a law's P.
Matrix kirchhoff(const Matrix& P, const Matrix& F) {
  Matrix t;
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b)
      t[2 * a + b] = P[2 * a] * F[2 * b] + P[2 * a + 1] * F[2 * b + 1];
  return t;
}

TEST(J2PlaneStrain, TangentIsTheDerivativeOfTheReturnAtElasticAndPlasticStates) {
  Point point(planeStrainLaw("j2"), 9);
  const Matrix general = {0.97, 0.04, -0.03, 0.95};  // with shear and rotation
  const double elastic = tangentError(point, {1.0, 0.002, 0.0, 0.998});
  EXPECT_LT(elastic, 1e-7) << "elastic state";
  const double firstYield = tangentError(point, general);
  EXPECT_LT(firstYield, 1e-7) << "plastic from the virgin state";
  compress(point, 0.9, 10, 9);
  const double hardened = tangentError(point, {1.01, 0.03, -0.02, 0.88});
  EXPECT_LT(hardened, 1e-7) << "plastic from a hardened state";
  const double unloading = tangentError(point, {1.0, 0.0, 0.0, 0.905});
  EXPECT_LT(unloading, 1e-7) << "elastic unloading from a plastic state";
  Point perfect(planeStrainLaw("j2", kYield, 0.0), 9);
  const double noHardening = tangentError(perfect, general);
  EXPECT_LT(noHardening, 1e-7) << "perfect plasticity";
  std::cout << "  j2 tangent, relative error against central differences (h = 1e-6): elastic "
            << elastic << ", plastic " << firstYield << ", hardened " << hardened << ", unloading "
            << unloading << ", H = 0 " << noHardening << "\n";
}

TEST(J2PlaneStrain, ReturnLandsOnTheYieldSurfaceWithIsochoricFlowAlongTheDeviator) {
  Point point(planeStrainLaw("j2"), 1);
  const Matrix F = {0.98, 0.05, -0.02, 0.9};
  const auto v = point.evaluate({F});
  const Matrix tau = kirchhoff(v.P[0], F);
  // tau_zz from the trial elastic strain: q needs all three principal stresses.
  const double alpha = point.trial(1, 0);
  ASSERT_GT(alpha, 0.0) << "the point must yield";
  // C_p^-1 = F^-1 b_e F^-T; b_e = exp(2 eps_e), tau = D : eps_e: recover eps_e from tau
  // (Hencky inverted), and check ln det C_p^-1 = 0 (isochoric flow) and the yield condition.
  const double cxx = point.trial(0, 0), cyy = point.trial(0, 1), czz = point.trial(0, 2),
               cxy = point.trial(0, 3);
  EXPECT_NEAR(czz * (cxx * cyy - cxy * cxy), 1.0, 1e-13) << "det C_p^-1 = 1";
  // eps_e,zz from tau: tau_zz = lambda tr eps + 2 mu eps_zz, tr tau = (3 lambda + 2 mu) tr eps.
  const double trTauInPlane = tau[0] + tau[3];
  // Solve for tau_zz: eps_zz = ln(b_e,zz) / 2 = ln(C_p^-1 zz) / 2 (F_zz = 1).
  const double epsZZ = 0.5 * std::log(czz);
  // tau_zz = lambda (tr eps) + 2 mu eps_zz with tr eps = (trTauInPlane + tau_zz)/(3 lambda + 2 mu)
  const double k3 = 3 * kLambda + 2 * kMu;
  const double tauZZ = (kLambda * trTauInPlane / k3 + 2 * kMu * epsZZ) / (1 - kLambda / k3);
  const double p = (trTauInPlane + tauZZ) / 3;
  const double sxx = tau[0] - p, syy = tau[3] - p, szz = tauZZ - p, sxy = tau[1];
  const double q = std::sqrt(1.5 * (sxx * sxx + syy * syy + szz * szz + 2 * sxy * sxy));
  EXPECT_NEAR(q, kYield + kH * alpha, 1e-12 * kYield) << "f = q - (sigma_y + H alpha) = 0";
  EXPECT_NEAR(tau[1], tau[2], 1e-12 * kYield) << "tau is symmetric";
}

TEST(J2PlaneStrain, WithoutYieldItIsHencky) {
  Point j2(planeStrainLaw("j2", 1e30), 1), hencky(planeStrainLaw("hencky"), 1);
  const Matrix F = {1.3, 0.2, -0.4, 0.7};
  const auto a = j2.evaluate({F}), b = hencky.evaluate({F});
  for (int k = 0; k < 4; ++k)
    EXPECT_NEAR(a.P[0][k], b.P[0][k], 1e-12 * kE);
  for (int k = 0; k < 16; ++k)
    EXPECT_NEAR(a.A[0][k], b.A[0][k], 1e-12 * kE);
}

TEST(J2PlaneStrain, SuperposedRotationRotatesTheStress) {
  Point point(planeStrainLaw("j2"), 2);
  compress(point, 0.93, 5, 2);
  const Matrix F = {1.02, 0.03, -0.01, 0.9};
  const double c = std::cos(0.7), s = std::sin(0.7);
  const Matrix QF = {c * F[0] - s * F[2], c * F[1] - s * F[3], s * F[0] + c * F[2],
                     s * F[1] + c * F[3]};
  const auto v = point.evaluate({F, QF});
  ASSERT_GT(point.trial(1, 0), point.committed("equivalent_plastic_strain", 0));
  const Matrix& P = v.P[0];
  const Matrix QP = {c * P[0] - s * P[2], c * P[1] - s * P[3], s * P[0] + c * P[2],
                     s * P[1] + c * P[3]};
  for (int k = 0; k < 4; ++k)
    EXPECT_NEAR(v.P[1][k], QP[k], 1e-12 * kE) << "P(QF) = Q P(F), component " << k;
}

// The independent reference: the same law (Hencky elasticity on logarithmic strains, von
// Mises yield, linear hardening, associated flow) on the principal logarithmic strains of
// F = diag(a, b), integrated in many small strain increments, each brought back to the yield
// surface along the current normal.  The path compresses y to b = 0.95, then stretches x to
// a = 1.05: the second leg turns the deviatoric strain rate, so the stress path is not
// radial and the return's step size matters.
struct Reference {
  double tau[3] = {0, 0, 0}, alpha = 0;
};

struct Path {
  double a, b;  // F = diag(a, b) at the end of each leg
};
const Path kLegs[] = {{1.0, 0.95}, {1.05, 0.95}};

Reference integrateReference(int stepsPerLeg) {
  Reference r;
  double eps[3] = {0, 0, 0}, epsP[3] = {0, 0, 0};
  double from[2] = {0, 0};
  for (const Path& leg : kLegs) {
    const double to[2] = {std::log(leg.a), std::log(leg.b)};
    for (int i = 1; i <= stepsPerLeg; ++i) {
      for (int k = 0; k < 2; ++k)
        eps[k] = from[k] + (to[k] - from[k]) * i / stepsPerLeg;
      double ee[3], tr = 0;
      for (int k = 0; k < 3; ++k)
        ee[k] = eps[k] - epsP[k], tr += ee[k];
      double t[3], mean = 0;
      for (int k = 0; k < 3; ++k)
        t[k] = kLambda * tr + 2 * kMu * ee[k], mean += t[k] / 3;
      double dev[3], ss = 0;
      for (int k = 0; k < 3; ++k)
        dev[k] = t[k] - mean, ss += dev[k] * dev[k];
      const double q = std::sqrt(1.5 * ss);
      const double over = q - (kYield + kH * r.alpha);
      if (over > 0) {
        const double dAlpha = over / (3 * kMu + kH);
        for (int k = 0; k < 3; ++k)
          epsP[k] += 1.5 * dAlpha * dev[k] / q;
        r.alpha += dAlpha;
      }
    }
    from[0] = to[0], from[1] = to[1];
  }
  double tr = 0, ee[3];
  for (int k = 0; k < 3; ++k)
    ee[k] = eps[k] - epsP[k], tr += ee[k];
  for (int k = 0; k < 3; ++k)
    r.tau[k] = kLambda * tr + 2 * kMu * ee[k];
  return r;
}

TEST(J2PlaneStrain, CompressionPathMatchesAnIndependentIntegration) {
  const Reference ref = integrateReference(100000);
  double previous = 1e300;
  for (int steps : {10, 100, 1000}) {
    Point point(planeStrainLaw("j2"), 1);
    Matrix F = {1.0, 0.0, 0.0, 1.0};
    for (const Path& leg : kLegs) {
      const Matrix start = F;
      for (int i = 1; i <= steps; ++i) {
        F = {start[0] + (leg.a - start[0]) * i / steps, 0.0, 0.0,
             start[3] + (leg.b - start[3]) * i / steps};
        point.evaluate({F});
        point.commit();
      }
    }
    const auto v = point.evaluate({F});
    const Matrix tau = kirchhoff(v.P[0], F);
    const double alpha = point.committed("equivalent_plastic_strain", 0);
    const double error =
        std::max({std::abs(tau[0] - ref.tau[0]) / kYield, std::abs(tau[3] - ref.tau[1]) / kYield,
                  std::abs(alpha - ref.alpha) / ref.alpha});
    std::cout << "  compression then stretch, " << steps << " steps per leg: tau_xx " << tau[0]
              << " (reference " << ref.tau[0] << "), tau_yy " << tau[3] << " (" << ref.tau[1]
              << "), alpha " << alpha << " (" << ref.alpha << "), relative error " << error << "\n";
    EXPECT_LT(error, 0.5 * previous) << "the return converges to the reference as steps shrink";
    previous = error;
  }
  EXPECT_LT(previous, 1e-3);
}

TEST(J2PlaneStrain, InvertedParticleIsANumericalError) {
  Point point(planeStrainLaw("j2"), 1);
  EXPECT_THROW(point.evaluate({{-0.5, 0.0, 0.0, 1.0}}), NumericalError);
}

TEST(J2PlaneStrain, InadmissibleParametersAreInputErrors) {
  for (const auto& [name, value] : std::vector<std::pair<std::string, double>>{
           {"Yield Stress", 0.0}, {"Yield Stress", -1.0}, {"Hardening Modulus", -1.0}}) {
    Teuchos::ParameterList p;
    p.set("Model", std::string("j2"));
    p.set("E", kE);
    p.set("nu", kNu);
    p.set("Yield Stress", kYield);
    p.set(name, value);
    EXPECT_THROW(validateParameters(p, materialValidParameters()), InputError) << name;
  }
}

// drucker-prager: cohesion 10, friction and dilation angles in degrees.
std::shared_ptr<Material<2>> druckerPrager(double phi, double psi, double c = 10.0,
                                           const std::string& cone = "plane strain") {
  Teuchos::ParameterList p;
  p.set("Model", std::string("drucker-prager"));
  p.set("E", kE);
  p.set("nu", kNu);
  p.set("Cohesion", c);
  p.set("Friction Angle", phi);
  p.set("Dilation Angle", psi);
  p.set("Cone", cone);
  validateParameters(p, materialValidParameters());
  return createMaterial<2>("m", p);
}

// The largest |A_abcd - A_cdab| relative to max |A| (major symmetry of the tangent).
double asymmetry(const std::array<double, 16>& A) {
  double worst = 0, scale = 0;
  for (int k = 0; k < 16; ++k) {
    const int ab = k / 4, cd = k % 4;
    worst = std::max(worst, std::abs(A[k] - A[cd * 4 + ab]));
    scale = std::max(scale, std::abs(A[k]));
  }
  return worst / scale;
}

TEST(DruckerPrager, TangentIsTheDerivativeOfTheReturnOnTheConeAndAtTheApex) {
  const Matrix shear = {1.0, 0.03, 0.01, 0.985};    // compression and shear: the cone
  const Matrix stretched = {1.02, 0.0, 0.0, 1.02};  // hydrostatic tension: the apex
  for (double psi : {30.0, 10.0}) {
    Point point(druckerPrager(30.0, psi), 9);
    const double cone = tangentError(point, shear), apex = tangentError(point, stretched);
    std::cout << "  drucker-prager phi 30, psi " << psi << ": tangent error on the cone " << cone
              << ", at the apex " << apex << "\n";
    EXPECT_LT(cone, 1e-7);
    EXPECT_LT(apex, 1e-7);
  }
  Point elastic(druckerPrager(30.0, 30.0, 1e6), 9);
  EXPECT_LT(tangentError(elastic, shear), 1e-7) << "elastic";
}

TEST(DruckerPrager, AssociatedTangentIsSymmetricAndNonAssociatedIsNot) {
  const Matrix F = {1.0, 0.03, 0.01, 0.985};
  Point associated(druckerPrager(30.0, 30.0), 1), nonAssociated(druckerPrager(30.0, 5.0), 1);
  const double a = asymmetry(associated.evaluate({F}).A[0]);
  const double b = asymmetry(nonAssociated.evaluate({F}).A[0]);
  std::cout << "  asymmetry of A: associated " << a << ", non-associated " << b << "\n";
  EXPECT_GT(associated.trial(1, 0), 0.0) << "the point must yield";
  EXPECT_LT(a, 1e-9);
  EXPECT_GT(b, 1e-3);
}

TEST(DruckerPrager, ReturnLandsOnTheConeOrItsApex) {
  const double phi = 25.0, c = 10.0;
  const double t = std::tan(phi * M_PI / 180), d = std::sqrt(9 + 12 * t * t);
  const double eta = 3 * t / d, xi = 3 / d;
  Point cone(druckerPrager(phi, 10.0, c), 1);
  const Matrix F = {1.0, 0.03, 0.01, 0.985};
  const Matrix tau = kirchhoff(cone.evaluate({F}).P[0], F);
  // tau_zz from the elastic strain eps_zz = ln(C_p^-1 zz) / 2 (F_zz = 1), as in the j2 test.
  const double k3 = 3 * kLambda + 2 * kMu, T2 = tau[0] + tau[3];
  const double tauZZ =
      (kLambda * T2 / k3 + 2 * kMu * 0.5 * std::log(cone.trial(0, 2))) / (1 - kLambda / k3);
  const double p = (T2 + tauZZ) / 3;
  const double sxx = tau[0] - p, syy = tau[3] - p, szz = tauZZ - p;
  const double rootJ2 = std::sqrt(0.5 * (sxx * sxx + syy * syy + szz * szz + 2 * tau[1] * tau[1]));
  ASSERT_GT(cone.trial(1, 0), 0.0);
  EXPECT_NEAR(rootJ2 + eta * p - xi * c, 0.0, 1e-12 * c) << "on the cone";
  Point apex(druckerPrager(phi, 10.0, c), 1);
  const Matrix G = {1.02, 0.0, 0.0, 1.02};
  const Matrix tauApex = kirchhoff(apex.evaluate({G}).P[0], G);
  EXPECT_NEAR(tauApex[0], xi * c / eta, 1e-12 * c) << "at the apex";
  EXPECT_NEAR(tauApex[3], xi * c / eta, 1e-12 * c);
  EXPECT_NEAR(tauApex[1], 0.0, 1e-12 * c);
}

TEST(DruckerPrager, WithoutFrictionItIsJ2InPlaneStrain) {
  // phi = psi = 0, plane-strain fit: sqrt(J2) <= c, that is q <= sqrt(3) c.
  const double c = 10.0;
  Point dp(druckerPrager(0.0, 0.0, c), 1), j2(planeStrainLaw("j2", std::sqrt(3.0) * c, 0.0), 1);
  const Matrix F = {0.98, 0.05, -0.02, 0.9};
  const auto a = dp.evaluate({F}), b = j2.evaluate({F});
  ASSERT_GT(j2.trial(1, 0), 0.0);
  for (int k = 0; k < 4; ++k)
    EXPECT_NEAR(a.P[0][k], b.P[0][k], 1e-11 * kE);
  for (int k = 0; k < 16; ++k)
    EXPECT_NEAR(a.A[0][k], b.A[0][k], 1e-10 * kE);
}

TEST(DruckerPrager, InadmissibleParametersAreInputErrors) {
  EXPECT_THROW(druckerPrager(20.0, 25.0), InputError) << "psi > phi";
  EXPECT_THROW(druckerPrager(0.0, 0.0, 0.0), InputError) << "no strength at all";
  EXPECT_THROW(druckerPrager(90.0, 0.0), InputError) << "phi = 90";
  EXPECT_THROW(druckerPrager(-5.0, 0.0), InputError) << "phi < 0";
  EXPECT_THROW(druckerPrager(20.0, 10.0, -1.0), InputError) << "c < 0";
  EXPECT_THROW(druckerPrager(20.0, 10.0, 10.0, "middle"), InputError) << "unknown cone";
}

// j2-1d: the primer's bar law with a return map.
std::shared_ptr<Material<1>> bar(double E, double yield, double H) {
  Teuchos::ParameterList p;
  p.set("Model", std::string("j2-1d"));
  p.set("E", std::to_string(E));
  p.set("Yield Stress", std::to_string(yield));
  p.set("Hardening Modulus", std::to_string(H));
  validateParameters(p, materialValidParameters());
  return createMaterial<1>("m", p);
}

TEST(J2Law1D, LoadingPastYieldAndUnloadingFollowTheExactBilinearLaw) {
  const double E = 200.0, yield = 2.0, H = 20.0;
  const Materials<1> materials = {bar(E, yield, H)};
  ParticleSet<1> ps(1);
  declareMaterialVariables(ps, materials);
  initializeMaterials(ps, materials, true);
  TrialState<1> trial(ps, materials);
  auto at = [&](double F) {
    ParticleSet<1>::Tensors Fv("F", 1), P("P", 1);
    Material<1>::Tangents A("A", 1);
    Kokkos::deep_copy(Fv, F);
    materials[0]->firstPiola(evaluationOf(ps, materials, 0, Fv, trial.of(0)), P, A);
    auto Ph = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), P);
    auto Ah = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), A);
    return std::make_pair(Ph(0, 0, 0), Ah(0, 0, 0, 0, 0));
  };
  const double peak = 0.05;  // 5 times the yield strain
  const auto loaded = at(1.0 + peak);
  const double expected = yield + E * H / (E + H) * (peak - yield / E);
  EXPECT_NEAR(loaded.first, expected, 1e-13 * expected);
  EXPECT_NEAR(loaded.second, E * H / (E + H), 1e-12 * E);
  const double h = 1e-7;
  EXPECT_NEAR(loaded.second, (at(1.0 + peak + h).first - at(1.0 + peak - h).first) / (2 * h),
              1e-6 * E);
  at(1.0 + peak);
  commitMaterialState(ps, materials, trial);
  // Unloading to zero stress leaves the plastic strain eps - sigma/E; the slope is E.
  const double plastic = peak - expected / E;
  const auto unloaded = at(1.0 + plastic);
  EXPECT_NEAR(unloaded.first, 0.0, 1e-12 * yield);
  EXPECT_NEAR(unloaded.second, E, 1e-12 * E);
  // Reloading in compression yields at -(sigma_y + H alpha).
  const double alpha = peak - yield / E - (expected - yield) / E;
  const auto reversed = at(1.0 + plastic - (yield + H * alpha) / E - 0.01);
  EXPECT_NEAR(reversed.first, -(yield + H * alpha) - E * H / (E + H) * 0.01, 1e-12 * E);
}

}  // namespace
}  // namespace impm

namespace impm {
namespace {

// Largest |A - dP/dF (central differences, h = 1e-6)| relative to max |A|, 3-D.
double tangentError3D(PointIn<3>& point, const std::vector<double>& F) {
  const double h = 1e-6;
  std::vector<std::vector<double>> Fs = {F};
  for (int cd = 0; cd < 9; ++cd)
    for (double s : {-1.0, 1.0}) {
      auto G = F;
      G[cd] += s * h;
      Fs.push_back(G);
    }
  const auto [P, A] = point.evaluate(Fs);
  double worst = 0, scale = 0;
  for (double a : A[0])
    scale = std::max(scale, std::abs(a));
  for (int cd = 0; cd < 9; ++cd)
    for (int ab = 0; ab < 9; ++ab)
      worst = std::max(
          worst, std::abs(A[0][ab * 9 + cd] - (P[2 + 2 * cd][ab] - P[1 + 2 * cd][ab]) / (2 * h)));
  return worst / scale;
}

// The 3-D return maps: tangents against central differences at plastic states reached along
// a 3-D path (compression with shear in every plane), from a hardened state, and unloading.
TEST(Plasticity3D, TangentIsTheDerivativeOfTheReturnAlongAThreeDimensionalPath) {
  for (const char* model : {"j2", "drucker-prager"}) {
    PointIn<3> point(plasticLaw<3>(model), 19);
    // Stretch in x and z, compression in y, shear in every plane: the mean stress is
    // tensile, so the cone yields too.
    const std::vector<double> general = {1.02,  0.02,  -0.015, -0.01, 0.975,
                                         0.025, 0.012, -0.02,  1.015};
    const double first = tangentError3D(point, general);
    EXPECT_LT(first, 1e-7) << model << ": plastic from the virgin state";
    for (int i = 1; i <= 5; ++i) {  // load along the path and commit
      std::vector<double> Fi(9);
      for (int k = 0; k < 9; ++k)
        Fi[k] = (k % 4 == 0 ? 1.0 : 0.0) + (general[k] - (k % 4 == 0 ? 1.0 : 0.0)) * i / 5.0 * 1.5;
      point.evaluate(std::vector<std::vector<double>>(19, Fi));
      point.commit();
    }
    EXPECT_GT(point.committed("equivalent_plastic_strain", 0), 0.0) << model;
    const std::vector<double> further = {1.035, 0.035, -0.02, -0.015, 0.96,
                                         0.04,  0.02,  -0.03, 1.025};
    const double hardened = tangentError3D(point, further);
    EXPECT_LT(hardened, 1e-7) << model << ": plastic from a plastic state";
    std::cout << "  " << model
              << " 3-D tangent, relative error against central differences: " << first
              << " (first yield), " << hardened << " (from a plastic state)\n";
  }
}

// Plane strain is the 3-D law at F_zz = 1, plastic states included: a 2-D compression path
// with shear run through the 2-D law and through the 3-D law with F = [[F2, 0], [0, 1]]
// gives the same in-plane P, tangent and equivalent plastic strain at every step, to
// round-off (the 2-D law takes the in-plane closed form of ln, the 3-D one the eigenvectors).
TEST(Plasticity3D, PlaneStrainIsTheThreeDimensionalLawAtUnitOutOfPlaneStretch) {
  for (const char* model : {"j2", "drucker-prager"}) {
    PointIn<2> two(plasticLaw<2>(model), 1);
    PointIn<3> three(plasticLaw<3>(model), 1);
    double worstP = 0, worstA = 0;
    for (int i = 1; i <= 8; ++i) {
      const double s = 1.0 - 0.01 * i, g = 0.004 * i;
      const std::vector<double> F2 = {1.0, g, 0.0, s};
      const std::vector<double> F3 = {1.0, g, 0.0, 0.0, s, 0.0, 0.0, 0.0, 1.0};
      const auto [P2, A2] = two.evaluate({F2});
      const auto [P3, A3] = three.evaluate({F3});
      for (int a = 0; a < 2; ++a)
        for (int b = 0; b < 2; ++b) {
          worstP = std::max(worstP, std::abs(P2[0][2 * a + b] - P3[0][3 * a + b]));
          for (int c = 0; c < 2; ++c)
            for (int d = 0; d < 2; ++d)
              worstA = std::max(worstA, std::abs(A2[0][8 * a + 4 * b + 2 * c + d] -
                                                 A3[0][27 * a + 9 * b + 3 * c + d]));
        }
      two.commit(), three.commit();
      EXPECT_NEAR(two.committed("equivalent_plastic_strain", 0),
                  three.committed("equivalent_plastic_strain", 0), 1e-13)
          << model << " step " << i;
    }
    EXPECT_GT(two.committed("equivalent_plastic_strain", 0), 0.0) << model;
    EXPECT_LT(worstP, 1e-11 * kE) << model;
    EXPECT_LT(worstA, 1e-10 * kE) << model;
    std::cout << "  " << model << ": 2-D against 3-D at F_zz = 1, largest difference in P "
              << worstP << ", in A " << worstA << "\n";
  }
}

}  // namespace
}  // namespace impm

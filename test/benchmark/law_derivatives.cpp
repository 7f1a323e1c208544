// Benchmark: the cost of the 3-D finite-strain laws' consistent tangent by forward
// differentiation (core/ForwardAD: Sacado's static Fad along the nine components of F), as
// FiniteStrainPlasticity evaluates it per particle: the j2 and drucker-prager return maps at
// plastic states, P = tau F^-T and dP/dF.  Each is checked against central differences of
// the value path (to 1e-6 of the largest entry); the time per evaluation is the fastest of 5
// repetitions.  impm's own dual numbers took 1.17 (j2) and 1.20 (drucker-prager) times as
// long on this code (doc/performance.md), which is why the laws use Sacado.
//
// usage: law_derivatives [evaluations]   (default 200000)

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "material/DruckerPragerLaw.hpp"
#include "material/J2Law.hpp"

namespace {

using namespace impm;

// P and dP/dF (row-major, 81 entries) of Law at F from state n.
template <class Law, class T>
void piolaAndTangent(const double F[3][3], const PlasticState& n, const typename Law::Parameters& k,
                     double P[9], double A[81]) {
  T Fd[3][3], Finv[3][3], Pd[3][3];
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b)
      Fd[a][b] = T(variable<9>(F[a][b], 3 * a + b));
  const auto r = Law::returnMap(Fd, n, k);
  inverseOf(Fd, T(determinantOf(Fd)), Finv);
  piolaOfKirchhoff<3>(r.tau, Finv, Pd);
  for (int a = 0; a < 9; ++a) {
    P[a] = valueOf(Pd[a / 3][a % 3]);
    for (int c = 0; c < 9; ++c)
      A[9 * a + c] = derivativeOf(Pd[a / 3][a % 3], c);
  }
}

// Seconds per evaluation, the fastest of 5 repetitions over the deformations Fs; out gets P
// and A of the last repetition.
template <class Law, class T>
double timed(const std::vector<std::array<double, 9>>& Fs, const typename Law::Parameters& k,
             std::vector<double>& out) {
  const PlasticState n{{1, 1, 1, 0, 0, 0}, 0.0, 0.0};
  out.assign(Fs.size() * 90, 0.0);
  double best = 1e300;
  for (int repetition = 0; repetition < 5; ++repetition) {
    const auto start = std::chrono::steady_clock::now();
    for (std::size_t q = 0; q < Fs.size(); ++q) {
      double F[3][3];
      for (int a = 0; a < 9; ++a)
        F[a / 3][a % 3] = Fs[q][a];
      piolaAndTangent<Law, T>(F, n, k, &out[90 * q], &out[90 * q + 9]);
    }
    const std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
    best = std::min(best, took.count());
  }
  return best / Fs.size();
}

template <class Law>
int measure(const char* name, const std::vector<std::array<double, 9>>& Fs,
            const typename Law::Parameters& k) {
  std::vector<double> values;
  const double seconds = timed<Law, Fad<9>>(Fs, k, values);
  // The tangent of the first deformation against central differences of the value path.
  double worst = 0.0, scale = 0.0;
  const PlasticState n{{1, 1, 1, 0, 0, 0}, 0.0, 0.0};
  const double h = 1e-6;
  for (int c = 0; c < 9; ++c) {
    double Fp[3][3], Fm[3][3], Pp[9], Pm[9], unused[81];
    for (int a = 0; a < 9; ++a)
      Fp[a / 3][a % 3] = Fm[a / 3][a % 3] = Fs[0][a];
    Fp[c / 3][c % 3] += h, Fm[c / 3][c % 3] -= h;
    piolaAndTangent<Law, Fad<9>>(Fp, n, k, Pp, unused);
    piolaAndTangent<Law, Fad<9>>(Fm, n, k, Pm, unused);
    for (int a = 0; a < 9; ++a) {
      worst = std::max(worst, std::abs(values[9 + 9 * a + c] - (Pp[a] - Pm[a]) / (2 * h)));
      scale = std::max(scale, std::abs(values[9 + 9 * a + c]));
    }
  }
  std::printf(
      "%-15s %7.3f us per evaluation; tangent against central differences %.1e of "
      "the largest entry\n",
      name, 1e6 * seconds, worst / scale);
  return worst <= 1e-6 * scale ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  const int count = argc > 1 ? std::atoi(argv[1]) : 200000;
  // Deformations past yield from the virgin state: stretch, compression and shear in every
  // plane, different at each evaluation.
  std::vector<std::array<double, 9>> Fs(count);
  for (int q = 0; q < count; ++q) {
    const double s = 1.0 + 0.5 * q / count;
    Fs[q] = {1 + 0.02 * s, 0.02 * s,  -0.015 * s, -0.01 * s,    1 - 0.025 * s,
             0.025 * s,    0.012 * s, -0.02 * s,  1 + 0.015 * s};
  }
  const double E = 1000.0, nu = 0.3, mu = E / (2 * (1 + nu)),
               lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
  int failures = measure<J2Law>("j2", Fs, {mu, lambda, 10.0, 50.0});
  const auto [eta, xi] = DruckerPragerLaw::fit(30.0, "plane strain");
  failures += measure<DruckerPragerLaw>(
      "drucker-prager", Fs,
      {mu, lambda, 1.0, eta, xi, DruckerPragerLaw::fit(10.0, "plane strain").first});
  return failures;
}

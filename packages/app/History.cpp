#include "app/History.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <limits>

namespace impm {

template <int Dim>
History<Dim>::History(const std::vector<std::string>& bodyNames) : bodies_(bodyNames.size()) {
  columns_ = {"step",
              "time",
              "dt",
              "load_factor",
              "F0",
              "FL",
              "kinetic_energy",
              "strain_energy",
              "total_energy",
              "external_work",
              "energy_balance",
              "momentum"};
  for (const auto& b : bodyNames)
    for (const char* c : {"v_cm_", "x_min_", "x_max_"})
      columns_.push_back(c + b);
  for (const char* c : {"newton_iterations", "linear_iterations", "residual", "attempts"})
    columns_.push_back(c);
}

template <int Dim>
std::vector<double> History<Dim>::row(const StepRecord& r, double F0, double FL,
                                      const ParticleSet<Dim>& particles, const Comm& comm) const {
  // Per body: mass, momentum (first component), smallest and largest position.
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> sums(2 * bodies_, 0.0), lows(bodies_, inf), highs(bodies_, -inf);
  auto body = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), particles.body);
  auto m = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), particles.mass);
  auto v = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), particles.v);
  auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), particles.x);
  for (std::size_t p = 0; p < particles.size(); ++p) {
    const int b = body(p);
    sums[2 * b] += m(p);
    sums[2 * b + 1] += m(p) * v(p, 0);
    lows[b] = std::min(lows[b], x(p, 0));
    highs[b] = std::max(highs[b], x(p, 0));
  }
  std::vector<double> gsums(sums.size()), glows(bodies_), ghighs(bodies_);
  const int n = static_cast<int>(bodies_);
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, 2 * n, sums.data(), gsums.data());
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MIN, n, lows.data(), glows.data());
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, n, highs.data(), ghighs.data());

  double momentum = 0.0;
  for (std::size_t b = 0; b < bodies_; ++b)
    momentum += gsums[2 * b + 1];
  const double total = r.kineticEnergy + r.strainEnergy;
  std::vector<double> row = {
      double(r.step), r.time, r.dt,           r.loadFactor,           F0,      FL, r.kineticEnergy,
      r.strainEnergy, total,  r.externalWork, total - r.externalWork, momentum};
  for (std::size_t b = 0; b < bodies_; ++b) {
    row.push_back(gsums[2 * b] > 0 ? gsums[2 * b + 1] / gsums[2 * b] : 0.0);
    row.push_back(glows[b]);
    row.push_back(ghighs[b]);
  }
  const double residual = r.newton.residualNorms.empty() ? 0.0 : r.newton.residualNorms.back();
  for (double c : {double(r.newton.iterations()), double(r.newton.totalLinearIterations()),
                   residual, double(r.attempts)})
    row.push_back(c);
  return row;
}

template class History<1>;

}  // namespace impm

#include "app/History.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <algorithm>
#include <limits>

namespace impm {

template <int Dim>
History<Dim>::History(const std::vector<std::string>& bodyNames,
                      const std::vector<std::string>& supportNames)
    : bodies_(bodyNames.size()), supports_(supportNames.size()) {
  static_assert(Dim == 1 || Dim == 2, "History: the columns of this dimension");
  columns_ = {"step",
              "time",
              "dt",
              "load_factor",
              "F0",
              "FL",
              "kinetic_energy",
              "strain_energy",
              "dissipation",
              "total_energy",
              "external_work",
              "energy_balance",
              "momentum"};
  if (Dim == 2)
    columns_.push_back("momentum_y");
  for (const auto& b : bodyNames) {
    for (const char* c : {"v_cm_", "x_min_", "x_max_"})
      columns_.push_back(c + b);
    if (Dim == 2)
      for (const char* c : {"vy_cm_", "y_min_", "y_max_"})
        columns_.push_back(c + b);
  }
  for (std::string s : supportNames) {
    std::replace(s.begin(), s.end(), ' ', '_');
    columns_.push_back("reaction_" + s);
  }
  for (const char* c : {"newton_iterations", "linear_iterations", "residual", "attempts"})
    columns_.push_back(c);
}

template <int Dim>
std::vector<double> History<Dim>::row(const StepRecord& r, double F0, double FL,
                                      const ParticleSet<Dim>& particles, const Comm& comm) const {
  // Per body: mass, momentum, smallest and largest position, per component.
  const double inf = std::numeric_limits<double>::infinity();
  const std::size_t n = bodies_ * Dim;
  std::vector<double> mass(bodies_, 0.0), sums(n, 0.0), lows(n, inf), highs(n, -inf);
  const auto host = particles.mirror(Kokkos::DefaultHostExecutionSpace());
  for (std::size_t p = 0; p < particles.size(); ++p) {
    const int b = host.body(p);
    mass[b] += host.mass(p);
    for (int d = 0; d < Dim; ++d) {
      const std::size_t k = b * Dim + d;
      sums[k] += host.mass(p) * host.v(p, d);
      lows[k] = std::min(lows[k], host.x(p, d));
      highs[k] = std::max(highs[k], host.x(p, d));
    }
  }
  std::vector<double> gmass(bodies_), gsums(n), glows(n), ghighs(n);
  const int count = static_cast<int>(n);
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, static_cast<int>(bodies_), mass.data(),
                     gmass.data());
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, count, sums.data(), gsums.data());
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MIN, count, lows.data(), glows.data());
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, count, highs.data(), ghighs.data());

  double momentum[Dim] = {};
  for (std::size_t b = 0; b < bodies_; ++b)
    for (int d = 0; d < Dim; ++d)
      momentum[d] += gsums[b * Dim + d];
  const double total = r.kineticEnergy + r.strainEnergy + r.dissipation;
  std::vector<double> row = {double(r.step),
                             r.time,
                             r.dt,
                             r.loadFactor,
                             F0,
                             FL,
                             r.kineticEnergy,
                             r.strainEnergy,
                             r.dissipation,
                             total,
                             r.externalWork,
                             total - r.externalWork,
                             momentum[0]};
  if (Dim == 2)
    row.push_back(momentum[Dim - 1]);
  for (std::size_t b = 0; b < bodies_; ++b)
    for (int d = 0; d < Dim; ++d) {
      const std::size_t k = b * Dim + d;
      row.push_back(gmass[b] > 0 ? gsums[k] / gmass[b] : 0.0);
      row.push_back(glows[k]);
      row.push_back(ghighs[k]);
    }
  for (std::size_t s = 0; s < supports_; ++s)  // the initial state has no reactions yet
    row.push_back(s < r.supportForces.size() ? r.supportForces[s] : 0.0);
  const double residual = r.newton.residualNorms.empty() ? 0.0 : r.newton.residualNorms.back();
  for (double c : {double(r.newton.iterations()), double(r.newton.totalLinearIterations()),
                   residual, double(r.attempts)})
    row.push_back(c);
  return row;
}

template class History<1>;
template class History<2>;

}  // namespace impm

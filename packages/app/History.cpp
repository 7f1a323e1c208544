#include "app/History.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <algorithm>
#include <limits>

#include "core/Axes.hpp"

namespace impm {

template <int Dim>
History<Dim>::History(const std::vector<std::string>& bodyNames,
                      const std::vector<std::string>& supportNames)
    : bodies_(bodyNames.size()), supports_(supportNames.size()) {
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
  // The x components keep their 1-D names (momentum, v_cm_<body>); y and z are named.
  for (int d = 1; d < Dim; ++d)
    columns_.push_back(std::string("momentum_") + axisName(d));
  for (const auto& b : bodyNames)
    for (int d = 0; d < Dim; ++d) {
      const std::string v = d == 0 ? "v" : std::string("v") + axisName(d), x = axisName(d);
      for (const std::string& c : {v + "_cm_", x + "_min_", x + "_max_"})
        columns_.push_back(c + b);
    }
  for (std::string s : supportNames) {
    std::replace(s.begin(), s.end(), ' ', '_');
    columns_.push_back("reaction_" + s);
  }
  for (const char* c : {"newton_iterations", "linear_iterations", "residual", "attempts"})
    columns_.push_back(c);
}

namespace {

// Per body: mass, momentum, smallest and largest position, per component.
template <int Dim>
struct BodySums {
  std::vector<double> mass, sums, lows, highs;
  explicit BodySums(std::size_t bodies)
      : mass(bodies, 0.0),
        sums(bodies * Dim, 0.0),
        lows(bodies * Dim, std::numeric_limits<double>::infinity()),
        highs(bodies * Dim, -std::numeric_limits<double>::infinity()) {}
};

// Particles come in runs of one body (bodies are seeded in turn, and migration moves
// blocks): each run is summed in local variables, which the compiler keeps in registers,
// then merged.  Two partial sums and extents (lanes) run side by side, so that the loop
// does not wait on one chain of additions or comparisons.  (One accumulator per body,
// updated through memory at every particle, cost as much as the residual's force sums.)
template <int Dim, class Host>
void addRun(const Host& host, std::size_t begin, std::size_t end, BodySums<Dim>& out) {
  constexpr int lanes = 2;
  const double inf = std::numeric_limits<double>::infinity();
  double mass[lanes] = {}, sum[lanes][Dim] = {}, low[lanes][Dim], high[lanes][Dim];
  for (int l = 0; l < lanes; ++l)
    for (int d = 0; d < Dim; ++d)
      low[l][d] = inf, high[l][d] = -inf;
  const auto add = [&](int l, std::size_t p) {
    mass[l] += host.mass(p);
    for (int d = 0; d < Dim; ++d) {
      sum[l][d] += host.mass(p) * host.v(p, d);
      low[l][d] = std::min(low[l][d], host.x(p, d));
      high[l][d] = std::max(high[l][d], host.x(p, d));
    }
  };
  std::size_t p = begin;
  for (; p + lanes <= end; p += lanes)
    for (int l = 0; l < lanes; ++l)
      add(l, p + l);
  for (int l = 0; p < end; ++p, ++l)
    add(l, p);
  const int b = host.body(begin);
  for (int l = 0; l < lanes; ++l) {
    out.mass[b] += mass[l];
    for (int d = 0; d < Dim; ++d) {
      const std::size_t k = b * Dim + d;
      out.sums[k] += sum[l][d];
      out.lows[k] = std::min(out.lows[k], low[l][d]);
      out.highs[k] = std::max(out.highs[k], high[l][d]);
    }
  }
}

}  // namespace

template <int Dim>
std::vector<double> History<Dim>::row(const StepRecord& r, double F0, double FL,
                                      const ParticleSet<Dim>& particles, const Comm& comm) const {
  const std::size_t n = bodies_ * Dim;
  BodySums<Dim> local(bodies_);
  const auto host = particles.mirror(Kokkos::DefaultHostExecutionSpace());
  for (std::size_t begin = 0; begin < particles.size();) {
    std::size_t end = begin + 1;
    while (end < particles.size() && host.body(end) == host.body(begin))
      ++end;
    addRun<Dim>(host, begin, end, local);
    begin = end;
  }
  auto& [mass, sums, lows, highs] = local;
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
  for (int d = 1; d < Dim; ++d)
    row.push_back(momentum[d]);
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
template class History<3>;

}  // namespace impm

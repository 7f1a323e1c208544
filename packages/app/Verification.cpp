#include "app/Verification.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <array>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <tuple>

#include "core/Axes.hpp"
#include "core/Errors.hpp"
#include "core/Parameters.hpp"

namespace impm {

Teuchos::ParameterList verificationValidParameters() {
  Teuchos::ParameterList valid;
  declareString(valid, "Exact Displacement", "",
                "Exact displacement u(X, t), a formula of the reference position X and time t; "
                "when given, the particle RMS error is measured and reported (1-D)");
  for (int d = 0; d < 3; ++d)
    declareString(valid, std::string("Exact Displacement ") + axisName(d), "",
                  std::string(d < 2 ? "2-D and 3-D: " : "3-D: ") + axisName(d) +
                      " component of the exact displacement, a formula of the reference "
                      "position X, Y (, Z) and time t (every component, or none)");
  declareDouble(valid, "Maximum RMS Error", 0.0,
                "Fail the run when the RMS displacement error exceeds this (0: no check)",
                Bounds::nonNegative());
  declareDouble(valid, "Expected F0", 0.0, "Expected force F(0) at the left Robin end");
  declareDouble(valid, "Expected FL", 0.0, "Expected force F(L) at the right Robin end");
  declareDouble(valid, "Reaction Tolerance", 0.0,
                "Fail the run when F0 or FL differs from its expected value by more than this, "
                "relative to max(1, |expected|) (0: no check)",
                Bounds::nonNegative());
  return valid;
}

Verification::Verification(const Teuchos::ParameterList& params)
    : hasExact_(!params.get<std::string>("Exact Displacement").empty() ||
                !params.get<std::string>("Exact Displacement x").empty() ||
                !params.get<std::string>("Exact Displacement y").empty() ||
                !params.get<std::string>("Exact Displacement z").empty()),
      maxRms_(params.get<double>("Maximum RMS Error")),
      expectedF0_(params.get<double>("Expected F0")),
      expectedFL_(params.get<double>("Expected FL")),
      reactionTolerance_(params.get<double>("Reaction Tolerance")) {
  const auto read = [&](const std::string& name, const std::vector<std::string>& vars) {
    try {
      return Formula(params.get<std::string>(name), vars);
    } catch (const InputError& e) {
      throw InputError("Verification/" + name, e.what());
    }
  };
  if (!params.get<std::string>("Exact Displacement").empty()) {
    exact_.push_back(read("Exact Displacement", {"X", "t"}));
  } else if (hasExact_) {  // 3 components when z is given, else 2
    const int components = params.get<std::string>("Exact Displacement z").empty() ? 2 : 3;
    std::vector<std::string> variables;
    for (int d = 0; d < components; ++d)
      variables.push_back(referenceAxisName(d));
    variables.push_back("t");
    for (int d = 0; d < components; ++d) {
      const std::string name = std::string("Exact Displacement ") + axisName(d);
      if (params.get<std::string>(name).empty())
        throw InputError("Verification/" + name, "is missing: give every component");
      exact_.push_back(read(name, variables));
    }
  }
  if (maxRms_ > 0 && !hasExact_)
    throw InputError("Verification/Maximum RMS Error", "needs Verification/Exact Displacement");
}

template <int Dim>
VerificationResult Verification::check(const ParticleSet<Dim>& particles,
                                       const Teuchos::RCP<const Comm>& comm, double time, double F0,
                                       double FL) const {
  VerificationResult result;
  std::ostringstream line;
  line.precision(6);
  if (hasExact_) {
    if (static_cast<int>(exact_.size()) != Dim)
      throw InputError("Verification/Exact Displacement",
                       Dim == 1 ? "use 'Exact Displacement' on a 1-D grid"
                                : "use 'Exact Displacement x' to 'Exact Displacement " +
                                      std::string(axisName(Dim - 1)) + "' on a " +
                                      std::to_string(Dim) + "-D grid");
    auto X = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), particles.X);
    auto u = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), particles.u);
    double local[2] = {0.0, 0.0}, global[2];
    for (std::size_t p = 0; p < particles.size(); ++p) {
      double e2 = 0.0;
      std::array<double, Dim + 1> at;  // X, (Y, Z,) t
      for (int d = 0; d < Dim; ++d)
        at[d] = X(p, d);
      at[Dim] = time;
      for (int d = 0; d < Dim; ++d) {
        const double ed = u(p, d) - exact_[d](at);
        e2 += ed * ed;
      }
      const double e = std::sqrt(e2);
      local[0] += e2;
      local[1] = std::max(local[1], std::abs(e));
    }
    const GlobalId n = particles.size();
    Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, 1, local, global);
    Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, 1, local + 1, global + 1);
    Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, n, Teuchos::outArg(result.points));
    result.hasExact = true;
    result.rmsError = std::sqrt(global[0] / result.points);
    result.maxError = global[1];
    line << std::scientific << "RMS displacement error " << result.rmsError << " (max "
         << result.maxError << ") over " << result.points << " points";
    if (maxRms_ > 0) {
      const bool ok = result.rmsError <= maxRms_;
      line << (ok ? ", within " : ", ABOVE the allowed ") << maxRms_;
      if (!ok)
        result.failures.push_back(line.str());
    }
    result.report.push_back(line.str());
  }
  if (reactionTolerance_ > 0) {
    for (const auto& [name, value, expected] :
         {std::make_tuple("F0", F0, expectedF0_), std::make_tuple("FL", FL, expectedFL_)}) {
      if (std::isnan(value))
        continue;  // the deck has no Robin condition at this end
      std::ostringstream msg;
      msg.precision(10);
      const double error = std::abs(value - expected) / std::max(1.0, std::abs(expected));
      msg << name << " = " << value << ", expected " << expected << " (relative difference "
          << std::scientific << std::setprecision(2) << error << ", tolerance "
          << reactionTolerance_ << ")";
      if (!(error <= reactionTolerance_))
        result.failures.push_back(msg.str());
      result.report.push_back(msg.str());
    }
  }
  return result;
}

template VerificationResult Verification::check<1>(const ParticleSet<1>&,
                                                   const Teuchos::RCP<const Comm>&, double, double,
                                                   double) const;
template VerificationResult Verification::check<2>(const ParticleSet<2>&,
                                                   const Teuchos::RCP<const Comm>&, double, double,
                                                   double) const;
template VerificationResult Verification::check<3>(const ParticleSet<3>&,
                                                   const Teuchos::RCP<const Comm>&, double, double,
                                                   double) const;

}  // namespace impm

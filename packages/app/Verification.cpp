#include "app/Verification.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <cmath>
#include <iomanip>
#include <sstream>
#include <tuple>

#include "core/Errors.hpp"
#include "core/Parameters.hpp"

namespace impm {

Teuchos::ParameterList verificationValidParameters() {
  Teuchos::ParameterList valid;
  declareString(valid, "Exact Displacement", "",
                "Exact displacement u(X, t), a formula of the reference position X and time t; "
                "when given, the particle RMS error is measured and reported");
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
    : hasExact_(!params.get<std::string>("Exact Displacement").empty()),
      maxRms_(params.get<double>("Maximum RMS Error")),
      expectedF0_(params.get<double>("Expected F0")),
      expectedFL_(params.get<double>("Expected FL")),
      reactionTolerance_(params.get<double>("Reaction Tolerance")) {
  if (hasExact_) {
    try {
      exact_ = Formula(params.get<std::string>("Exact Displacement"), {"X", "t"});
    } catch (const InputError& e) {
      throw InputError("Verification/Exact Displacement", e.what());
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
    auto X = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), particles.X);
    auto u = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), particles.u);
    double local[2] = {0.0, 0.0}, global[2];
    for (std::size_t p = 0; p < particles.size(); ++p) {
      const double e = u(p, 0) - exact_(X(p, 0), time);
      local[0] += e * e;
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
      std::ostringstream msg;
      msg.precision(10);
      const double error = std::abs(value - expected) / std::max(1.0, std::abs(expected));
      msg << name << " = " << value << ", expected " << expected << " (relative difference "
          << std::scientific << std::setprecision(2) << error << ", tolerance "
          << reactionTolerance_ << ")";
      if (error > reactionTolerance_)
        result.failures.push_back(msg.str());
      result.report.push_back(msg.str());
    }
  }
  return result;
}

template VerificationResult Verification::check<1>(const ParticleSet<1>&,
                                                   const Teuchos::RCP<const Comm>&, double, double,
                                                   double) const;

}  // namespace impm

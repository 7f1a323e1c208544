#include "app/TimeIntegration.hpp"

#include "core/Parameters.hpp"

namespace impm {

namespace {

// Parameters every transient scheme takes.
void declareTransient(Teuchos::ParameterList& valid) {
  declareDouble(valid, "Time Step", 0.01, "Time step dt", Bounds::positive(), true);
  declareDouble(valid, "Minimum Time Step", 0.0,
                "Smallest time step a failed step may be cut to (0: Time Step / 1024)",
                Bounds::nonNegative());
  declareDouble(valid, "FLIP Fraction", 1.0,
                "Particle velocity update, updated Lagrangian: 1 FLIP (v_p += sum phi_ip dv_i), "
                "0 PIC (v_p = sum phi_ip v_i), or a blend",
                Bounds::between(0.0, 1.0));
}

}  // namespace

Teuchos::ParameterList timeIntegrationValidParameters() {
  Teuchos::ParameterList valid;
  declareChoice(valid, "Type", "static", {"static", "newmark", "explicit"},
                "static: quasi-static load stepping (no inertia); newmark: implicit Newmark "
                "with Newton; explicit: the primer's explicit update (eq. 1.51-1.53), lumped "
                "mass");
  declareDouble(valid, "Final Time", 1.0,
                "Dynamic runs: the end time.  Static runs: the time at which formulas of t are "
                "evaluated",
                Bounds::positive());
  auto& statics = valid.sublist("[Type=static]");
  declareInt(statics, "Load Steps", 1, "Equal load increments from 0 to the full loads",
             Bounds::atLeast(1));
  declareFormula(statics, "Load Path", "s", {"s"},
                 "The load factor lambda(s) as a formula of the pseudo-time s, which the load "
                 "steps advance from 0 to 1 (s: a ramp to the full loads; for example "
                 "'s < 0.5 ? 2*s : 2 - 2*s' loads and unloads)");
  declareDouble(statics, "Minimum Load Increment", 1e-4,
                "Smallest load increment a failed step may be cut to", Bounds::positive());
  declareChoice(statics, "Predictor", "extrapolate", {"extrapolate", "zero"},
                "Where each load step's Newton iterations start.  extrapolate: from the last "
                "accepted step's displacement increment scaled by the ratio of the load factor "
                "increments (linear extrapolation, as commercial implicit codes do by default); "
                "zero: from no displacement beyond the prescribed one");

  auto& newmark = valid.sublist("[Type=newmark]");
  declareTransient(newmark);
  declareDouble(newmark, "Beta", 0.25, "Newmark beta (1/4: average acceleration)",
                Bounds{0.0, 0.5, true, false});
  declareDouble(newmark, "Gamma", 0.5, "Newmark gamma (1/2: no numerical damping)",
                Bounds::between(0.0, 1.0));
  declareChoice(newmark, "Mass", "lumped", {"lumped", "consistent"},
                "lumped: m_i = sum_p m_p phi_ip (eq. 1.49); consistent: "
                "M_ij = sum_p m_p phi_ip phi_jp (eq. 1.48)");
  declareChoice(newmark, "Initial Acceleration", "equilibrium", {"equilibrium", "zero"},
                "equilibrium: solve M a = f_ext - f_int at t = 0 with the boundary conditions; "
                "zero: start from rest acceleration");

  auto& explicitList = valid.sublist("[Type=explicit]");
  declareTransient(explicitList);
  declareChoice(explicitList, "Position Update", "central difference",
                {"central difference", "primer"},
                "central difference: u += dt v^(n+1), stable for dt <= h/c; primer: eq. 1.53 as "
                "printed, u += dt v^n + dt^2 a^n / 2, unconditionally unstable (for study)");
  declareBool(explicitList, "Allow Unstable Time Step", false,
              "Run even when Time Step exceeds the stability limit h/c (otherwise an input "
              "error)");
  return valid;
}

bool isStatic(const Teuchos::ParameterList& p) {
  return p.get<std::string>("Type") == "static";
}

DynamicSettings dynamicSettings(const Teuchos::ParameterList& p) {
  DynamicSettings s;
  const bool newmark = p.get<std::string>("Type") == "newmark";
  s.integrator = newmark ? DynamicSettings::Integrator::newmark
                 : p.get<std::string>("Position Update") == "primer"
                     ? DynamicSettings::Integrator::primerTaylor
                     : DynamicSettings::Integrator::centralDifference;
  s.timeStep = p.get<double>("Time Step");
  s.finalTime = p.get<double>("Final Time");
  s.minTimeStep = p.get<double>("Minimum Time Step") > 0 ? p.get<double>("Minimum Time Step")
                                                         : s.timeStep / 1024;
  s.flip = p.get<double>("FLIP Fraction");
  if (newmark) {
    s.beta = p.get<double>("Beta");
    s.gamma = p.get<double>("Gamma");
    s.mass = p.get<std::string>("Mass") == "consistent" ? MassType::consistent : MassType::lumped;
    s.equilibriumInitialAcceleration = p.get<std::string>("Initial Acceleration") == "equilibrium";
  }
  return s;
}

}  // namespace impm

#include "solver/NoxChoices.hpp"

#include <NOX.H>
#include <NOX_Thyra.H>
#include <Thyra_TpetraThyraWrappers.hpp>

#include <algorithm>
#include <iostream>

#include "core/CapturedOutput.hpp"
#include "core/Errors.hpp"
#include "solver/LinearSolver.hpp"
#include "solver/ModelEvaluator.hpp"

namespace impm {

namespace {

// R(x) = 2 (x - 1) on one unknown per rank.
class ProbeModel : public ResidualModel {
 public:
  explicit ProbeModel(const Teuchos::RCP<const Comm>& comm)
      : map_(Teuchos::rcp(new Map(comm->getSize(), 0, comm))) {}
  Teuchos::RCP<const Map> unknownMap() const override { return map_; }
  Teuchos::RCP<CrsMatrix> createJacobian() const override {
    auto J = Teuchos::rcp(new CrsMatrix(map_, 1));
    const GO row = map_->getGlobalElement(0);
    J->insertGlobalValues(row, Teuchos::tuple<GO>(row), Teuchos::tuple<double>(2.0));
    J->fillComplete();
    return J;
  }
  void evaluate(const Vector& x, Vector* residual, CrsMatrix* /*jacobian*/) override {
    if (residual) {
      residual->putScalar(-2.0);
      residual->update(2.0, x, 1.0);
    }
  }

 private:
  Teuchos::RCP<const Map> map_;
};

}  // namespace

const std::vector<NoxChoice>& supportedNoxChoices() {
  static const std::vector<NoxChoice> choices = {
      {"Nonlinear Solver", {"Line Search Based"}},
      {"Direction/Method", {"Newton"}},
      {"Line Search/Method", {"Full Step", "Backtrack", "Polynomial"}}};
  return choices;
}

void checkNoxList(const Teuchos::ParameterList& nox, const Teuchos::RCP<const Comm>& comm) {
  for (const auto& choice : supportedNoxChoices()) {
    const Teuchos::ParameterList* list = &nox;
    std::string name = choice.path;
    for (auto slash = name.find('/'); slash != std::string::npos; slash = name.find('/')) {
      const std::string sub = name.substr(0, slash);
      if (!list->isSublist(sub))
        break;
      list = &list->sublist(sub);
      name = name.substr(slash + 1);
    }
    if (name.find('/') != std::string::npos || !list->isParameter(name))
      continue;
    const std::string path = "Solver/NOX/" + choice.path;
    if (!list->isType<std::string>(name))
      throw InputError(path, "must be a string");
    const auto value = list->get<std::string>(name);
    if (std::find(choice.supported.begin(), choice.supported.end(), value) ==
        choice.supported.end()) {
      std::string names;
      for (const auto& s : choice.supported)
        names += (names.empty() ? "" : ", ") + s;
      throw InputError(path, "'" + value +
                                 "' is not supported: impm gives NOX a Newton direction from "
                                 "the assembled Jacobian and a line search along it (one of: " +
                                 names + ")");
    }
  }
  // The list built and run on R(x) = 2 (x - 1), with a plain Krylov solve; what NOX prints
  // goes into the message.
  const CapturedOutput said;
  const auto printed = [&] {
    std::cout << std::flush;
    const std::string line = said.firstLine();
    return line.empty() ? std::string() : ": " + line;
  };
  try {
    Teuchos::ParameterList plain;
    plain.set("Linear Solver Type", "Belos");
    plain.set("Preconditioner Type", "None");
    auto lows = createLinearSolveStrategy(plain, comm, "Solver/NOX");
    auto model = Teuchos::rcp(new ProbeModel(comm));
    auto me = Teuchos::rcp(new MpmModelEvaluator(model, lows));
    Vector x(model->unknownMap());
    auto guess =
        Thyra::createVector<double, LO, GO, Node>(Teuchos::rcpFromRef(x), me->get_x_space());
    auto group =
        Teuchos::rcp(new NOX::Thyra::Group(NOX::Thyra::Vector(guess), me, me->create_W_op(), lows,
                                           Teuchos::null, Teuchos::null, Teuchos::null));
    auto params = Teuchos::rcp(new Teuchos::ParameterList(nox));
    // NOX reads it as an int at every solve; the probe is quiet, so it reads it here.
    if (const auto* shown = params->sublist("Printing").getEntryPtr("Output Information");
        shown && !shown->isType<int>() && !shown->isType<NOX::Utils::MsgType>())
      throw InputError("Solver/NOX/Printing/Output Information",
                       "must be an int (a sum of NOX::Utils' message types), not " +
                           std::string(shown->getAny().typeName()) + " '" +
                           Teuchos::toString(shown->getAny()) + "'");
    params->sublist("Printing").set("Output Information", NOX::Utils::Error);
    auto tests = Teuchos::rcp(new NOX::StatusTest::MaxIters(2));
    auto solver = NOX::Solver::buildSolver(group, tests, params);
    solver->solve();
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError("Solver/NOX", trilinosMessage(e.what()));
  } catch (const char*) {  // NOX throws "NOX Error" as a string literal, having printed why
    throw InputError("Solver/NOX", "NOX rejects the list" + printed());
  }
}

}  // namespace impm

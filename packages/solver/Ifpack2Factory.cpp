#include "solver/Ifpack2Factory.hpp"

namespace impm {

Teuchos::RCP<const Teuchos::ParameterList> Ifpack2Factory::getValidParameters() const {
  static Teuchos::RCP<Teuchos::ParameterList> valid;
  if (valid.is_null()) {
    valid = Teuchos::rcp(new Teuchos::ParameterList(
        *Thyra::Ifpack2PreconditionerFactory<CrsMatrix>::getValidParameters()));
    auto& settings = valid->sublist("Ifpack2 Settings");
    // Ifpack2::AdditiveSchwarz: the subdomain solver and its list (checked by the solver
    // it names when the preconditioner is built).  AMESOS2 needs "Amesos2 solver name" and
    // an "Amesos2" sublist in it.
    settings.set("schwarz: inner preconditioner name", "ILUT",
                 "Ifpack2 preconditioner of each rank's subdomain: ILUT, RILUK, RELAXATION, "
                 "CHEBYSHEV, AMESOS2, ...");
    settings.sublist("schwarz: inner preconditioner parameters", false,
                     "Ifpack2 parameters of the subdomain solver");
    // Ifpack2::RILUK: "Serial" (Ifpack2's own) or "KSPILUK" (KokkosKernels).
    settings.set("fact: type", "Serial", "RILUK implementation: Serial or KSPILUK");
  }
  return valid;
}

}  // namespace impm

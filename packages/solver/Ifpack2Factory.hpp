#pragma once
// The Stratimikos preconditioner factory for Ifpack2, with the parameters that Trilinos
// 13.2's Ifpack2::getValidParameters omits added to its valid list.  Stratimikos checks
// the deck's "Ifpack2 Settings" against that list, so without them a deck could not choose
// the solver of AdditiveSchwarz's subdomains (an exact local LU by Amesos2 KLU2, say) or
// RILUK's KokkosKernels implementation, although Ifpack2 itself accepts both.

#include <Thyra_Ifpack2PreconditionerFactory.hpp>

#include "core/TpetraTypes.hpp"

namespace impm {

class Ifpack2Factory : public Thyra::Ifpack2PreconditionerFactory<CrsMatrix> {
 public:
  Teuchos::RCP<const Teuchos::ParameterList> getValidParameters() const override;
};

}  // namespace impm

#pragma once
// The valid parameters of a whole deck, assembled from each component's own list.  This is
// the single source of `impm --list-parameters` and of doc/user-guide.md.

#include <Teuchos_ParameterList.hpp>

namespace impm {

Teuchos::ParameterList deckValidParameters();

}  // namespace impm

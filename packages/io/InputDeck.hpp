#pragma once
// The input deck: a Teuchos XML parameter list, with command-line overrides, validated
// against the valid parameters before anything else happens.  Every problem is reported as
// an InputError naming the parameter's path; the driver adds the file name.

#include <Teuchos_ParameterList.hpp>

#include <string>
#include <vector>

namespace impm {

// --set Path/To/Param=value
struct Override {
  std::string path;
  std::string value;
};

// Parses "Path/To/Param=value"; throws InputError on a malformed override.
Override parseOverride(const std::string& text);

// Reads `file`, applies the overrides (typed like the parameters they replace: Teuchos
// array syntax for arrays), validates against `valid` and fills defaults.
Teuchos::ParameterList loadDeck(const std::string& file, const std::vector<Override>& overrides,
                                const Teuchos::ParameterList& valid);

// The deck file's name without directory and extension (the default output prefix).
std::string deckStem(const std::string& file);

}  // namespace impm

#pragma once
// The registry of constitutive models: the valid parameters of Materials/<name> (one
// "[Model=...]" variant per model) and construction from a validated sublist.  Adding a
// model = one class and one line in MaterialFactory.cpp.

#include <Teuchos_ParameterList.hpp>

#include <memory>
#include <string>
#include <vector>

#include "material/Material.hpp"

namespace impm {

template <int Dim>
std::vector<std::string> materialModels();

// Valid parameters of one Materials/<name> sublist: the models of every dimension, so that
// one list documents them all; createMaterial<Dim> rejects a model of another dimension.
Teuchos::ParameterList materialValidParameters();

template <int Dim>
std::shared_ptr<Material<Dim>> createMaterial(const std::string& name,
                                              const Teuchos::ParameterList& params);

}  // namespace impm

#pragma once
// The registry of constitutive models: the valid parameters of Materials/<name> (one
// "[Model=...]" variant per model) and construction from a validated sublist.  Adding a
// model = one class and one line in MaterialFactory.cpp (or, for a law that lives outside
// impm, one call of registerMaterialModel before the deck is read).

#include <Teuchos_ParameterList.hpp>

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "material/Material.hpp"

namespace impm {

// A model: its name (Materials/<name>/Model), its parameters, its construction.
template <int Dim>
struct MaterialModel {
  std::string model;
  std::function<Teuchos::ParameterList()> validParameters;
  std::function<std::shared_ptr<Material<Dim>>(const std::string&, const Teuchos::ParameterList&)>
      create;
};

// The model of class M: M::model(), M::validParameters(), M(name, params).
template <class M, int Dim = M::dimension>
MaterialModel<Dim> materialModel() {
  return {M::model(), &M::validParameters,
          [](const std::string& name, const Teuchos::ParameterList& params) {
            return std::make_shared<M>(name, params);
          }};
}

// Adds a model to the registry; throws std::invalid_argument when its name is taken.
template <int Dim>
void registerMaterialModel(const MaterialModel<Dim>& model);

template <int Dim>
std::vector<std::string> materialModels();

// Valid parameters of one Materials/<name> sublist: the models of every dimension, so that
// one list documents them all; createMaterial<Dim> rejects a model of another dimension.
Teuchos::ParameterList materialValidParameters();

template <int Dim>
std::shared_ptr<Material<Dim>> createMaterial(const std::string& name,
                                              const Teuchos::ParameterList& params);

}  // namespace impm

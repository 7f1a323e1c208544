#include "material/MaterialFactory.hpp"

#include <algorithm>
#include <functional>

#include "core/Errors.hpp"
#include "core/Parameters.hpp"
#include "material/DruckerPragerLaw.hpp"
#include "material/ElasticLaws.hpp"
#include "material/ElasticLaws1D.hpp"
#include "material/FormulaLaw1D.hpp"
#include "material/HenckyLaw.hpp"
#include "material/J2Law.hpp"
#include "material/PlasticLaw1D.hpp"

namespace impm {

namespace {

template <int Dim>
std::vector<MaterialModel<Dim>>& registry();

// The registration lines: one per model.
template <>
std::vector<MaterialModel<1>>& registry<1>() {
  static std::vector<MaterialModel<1>> models = {
      materialModel<ElasticLaw1D<LinearLaw>, 1>(),
      materialModel<ElasticLaw1D<LinearFiniteLaw>, 1>(),
      materialModel<ElasticLaw1D<CubicLaw>, 1>(),
      materialModel<ElasticLaw1D<NeoHookeanLaw1D>, 1>(),
      materialModel<ElasticLaw1D<HenckyLaw1D>, 1>(),
      materialModel<J2Law1D, 1>(),
      materialModel<FormulaLaw1D, 1>(),
  };
  return models;
}

template <>
std::vector<MaterialModel<2>>& registry<2>() {
  static std::vector<MaterialModel<2>> models = {
      materialModel<ElasticLaw<2, LinearElasticLaw>, 2>(),
      materialModel<ElasticLaw<2, NeoHookeanLaw>, 2>(),
      materialModel<ElasticLaw<2, HenckyLaw>, 2>(),
      materialModel<FiniteStrainPlasticity<2, J2Law>, 2>(),
      materialModel<FiniteStrainPlasticity<2, DruckerPragerLaw>, 2>(),
  };
  return models;
}

template <>
std::vector<MaterialModel<3>>& registry<3>() {
  static std::vector<MaterialModel<3>> models = {
      materialModel<ElasticLaw<3, LinearElasticLaw>, 3>(),
      materialModel<ElasticLaw<3, NeoHookeanLaw>, 3>(),
      materialModel<ElasticLaw<3, HenckyLaw>, 3>(),
      materialModel<FiniteStrainPlasticity<3, J2Law>, 3>(),
      materialModel<FiniteStrainPlasticity<3, DruckerPragerLaw>, 3>(),
  };
  return models;
}

template <int Dim>
void addVariants(Teuchos::ParameterList& valid, std::vector<std::string>& models) {
  for (const auto& e : registry<Dim>()) {
    if (std::find(models.begin(), models.end(), e.model) != models.end())
      continue;  // the same model in another dimension: the same parameters
    models.push_back(e.model);
    valid.sublist("[Model=" + e.model + "]", false, std::to_string(Dim) + "-D model")
        .setParameters(e.validParameters());
  }
}

}  // namespace

template <int Dim>
void registerMaterialModel(const MaterialModel<Dim>& model) {
  for (const auto& e : registry<Dim>())
    if (e.model == model.model)
      throw std::invalid_argument("material model '" + model.model + "' is registered twice");
  registry<Dim>().push_back(model);
}

template <int Dim>
std::vector<std::string> materialModels() {
  std::vector<std::string> names;
  for (const auto& e : registry<Dim>())
    names.push_back(e.model);
  return names;
}

Teuchos::ParameterList materialValidParameters() {
  Teuchos::ParameterList variants;
  std::vector<std::string> models;
  addVariants<1>(variants, models);
  addVariants<2>(variants, models);
  addVariants<3>(variants, models);
  Teuchos::ParameterList valid;
  declareChoice(valid, "Model", models.front(), models, "Constitutive model", true);
  declareDouble(valid, "Density", 1.0, "Mass density in the reference configuration",
                Bounds::positive());
  valid.setParameters(variants);
  return valid;
}

template <int Dim>
std::shared_ptr<Material<Dim>> createMaterial(const std::string& name,
                                              const Teuchos::ParameterList& params) {
  const auto& model = params.get<std::string>("Model");
  for (const auto& e : registry<Dim>())
    if (e.model == model)
      return e.create(name, params);
  throw InputError("Materials/" + name + "/Model",
                   "model '" + model + "' is not a " + std::to_string(Dim) +
                       "-D model, and this deck's grid is " + std::to_string(Dim) + "-D");
}

template void registerMaterialModel<1>(const MaterialModel<1>&);
template void registerMaterialModel<2>(const MaterialModel<2>&);
template void registerMaterialModel<3>(const MaterialModel<3>&);
template std::vector<std::string> materialModels<1>();
template std::vector<std::string> materialModels<2>();
template std::vector<std::string> materialModels<3>();
template std::shared_ptr<Material<1>> createMaterial<1>(const std::string&,
                                                        const Teuchos::ParameterList&);
template std::shared_ptr<Material<2>> createMaterial<2>(const std::string&,
                                                        const Teuchos::ParameterList&);
template std::shared_ptr<Material<3>> createMaterial<3>(const std::string&,
                                                        const Teuchos::ParameterList&);

}  // namespace impm

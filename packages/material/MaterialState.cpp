#include "material/MaterialState.hpp"

#include <Teuchos_CommHelpers.hpp>

#include "core/Errors.hpp"
#include "core/TpetraTypes.hpp"

namespace impm {

template <int Dim>
void declareMaterialVariables(ParticleSet<Dim>& particles, const Materials<Dim>& materials) {
  std::map<std::string, std::string> declaredBy;  // variable -> first material declaring it
  for (const auto& m : materials)
    for (const auto& v : m->variables()) {
      const std::string& name = v.spec.name;
      const std::string path = "Materials/" + m->name();
      if (!particles.has(name)) {
        try {
          particles.declare(v.spec);
        } catch (const std::invalid_argument& e) {
          throw InputError(path, e.what());
        }
        declaredBy[name] = m->name();
        continue;
      }
      const auto owner = declaredBy.find(name);
      if (owner == declaredBy.end())
        throw InputError(path,
                         "the law's variable '" + name + "' has the name of a framework field");
      const FieldSpec& other = particles.spec(name);
      if (other.shape != v.spec.shape || other.twoLevels != v.spec.twoLevels ||
          other.checkpoint != v.spec.checkpoint || other.output() != v.spec.output())
        throw InputError(path, "the law's variable '" + name +
                                   "' differs from the one of material '" + owner->second + "'");
    }
}

template <int Dim>
void initializeMaterials(ParticleSet<Dim>& particles, const Materials<Dim>& materials,
                         bool freshStart) {
  particles.indexMaterials(static_cast<int>(materials.size()));
  for (std::size_t m = 0; m < materials.size(); ++m) {
    const auto at = evaluationOf(particles, materials, static_cast<int>(m), particles.F);
    if (freshStart) {
      const auto variables = materials[m]->variables();
      for (std::size_t k = 0; k < variables.size(); ++k) {
        if (variables[k].initial.empty())
          continue;
        auto values = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), at.variables[k]);
        auto members = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), at.members);
        for (std::size_t i = 0; i < members.extent(0); ++i)
          for (std::size_t c = 0; c < values.extent(1); ++c)
            values(members(i), c) = variables[k].initial.at(c);
        Kokkos::deep_copy(at.variables[k], values);
      }
    }
    materials[m]->initialize(at);
  }
}

template <int Dim>
TrialState<Dim>::TrialState(const ParticleSet<Dim>& particles, const Materials<Dim>& materials) {
  std::map<std::string, Table> tables;
  for (const auto& m : materials) {
    perMaterial_.emplace_back();
    for (const auto& v : m->variables()) {
      if (!v.spec.twoLevels)
        continue;
      auto it = tables.find(v.spec.name);
      if (it == tables.end()) {
        const Table& n = particles.values(v.spec.name);
        it = tables.emplace(v.spec.name, Table(v.spec.name + " (trial)", n.extent(0), n.extent(1)))
                 .first;
      }
      perMaterial_.back().push_back(it->second);
    }
  }
}

template <int Dim>
typename Material<Dim>::Evaluation evaluationOf(
    const ParticleSet<Dim>& particles, const Materials<Dim>& materials, int m,
    const typename ParticleSet<Dim>::Tensors& F,
    const std::vector<typename ParticleSet<Dim>::Table>& trial) {
  typename Material<Dim>::Evaluation at{particles, particles.membersOf(m), F, {}, trial};
  for (const auto& v : materials[m]->variables())
    at.variables.push_back(particles.values(v.spec.name));
  return at;
}

template <int Dim>
void commitMaterialState(const ParticleSet<Dim>& particles, const Materials<Dim>& materials,
                         const TrialState<Dim>& trial) {
  for (std::size_t m = 0; m < materials.size(); ++m) {
    const int k = static_cast<int>(m);
    materials[m]->commit(evaluationOf(particles, materials, k, particles.F, trial.of(k)));
  }
}

template <int Dim>
double maxModulus(const ParticleSet<Dim>& particles, const Materials<Dim>& materials, int m,
                  const Comm& comm, Modulus which) {
  const auto at = evaluationOf(particles, materials, m, particles.F);
  const double local =
      which == Modulus::young ? materials[m]->youngModulus(at) : materials[m]->maxModulus(at);
  double global = 0.0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, local, Teuchos::outArg(global));
  return global;
}

#define IMPM_INSTANTIATE(D)                                                                    \
  template void declareMaterialVariables<D>(ParticleSet<D>&, const Materials<D>&);             \
  template void initializeMaterials<D>(ParticleSet<D>&, const Materials<D>&, bool);            \
  template class TrialState<D>;                                                                \
  template Material<D>::Evaluation evaluationOf<D>(const ParticleSet<D>&, const Materials<D>&, \
                                                   int, const ParticleSet<D>::Tensors&,        \
                                                   const std::vector<ParticleSet<D>::Table>&); \
  template void commitMaterialState<D>(const ParticleSet<D>&, const Materials<D>&,             \
                                       const TrialState<D>&);                                  \
  template double maxModulus<D>(const ParticleSet<D>&, const Materials<D>&, int, const Comm&,  \
                                Modulus);
IMPM_INSTANTIATE(1)
IMPM_INSTANTIATE(2)
IMPM_INSTANTIATE(3)
#undef IMPM_INSTANTIATE

}  // namespace impm

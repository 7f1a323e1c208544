#pragma once
// The framework's side of the material interface: the laws' variables declared in the
// particle set, their initial values, the trial tables of a step, and the Evaluation each
// law is handed.  A law never looks up a field itself.

#include <map>
#include <memory>
#include <vector>

#include "core/TpetraTypes.hpp"
#include "material/Material.hpp"

namespace impm {

template <int Dim>
using Materials = std::vector<std::shared_ptr<Material<Dim>>>;

// Declares every law's variables in `particles`: one field per name, shared by the laws that
// declare it alike.  Throws InputError(Materials/<name>) when two laws declare one name
// differently or a name is taken by a framework field.
template <int Dim>
void declareMaterialVariables(ParticleSet<Dim>& particles, const Materials<Dim>& materials);

// Index lists per material, then (fresh starts only, not restarts) each variable's initial
// values on its law's particles, then each law's initialize().  Throws InputError.
template <int Dim>
void initializeMaterials(ParticleSet<Dim>& particles, const Materials<Dim>& materials,
                         bool freshStart);

// The trial values of the two-level variables during a step: one table per variable name,
// of the particle set's size, written by the laws' evaluations and committed on acceptance.
template <int Dim>
class TrialState {
 public:
  using Table = typename ParticleSet<Dim>::Table;
  TrialState(const ParticleSet<Dim>& particles, const Materials<Dim>& materials);
  // Material m's trial tables, in the order of its two-level variables.
  const std::vector<Table>& of(int m) const { return perMaterial_.at(m); }

 private:
  std::vector<std::vector<Table>> perMaterial_;
};

// The evaluation of material m at deformation gradients F (trial: its trial tables, or none
// when only the committed state is read).
template <int Dim>
typename Material<Dim>::Evaluation evaluationOf(
    const ParticleSet<Dim>& particles, const Materials<Dim>& materials, int m,
    const typename ParticleSet<Dim>::Tensors& F,
    const std::vector<typename ParticleSet<Dim>::Table>& trial = {});

// Every law commits its particles' trial state (an accepted step).
template <int Dim>
void commitMaterialState(const ParticleSet<Dim>& particles, const Materials<Dim>& materials,
                         const TrialState<Dim>& trial);

// Which modulus of a law: the largest small-strain one (wave speeds, constraint scales) or
// Young's (the ghost penalty); Material::maxModulus and Material::youngModulus.
enum class Modulus { largest, young };

// That modulus of material m, the largest over all ranks.  Collective.
template <int Dim>
double maxModulus(const ParticleSet<Dim>& particles, const Materials<Dim>& materials, int m,
                  const Comm& comm, Modulus which = Modulus::largest);

}  // namespace impm

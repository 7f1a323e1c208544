#pragma once
// Helpers for materials whose parameters are formulas of the particle's reference position:
// evaluated once, on the host, into ParticleSet::props, then read by device kernels.

#include <string>

#include "core/Formula.hpp"
#include "core/Parameters.hpp"
#include "core/ParticleSet.hpp"

namespace impm {

// props(p, slot) = f(X_p) for the particles of material `index`; throws InputError(path)
// naming the particle when a value falls outside `bounds`.
template <int Dim>
void fillPropertyFromFormula(ParticleSet<Dim>& particles, int index, int slot, const Formula& f,
                             const std::string& path, Bounds bounds);

// Largest props(p, slot) over the particles of material `index` on this rank.
template <int Dim>
double maxProperty(const ParticleSet<Dim>& particles, int index, int slot);

}  // namespace impm

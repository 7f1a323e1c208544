#pragma once
// Helpers for materials whose parameters are formulas of the particle's reference position:
// evaluated once, on the host, into one of the law's parameter fields, then read by device
// kernels.

#include <string>

#include "core/Formula.hpp"
#include "core/Parameters.hpp"
#include "material/Material.hpp"

namespace impm {

// values(p, 0) = f(X_p) for the particles of the evaluation; throws InputError(path) naming
// the position when a value falls outside `bounds`.
template <int Dim>
void fillPropertyFromFormula(const typename Material<Dim>::Evaluation& at,
                             const typename Material<Dim>::Table& values, const Formula& f,
                             const std::string& path, Bounds bounds);

// Largest values(p, 0) over the particles of the evaluation on this rank (0 when none).
template <int Dim>
double maxProperty(const typename Material<Dim>::Evaluation& at,
                   const typename Material<Dim>::Table& values);

}  // namespace impm

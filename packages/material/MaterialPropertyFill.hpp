#pragma once
// Helpers for materials whose parameters are formulas of the particle's reference position:
// evaluated once, on the host, into one of the law's parameter fields, then read by device
// kernels.

#include <string>

#include "core/Formula.hpp"
#include "core/Parameters.hpp"
#include "material/Material.hpp"

namespace impm {

// A law's parameter fields (one scalar table each, in declaration order), read together by
// device kernels: at(p, k) fills k[j] with parameter j at particle p.
constexpr int kMaxLawParameters = 4;
template <int Dim>
struct ParameterTables {
  Kokkos::Array<typename Material<Dim>::Table, kMaxLawParameters> tables;
  int count = 0;
  // The first `first` tables of t (all of them when first < 0).
  explicit ParameterTables(const std::vector<typename Material<Dim>::Table>& t, int first = -1)
      : count(first < 0 ? static_cast<int>(t.size()) : first) {
    for (int j = 0; j < kMaxLawParameters; ++j)
      tables[j] = t.at(j < count ? j : 0);
  }
  KOKKOS_INLINE_FUNCTION void at(int p, double k[kMaxLawParameters]) const {
    for (int j = 0; j < count; ++j)
      k[j] = tables[j](p, 0);
  }
};

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

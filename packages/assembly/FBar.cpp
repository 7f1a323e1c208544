#include "assembly/FBar.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "assembly/RowAccumulator.hpp"

namespace impm {

FBar parseFBar(const std::string& name) {
  if (name == "none")
    return FBar::none;
  if (name == "cell")
    return FBar::cell;
  throw std::invalid_argument("unknown F-bar '" + name + "' (none, cell)");
}

std::string fbarName(FBar f) {
  return f == FBar::cell ? "cell" : "none";
}

template <int Dim>
void declareFBarFields(ParticleSet<Dim>& particles, FBar fbar, Kinematics kinematics) {
  if (fbar == FBar::none || kinematics != Kinematics::totalLagrangian)
    return;
  FieldSpec spec;
  spec.name = kCompatibleFField;
  spec.shape = FieldShape::tensor;
  spec.doc = "total Lagrangian with F-bar: the deformation gradient before the cell average";
  particles.declare(spec);
  storeCompatibleF<Dim>(particles, particles.F);
}

template <int Dim>
void storeCompatibleF(const ParticleSet<Dim>& particles,
                      const typename ParticleSet<Dim>::Tensors& F) {
  const auto& values = particles.values(kCompatibleFField);
  Kokkos::parallel_for(
      "impm::compatibleF", RangePolicy<DefaultExecSpace>(0, particles.size()),
      KOKKOS_LAMBDA(const int p) {
        for (int a = 0; a < Dim; ++a)
          for (int b = 0; b < Dim; ++b)
            values(p, a * Dim + b) = F(p, a, b);
      });
}

template <int Dim, class Space>
CellGroups<Space> groupByCell(const GridGeometry<Dim>& grid,
                              const typename ParticleSet<Dim, Space>::Vectors& y) {
  auto host = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), y);
  const std::size_t n = host.extent(0);
  std::vector<std::pair<GlobalId, int>> byCell(n);
  for (std::size_t p = 0; p < n; ++p) {
    int idx[Dim];
    for (int d = 0; d < Dim; ++d)
      idx[d] = grid.cellAlong(d, host(p, d));
    byCell[p] = {grid.cellId(idx), static_cast<int>(p)};
  }
  std::stable_sort(byCell.begin(), byCell.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  CellGroups<Space> out;
  std::vector<std::size_t> first;
  Kokkos::View<int*, Kokkos::HostSpace> order("F-bar order", n);
  for (std::size_t k = 0; k < n; ++k) {
    if (k == 0 || byCell[k].first != byCell[k - 1].first) {
      first.push_back(k);
      out.cells.push_back(byCell[k].first);
    }
    order(k) = byCell[k].second;
  }
  first.push_back(n);
  Kokkos::View<std::size_t*, Kokkos::HostSpace> start("F-bar groups", first.size());
  std::copy(first.begin(), first.end(), start.data());
  out.order = Kokkos::create_mirror_view_and_copy(typename Space::memory_space(), order);
  out.start = Kokkos::create_mirror_view_and_copy(typename Space::memory_space(), start);
  return out;
}

namespace {

// x^(1/Dim), exact at x = 1.
template <int Dim>
KOKKOS_INLINE_FUNCTION double rootOf(double x) {
  if constexpr (Dim == 1)
    return x;
  else if constexpr (Dim == 2)
    return Kokkos::Experimental::sqrt(x);
  else
    return Kokkos::Experimental::cbrt(x);
}

}  // namespace

template <int Dim, class Space>
void averageDilatation(const CellGroups<Space>& groups, const ParticleSet<Dim, Space>& particles,
                       const typename ParticleSet<Dim, Space>::Tensors& g,
                       const typename ParticleSet<Dim, Space>::Scalars& theta,
                       const typename ParticleSet<Dim, Space>::Scalars& omega) {
  const auto start = groups.start;
  const auto order = groups.order;
  const auto section = particles.section;
  const auto volume = particles.volume;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  Kokkos::parallel_for(
      "impm::averageDilatation", RangePolicy<Space>(0, groups.size()), KOKKOS_LAMBDA(const int c) {
        const std::size_t first = start(c), last = start(c + 1);
        if (last - first == 1) {  // its own average: theta = 1 exactly
          theta(order(first)) = 1.0, omega(order(first)) = 1.0;
          return;
        }
        double sw = 0.0, swj = 0.0;  // in index order: the same bits on any number of ranks
        bool inverted = false;
        for (std::size_t m = first; m < last; ++m) {
          const int q = order(m);
          const double w = section(q) * volume(q), j = determinant<Dim>(g, q);
          inverted = inverted || !(j > 0.0);
          sw += w, swj += w * j;
        }
        const double jbar = swj / sw;
        for (std::size_t m = first; m < last; ++m) {
          const int q = order(m);
          const double j = determinant<Dim>(g, q);
          // An inverted point makes theta NaN: the stress check names it (a cut-back).
          theta(q) = inverted || !(jbar > 0.0) ? nan : rootOf<Dim>(jbar / j);
          omega(q) = section(q) * volume(q) * j / swj;
        }
      });
}

template <int Dim, class Space>
void scaleByTheta(const typename ParticleSet<Dim, Space>::Scalars& theta,
                  const typename ParticleSet<Dim, Space>::Tensors& F) {
  Kokkos::parallel_for(
      "impm::scaleByTheta", RangePolicy<Space>(0, F.extent(0)), KOKKOS_LAMBDA(const int p) {
        for (int a = 0; a < Dim; ++a)
          for (int b = 0; b < Dim; ++b)
            F(p, a, b) *= theta(p);
      });
}

namespace {

// b_c = sum_D ginv_Dc G_D: the change of ln det g per unit du_c of the entry's node.
template <int Dim, class Grad>
KOKKOS_INLINE_FUNCTION void spatialGradient(const double ginv[Dim][Dim], const Grad& grad,
                                            std::size_t k, double b[Dim]) {
  for (int c = 0; c < Dim; ++c) {
    b[c] = 0.0;
    for (int D = 0; D < Dim; ++D)
      b[c] += ginv[D][c] * grad(k, D);
  }
}

template <int Dim, class Tensors>
KOKKOS_INLINE_FUNCTION void inverseOf(const Tensors& g, int p, double ginv[Dim][Dim]) {
  double m[Dim][Dim];
  for (int a = 0; a < Dim; ++a)
    for (int b = 0; b < Dim; ++b)
      m[a][b] = g(p, a, b);
  inverse<Dim>(m, determinant<Dim>(m), ginv);
}

}  // namespace

template <int Dim, class Space>
void addFBarTangent(const ParticleGridMap<Dim, Space>& map, const EntryDofs<Space>& entryDofs,
                    const ParticleSet<Dim, Space>& particles, const CellGroups<Space>& groups,
                    const typename ParticleSet<Dim, Space>::Tensors& g,
                    const typename ParticleSet<Dim, Space>::Scalars& theta,
                    const typename ParticleSet<Dim, Space>::Scalars& omega,
                    const Tangents<Dim, Space>& An, const LocalMatrix& K) {
  const auto start = groups.start;
  const auto order = groups.order;
  const auto rowPtr = map.rowPtr;
  const auto grad = map.grad;
  const auto section = particles.section;
  const auto volume = particles.volume;
  // b_k = g_p^-T G_k for every map entry k, once: each is read by every row of its cell.
  Kokkos::View<double* [Dim], typename Space::memory_space> b(
      Kokkos::ViewAllocateWithoutInitializing("F-bar b"), grad.extent(0));
  Kokkos::parallel_for(
      "impm::fbarSpatialGradients", RangePolicy<Space>(0, map.numParticles()),
      KOKKOS_LAMBDA(const int p) {
        double ginv[Dim][Dim];
        inverseOf<Dim>(g, p, ginv);
        for (std::size_t k = rowPtr(p); k < rowPtr(p + 1); ++k) {
          double bk[Dim];
          spatialGradient<Dim>(ginv, grad, k, bk);
          for (int c = 0; c < Dim; ++c)
            b(k, c) = bk[c];
        }
      });
  Kokkos::parallel_for(
      "impm::fbarTangent", RangePolicy<Space>(0, groups.size()), KOKKOS_LAMBDA(const int c) {
        const std::size_t first = start(c), last = start(c + 1);
        if (last - first == 1)
          return;  // beta = b_p: the coupling vanishes
        for (std::size_t m = first; m < last; ++m) {
          const int p = order(m);
          // AG_aB = sum_cD An_aBcD gbar_cD, gbar = theta g
          double AG[Dim][Dim];
          for (int a = 0; a < Dim; ++a)
            for (int B = 0; B < Dim; ++B) {
              double s = 0.0;
              for (int e = 0; e < Dim; ++e)
                for (int D = 0; D < Dim; ++D)
                  s += An(p, a, B, e, D) * g(p, e, D);
              AG[a][B] = theta(p) * s;
            }
          const double scale = section(p) * volume(p) / Dim;
          for (std::size_t ki = rowPtr(p); ki < rowPtr(p + 1); ++ki) {
            double Q[Dim];
            for (int a = 0; a < Dim; ++a) {
              Q[a] = 0.0;
              for (int B = 0; B < Dim; ++B)
                Q[a] += AG[a][B] * grad(ki, B);
              Q[a] *= scale;
            }
            NodeRowsAccumulator<LocalMatrix, Dim> rows(K, entryDofs(ki));
            const auto addColumns = [&](int q, double weight) {
              for (std::size_t kj = rowPtr(q); kj < rowPtr(q + 1); ++kj)
                for (int col = 0; col < Dim; ++col) {
                  double s[Dim];
                  for (int a = 0; a < Dim; ++a)
                    s[a] = weight * Q[a] * b(kj, col);
                  rows.add(entryDofs(kj) + col, s);
                }
            };
            for (std::size_t n = first; n < last; ++n)
              addColumns(order(n), omega(order(n)));
            addColumns(p, -1.0);
          }
        }
      });
}

#define IMPM_INSTANTIATE(D)                                                                      \
  template void declareFBarFields<D>(ParticleSet<D>&, FBar, Kinematics);                         \
  template void storeCompatibleF<D>(const ParticleSet<D>&, const ParticleSet<D>::Tensors&);      \
  template CellGroups<DefaultExecSpace> groupByCell<D, DefaultExecSpace>(                        \
      const GridGeometry<D>&, const ParticleSet<D>::Vectors&);                                   \
  template void averageDilatation<D, DefaultExecSpace>(                                          \
      const CellGroups<>&, const ParticleSet<D>&, const ParticleSet<D>::Tensors&,                \
      const ParticleSet<D>::Scalars&, const ParticleSet<D>::Scalars&);                           \
  template void scaleByTheta<D, DefaultExecSpace>(const ParticleSet<D>::Scalars&,                \
                                                  const ParticleSet<D>::Tensors&);               \
  template void addFBarTangent<D, DefaultExecSpace>(                                             \
      const ParticleGridMap<D>&, const EntryDofs<>&, const ParticleSet<D>&, const CellGroups<>&, \
      const ParticleSet<D>::Tensors&, const ParticleSet<D>::Scalars&,                            \
      const ParticleSet<D>::Scalars&, const Tangents<D>&, const LocalMatrix&);
IMPM_INSTANTIATE(1)
IMPM_INSTANTIATE(2)
IMPM_INSTANTIATE(3)
#undef IMPM_INSTANTIATE

}  // namespace impm

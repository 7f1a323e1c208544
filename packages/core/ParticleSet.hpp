#pragma once
// The material points.  Every field a particle carries lives here, in one Kokkos view per
// field, indexed by the local particle index p.  Particles carry the whole state of the
// body (primer 1.6.2): positions, velocity, deformation gradient, stress, volume, mass, the
// particle domain and the state of its material; the grid carries nothing between steps.
//
// The fields form a registry.  The framework's own (below) are typed members that kernels
// capture by name; further fields (a material's plastic strain, damage, ...) are declared at
// run time with declare() and stored as (particle, component) tables.  Each field is
// described once by a FieldSpec, and resizing, migration, output and checkpoints walk the
// registry through forEachField, so a new field needs no code in any of them.
//
// In 1-D, `volume` is the particle length (the primer's V_p) and `section` the bar's cross
// section A(x_p), so that the particle's true volume is section * volume.  In 2-D, `volume`
// is the area and `section` the out-of-plane thickness (1: plane strain, per unit depth).

#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/FieldSpec.hpp"
#include "core/Tensor.hpp"
#include "core/Types.hpp"

namespace impm {

template <int Dim, class Space = DefaultExecSpace>
class ParticleSet {
 public:
  using memory_space = typename Space::memory_space;
  using Ids = Kokkos::View<GlobalId*, memory_space>;
  using Indices = Kokkos::View<int*, memory_space>;
  using Scalars = Kokkos::View<double*, memory_space>;
  using Vectors = Kokkos::View<double* [Dim], memory_space>;
  using Tensors = Kokkos::View<double* [Dim][Dim], memory_space>;
  // A declared field: values(p, component).
  using Table = Kokkos::View<double**, Kokkos::LayoutRight, memory_space>;

  // The framework's fields, in the order of the particle tables' columns.
  Ids id;            // global, stable, used to sort output
  Vectors X;         // reference position X_p
  Vectors x;         // current position x_p
  Vectors u;         // displacement u_p (eq. 1.23 maps it from the grid)
  Scalars strain;    // 1-D engineering strain F - 1 (derived, for output)
  Tensors stress;    // Cauchy stress (1-D: axial force per unit section)
  Scalars stressZZ;  // 2-D plane strain: out-of-plane Cauchy stress (derived, for output)
  Scalars J;         // det F (derived, for output)
  Scalars volume;    // current V_p
  Vectors v;         // velocity
  Vectors a;         // acceleration
  Tensors F;         // deformation gradient
  Scalars mass;
  Scalars section;   // 1-D cross-section A(x_p); 2-D thickness
  Indices body;      // index of the body in the deck
  Tensors domain;    // particle domain: column k is the half-vector r_k (1-D: half length)
  Tensors domain0;   // reference particle domain
  Indices material;  // index of the material in the deck
  Vectors force;     // external force on the particle (body force times its volume)
  Scalars volume0;   // reference V_p

  ParticleSet() = default;
  explicit ParticleSet(std::size_t n) { resize(n); }

  std::size_t size() const { return id.extent(0); }

  // f(spec, view) for every stored field, the framework's first, then the declared ones.
  template <class Fn>
  void forEachField(Fn&& f) {
    visit(*this, *this, [&](const FieldSpec& spec, auto& view, auto&) { f(spec, view); });
  }
  template <class Fn>
  void forEachField(Fn&& f) const {
    visit(*this, *this, [&](const FieldSpec& spec, auto& view, auto&) { f(spec, view); });
  }

  // The same fields and values in another memory space (the host's, to fill or read
  // fields one particle at a time), and the copy back.  Where the spaces are the same the
  // mirror shares this set's views, as Kokkos' mirrors do: no copy is made.
  template <class OtherSpace>
  ParticleSet<Dim, OtherSpace> mirror(const OtherSpace& = OtherSpace()) const;
  template <class OtherSpace>
  void copyFrom(const ParticleSet<Dim, OtherSpace>& other);

  // Keeps existing entries; new entries are zero (declared fields: their initial values).
  void resize(std::size_t n);

  // Adds a field of `initial` values (one per component; empty: zeros).  Throws
  // std::invalid_argument when a field of that name exists or the name is not a field name.
  void declare(const FieldSpec& spec, const std::vector<double>& initial = {});
  bool has(const std::string& name) const;
  const FieldSpec& spec(const std::string& name) const;
  // The values of a declared field.
  const Table& values(const std::string& name) const;
  // Makes the declared field `name` of this set show `values` (of the same shape): a shallow
  // copy of a set seen in another configuration (the reference corners for the map of
  // total-Lagrangian kinematics).
  void replaceValues(const std::string& name, const Table& values);
  // Every field's specification, in registry order.
  std::vector<FieldSpec> specs() const;

  // Fields computed from others for output: J and the 1-D strain from F, then the rules
  // added (a material's sigma_zz), in order.
  void addDerivation(std::function<void(ParticleSet&)> rule) { derivations_.push_back(rule); }
  // The values someone holds back from the fields and how they deliver them (null: no one):
  // the motion of explicit steps on a fixed grid, which waits on the grid for a reader
  // (solver/DynamicStepper.hpp).
  void setCatchUp(std::function<void()> catchUp) { catchUp_ = std::move(catchUp); }
  // Every reader of the fields between steps (outputs, checkpoints, the verification) calls
  // this first: the values held back, then the derived fields.  Collective when a catch-up
  // is set (it checks the delivered values on every rank).
  void bringUpToDate();

  // The particles of each material (index lists into the fields), rebuilt from `material`
  // when materials are assigned and after every migration.
  void indexMaterials(int numMaterials);
  const Indices& membersOf(int m) const { return members_.at(m); }
  int numMaterials() const { return static_cast<int>(members_.size()); }

 private:
  struct Declared {
    FieldSpec spec;
    std::vector<double> initial;
    Table values;
  };

  // The one list of the framework's fields, with their specifications (ParticleFields.cpp):
  // f(spec, field of s, same field of t) for every field of two sets with the same registry.
  template <class S, class T, class Fn>
  static void visit(S& s, T& t, Fn&& f);

  template <int, class>
  friend class ParticleSet;

  std::vector<Declared> declared_;
  std::vector<Indices> members_;
  std::vector<std::function<void(ParticleSet&)>> derivations_;
  std::function<void()> catchUp_;
};

// A new field view of n particles shaped like `view` (the same components), zeroed; or, for
// a view every row of which the caller writes at once, left as the allocator gives it
// (Initialize::no: the zeroing would be a pass over the field for nothing).
enum class Initialize { zero, no };
template <class View>
View allocateField(const std::string& label, const View& like, std::size_t n,
                   Initialize initialize = Initialize::zero) {
  const auto make = [&](const auto& alloc) {
    if constexpr (View::rank_dynamic == 2)  // a declared table: (particle, component)
      return View(alloc, n, like.extent(1));
    else
      return View(alloc, n);
  };
  return initialize == Initialize::zero
             ? make(Kokkos::view_alloc(label))
             : make(Kokkos::view_alloc(label, Kokkos::WithoutInitializing));
}

// Component c of particle p of a field, as a double (host views: output and checkpoints).
// Tensors are row-major: component a * Dim + b.
template <class View>
double fieldComponent(const View& view, std::size_t p, int c) {
  if constexpr (View::rank == 1)
    return static_cast<double>(view(p));
  else if constexpr (View::rank == 2)
    return view(p, c);
  else
    return view(p, c / view.extent(2), c % view.extent(2));
}
template <class View>
void setFieldComponent(const View& view, std::size_t p, int c, double value) {
  using Value = typename View::non_const_value_type;
  if constexpr (View::rank == 1)
    view(p) = static_cast<Value>(value);
  else if constexpr (View::rank == 2)
    view(p, c) = value;
  else
    view(p, c / view.extent(2), c % view.extent(2)) = value;
}
// Values per particle of a field.
template <class View>
int fieldWidth(const View& view) {
  int width = 1;
  for (unsigned r = 1; r < View::rank; ++r)
    width *= static_cast<int>(view.extent(r));
  return width;
}

// The specifications of the framework's fields in Dim dimensions.
template <int Dim>
struct BuiltinFields {
  BuiltinFields();
  FieldSpec id, X, x, u, strain, stress, stressZZ, J, volume, v, a, F, mass, section, body, domain,
      domain0, material, force, volume0;
};
template <int Dim>
const BuiltinFields<Dim>& builtinFields();

template <int Dim, class Space>
template <class S, class T, class Fn>
void ParticleSet<Dim, Space>::visit(S& s, T& t, Fn&& f) {
  const BuiltinFields<Dim>& b = builtinFields<Dim>();
  f(b.id, s.id, t.id), f(b.X, s.X, t.X), f(b.x, s.x, t.x), f(b.u, s.u, t.u);
  f(b.strain, s.strain, t.strain), f(b.stress, s.stress, t.stress);
  f(b.stressZZ, s.stressZZ, t.stressZZ), f(b.J, s.J, t.J), f(b.volume, s.volume, t.volume);
  f(b.v, s.v, t.v), f(b.a, s.a, t.a), f(b.F, s.F, t.F), f(b.mass, s.mass, t.mass);
  f(b.section, s.section, t.section), f(b.body, s.body, t.body);
  f(b.domain, s.domain, t.domain), f(b.domain0, s.domain0, t.domain0);
  f(b.material, s.material, t.material), f(b.force, s.force, t.force);
  f(b.volume0, s.volume0, t.volume0);
  for (std::size_t k = 0; k < s.declared_.size(); ++k)
    f(s.declared_[k].spec, s.declared_[k].values, t.declared_[k].values);
}

template <int Dim, class Space>
void ParticleSet<Dim, Space>::resize(std::size_t n) {
  const std::size_t old = size();
  forEachField([n](const FieldSpec& spec, auto& view) {
    using V = std::decay_t<decltype(view)>;
    if (view.data() == nullptr)
      view = allocateField(spec.name, view, n);
    else if constexpr (V::rank_dynamic == 2)
      Kokkos::resize(view, n, view.extent(1));
    else
      Kokkos::resize(view, n);
  });
  for (auto& d : declared_)
    if (n > old && !d.initial.empty()) {
      auto rows = Kokkos::subview(d.values, Kokkos::make_pair(old, n), Kokkos::ALL());
      auto host = Kokkos::create_mirror_view(rows);
      for (std::size_t p = 0; p < rows.extent(0); ++p)
        for (std::size_t c = 0; c < rows.extent(1); ++c)
          host(p, c) = d.initial[c];
      Kokkos::deep_copy(rows, host);
    }
}

template <int Dim, class Space>
void ParticleSet<Dim, Space>::declare(const FieldSpec& spec, const std::vector<double>& initial) {
  if (!isFieldName(spec.name))
    throw std::invalid_argument("'" + spec.name +
                                "' is not a field name (a letter, then letters, digits or _)");
  if (has(spec.name))
    throw std::invalid_argument("the particle field '" + spec.name + "' is declared twice");
  const int n = componentCount<Dim>(spec.shape);
  if (!initial.empty() && static_cast<int>(initial.size()) != n)
    throw std::invalid_argument("the particle field '" + spec.name + "' has " + std::to_string(n) +
                                " components but " + std::to_string(initial.size()) +
                                " initial values");
  Declared d{spec, initial, Table(spec.name, 0, n)};
  declared_.push_back(d);
  const std::size_t count = size();
  Kokkos::resize(declared_.back().values, count, n);
  if (!initial.empty()) {
    auto host = Kokkos::create_mirror_view(declared_.back().values);
    for (std::size_t p = 0; p < count; ++p)
      for (int c = 0; c < n; ++c)
        host(p, c) = initial[c];
    Kokkos::deep_copy(declared_.back().values, host);
  }
}

template <int Dim, class Space>
bool ParticleSet<Dim, Space>::has(const std::string& name) const {
  bool found = false;
  forEachField([&](const FieldSpec& spec, const auto&) { found = found || spec.name == name; });
  return found;
}

template <int Dim, class Space>
const FieldSpec& ParticleSet<Dim, Space>::spec(const std::string& name) const {
  const FieldSpec* found = nullptr;
  forEachField([&](const FieldSpec& spec, const auto&) {
    if (spec.name == name)
      found = &spec;
  });
  if (!found)
    throw std::out_of_range("no particle field '" + name + "'");
  return *found;
}

template <int Dim, class Space>
const typename ParticleSet<Dim, Space>::Table& ParticleSet<Dim, Space>::values(
    const std::string& name) const {
  for (const auto& d : declared_)
    if (d.spec.name == name)
      return d.values;
  throw std::out_of_range("no declared particle field '" + name + "'");
}

template <int Dim, class Space>
void ParticleSet<Dim, Space>::replaceValues(const std::string& name, const Table& values) {
  for (auto& d : declared_)
    if (d.spec.name == name) {
      if (values.extent(0) != d.values.extent(0) || values.extent(1) != d.values.extent(1))
        throw std::logic_error("replaceValues: '" + name + "' of another shape");
      d.values = values;
      return;
    }
  throw std::out_of_range("no declared particle field '" + name + "'");
}

template <int Dim, class Space>
std::vector<FieldSpec> ParticleSet<Dim, Space>::specs() const {
  std::vector<FieldSpec> out;
  forEachField([&](const FieldSpec& spec, const auto&) { out.push_back(spec); });
  return out;
}

template <int Dim, class Space>
template <class OtherSpace>
ParticleSet<Dim, OtherSpace> ParticleSet<Dim, Space>::mirror(const OtherSpace&) const {
  ParticleSet<Dim, OtherSpace> out;
  for (const auto& d : declared_)
    out.declared_.push_back({d.spec, d.initial, {}});
  visit(out, *this, [](const FieldSpec&, auto& mine, const auto& theirs) {
    mine = Kokkos::create_mirror_view_and_copy(typename OtherSpace::memory_space(), theirs);
  });
  out.members_.clear();
  out.derivations_.clear();
  return out;
}

template <int Dim, class Space>
template <class OtherSpace>
void ParticleSet<Dim, Space>::copyFrom(const ParticleSet<Dim, OtherSpace>& other) {
  if (other.declared_.size() != declared_.size())
    throw std::logic_error("copying between particle sets of different fields");
  visit(*this, other, [](const FieldSpec& spec, auto& mine, const auto& theirs) {
    using V = std::decay_t<decltype(mine)>;
    if (mine.extent(0) != theirs.extent(0) || mine.data() == nullptr) {
      if constexpr (V::rank_dynamic == 2)
        mine = V(spec.name, theirs.extent(0), theirs.extent(1));
      else
        mine = V(spec.name, theirs.extent(0));
    }
    Kokkos::deep_copy(mine, theirs);
  });
}

template <int Dim, class Space>
void ParticleSet<Dim, Space>::bringUpToDate() {
  if (catchUp_)
    catchUp_();
  auto Fp = F;
  auto Jp = J;
  auto strainp = strain;
  Kokkos::parallel_for(
      "impm::derivedFields", RangePolicy<Space>(0, size()), KOKKOS_LAMBDA(const int p) {
        Jp(p) = determinant<Dim>(Fp, p);
        strainp(p) = Fp(p, 0, 0) - 1.0;
      });
  for (const auto& rule : derivations_)
    rule(*this);
}

template <int Dim, class Space>
void ParticleSet<Dim, Space>::indexMaterials(int numMaterials) {
  auto m = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), material);
  std::vector<std::vector<int>> lists(numMaterials);
  for (std::size_t p = 0; p < size(); ++p) {
    if (m(p) < 0 || m(p) >= numMaterials)
      throw std::logic_error("particle with material index " + std::to_string(m(p)));
    lists[m(p)].push_back(static_cast<int>(p));
  }
  members_.clear();
  for (int k = 0; k < numMaterials; ++k) {
    Indices list("material members", lists[k].size());
    auto host = Kokkos::create_mirror_view(list);
    for (std::size_t i = 0; i < lists[k].size(); ++i)
      host(i) = lists[k][i];
    Kokkos::deep_copy(list, host);
    members_.push_back(list);
  }
}

}  // namespace impm

#include "bc/DirichletNodes.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/Axes.hpp"
#include "core/Collective.hpp"
#include "core/Errors.hpp"
#include "core/Parameters.hpp"

namespace impm {

template <int Dim>
Teuchos::ParameterList DirichletNodes<Dim>::validParameters() {
  Teuchos::ParameterList valid;
  declareChoice(valid, "Face", "left", {"left", "right", "bottom", "top", "back", "front", "box"},
                "The grid nodes held: those on a face of the grid (left: x = min, right: x = "
                "max, bottom: y = min, top: y = max, back: z = min, front: z = max), or those "
                "inside Box",
                true);
  declareDoubleArray(valid, "Box", {0.0, 0.0, 0.0, 0.0}, {2, 4, 6},
                     "With Face = box: xmin, xmax (1-D), then ymin, ymax (2-D), then zmin, zmax "
                     "(3-D); nodes on its faces are inside");
  declareChoice(valid, "Component", "x", axisNames<3>(), "The displacement component held", true);
  declareFormula(valid, "Value", "0", anyPointTimeVariables(),
                 "Prescribed displacement g(x, y, t) (3-D: g(x, y, z, t)) at the node position "
                 "(0: a roller or clamp); ramped with the load factor in static load steps");
  return valid;
}

template <int Dim>
DirichletNodes<Dim>::DirichletNodes(const std::string& name, const Teuchos::ParameterList& params,
                                    const GridGeometry<Dim>& grid, double initialLoadFactor)
    : name_(name), grid_(grid), committedLoad_(initialLoadFactor) {
  const std::string path = "Boundary Conditions/" + name + "/";
  const auto names = axisNames<3>();
  component_ = static_cast<int>(
      std::find(names.begin(), names.end(), params.get<std::string>("Component")) - names.begin());
  if (component_ >= Dim)
    throw InputError(path + "Component", "a " + std::to_string(Dim) + "-D grid has no " +
                                             names[component_] + " component");
  try {
    value_ = Formula(formulaText(params, "Value"), pointTimeVariables<Dim>());
  } catch (const InputError& e) {
    throw InputError(path + "Value", e.what());
  }
  for (int d = 0; d < Dim; ++d)
    lo_[d] = 0, hi_[d] = grid.cells[d];
  const auto& face = params.get<std::string>("Face");
  if (face == "box") {
    const auto& box = params.get<Teuchos::Array<double>>("Box");
    if (static_cast<int>(box.size()) != 2 * Dim)
      throw InputError(path + "Box", "needs " + std::to_string(2 * Dim) + " numbers on a " +
                                         std::to_string(Dim) + "-D grid");
    for (int d = 0; d < Dim; ++d) {
      const double tol = 1e-9;
      lo_[d] = std::max(0, static_cast<int>(std::ceil(grid.gridCoord(d, box[2 * d]) - tol)));
      hi_[d] = std::min(grid.cells[d],
                        static_cast<int>(std::floor(grid.gridCoord(d, box[2 * d + 1]) + tol)));
      if (lo_[d] > hi_[d])
        throw InputError(path + "Box", "holds no grid node");
    }
    return;
  }
  const std::array<std::string, 6> faces = {"left", "right", "bottom", "top", "back", "front"};
  const int f = static_cast<int>(std::find(faces.begin(), faces.end(), face) - faces.begin());
  const int d = f / 2;
  if (d >= Dim)
    throw InputError(path + "Face", "a " + std::to_string(Dim) + "-D grid has no " + face +
                                        " face (its faces are left, right" +
                                        (Dim > 1 ? ", bottom, top" : "") + ")");
  if (f % 2 == 0)
    hi_[d] = 0;
  else
    lo_[d] = grid.cells[d];
}

template <int Dim>
bool DirichletNodes<Dim>::selects(const int idx[Dim]) const {
  for (int d = 0; d < Dim; ++d)
    if (idx[d] < lo_[d] || idx[d] > hi_[d])
      return false;
  return true;
}

template <int Dim>
double DirichletNodes<Dim>::prescribed(const double* x, double time, double loadFactor) const {
  std::array<double, Dim + 1> at;  // x, (y, z,) t
  std::copy(x, x + Dim, at.begin());
  at[Dim] = time;
  return loadFactor * value_(at);
}

template <int Dim>
double DirichletNodes<Dim>::increment(const ContributionContext<Dim>& ctx, GlobalId node) const {
  int idx[Dim];
  grid_.nodeIndex(node, idx);
  double x[Dim];
  for (int d = 0; d < Dim; ++d)
    x[d] = grid_.nodeCoord(d, idx[d]);
  return prescribed(x, ctx.time, ctx.loadFactor) - prescribed(x, committedTime_, committedLoad_);
}

template <int Dim>
void DirichletNodes<Dim>::constraints(const ContributionContext<Dim>& ctx,
                                      std::vector<std::pair<GO, double>>& out) const {
  for (const GlobalId node : ctx.dofs.ownedActiveNodes()) {
    int idx[Dim];
    grid_.nodeIndex(node, idx);
    if (selects(idx))
      out.emplace_back(ctx.dofs.nodeDof(node, component_), increment(ctx, node));
  }
}

template <int Dim>
double DirichletNodes<Dim>::reaction(const ContributionContext<Dim>& ctx, const HostValues& r) {
  const auto& owned = *ctx.dofs.ownedMap();
  std::vector<double> local;  // (node key, reaction, increment) of the nodes this rank owns
  for (const GlobalId node : ctx.dofs.ownedActiveNodes()) {
    int idx[Dim];
    grid_.nodeIndex(node, idx);
    if (!selects(idx))
      continue;
    const LO row = owned.getLocalElement(ctx.dofs.nodeDof(node, component_));
    local.insert(local.end(),
                 {static_cast<double>(node * Dim + component_), r(row, 0), increment(ctx, node)});
  }
  // Every rank sums every node in the same (key) order: the work does not depend on the
  // number of ranks beyond the reactions' own round-off.
  const auto all = gatherToAll(*owned.getComm(), local);
  std::vector<std::array<double, 3>> nodes(all.size() / 3);
  for (std::size_t k = 0; k < nodes.size(); ++k)
    nodes[k] = {all[3 * k], all[3 * k + 1], all[3 * k + 2]};
  std::sort(nodes.begin(), nodes.end());
  double total = 0.0, work = 0.0;
  pendingForces_.clear();
  auto before = forces_.begin();
  for (const auto& [key, force, du] : nodes) {
    while (before != forces_.end() && before->first < key)
      ++before;
    const double previous = before != forces_.end() && before->first == key ? before->second : 0.0;
    total += force;
    work += 0.5 * (previous + force) * du;
    pendingForces_.emplace_back(key, force);
  }
  pendingWork_ = work_ + work;
  pending_ = true;
  return total;
}

template <int Dim>
void DirichletNodes<Dim>::commit(const ContributionContext<Dim>& ctx, const HostValues& /*x*/) {
  committedTime_ = ctx.time;
  committedLoad_ = ctx.loadFactor;
  if (pending_) {
    forces_.swap(pendingForces_);
    work_ = pendingWork_;
    pending_ = false;
  }
}

template <int Dim>
std::vector<double> DirichletNodes<Dim>::state() const {
  std::vector<double> state{committedTime_, committedLoad_, work_};
  for (const auto& [key, force] : forces_)
    state.insert(state.end(), {key, force});
  return state;
}

template <int Dim>
void DirichletNodes<Dim>::restore(const std::vector<double>& state) {
  if (state.size() < 3 || state.size() % 2 == 0)
    throw std::invalid_argument("a Dirichlet condition's state has 3 + 2n values, not " +
                                std::to_string(state.size()));
  committedTime_ = state[0], committedLoad_ = state[1], work_ = state[2];
  forces_.clear();
  for (std::size_t k = 3; k < state.size(); k += 2)
    forces_.emplace_back(state[k], state[k + 1]);
  pending_ = false;
}

template class DirichletNodes<1>;
template class DirichletNodes<2>;
template class DirichletNodes<3>;

}  // namespace impm

#include "app/Output.hpp"

#include <filesystem>

#include "core/Errors.hpp"
#include "core/Parameters.hpp"

namespace impm {

Teuchos::ParameterList outputValidParameters() {
  Teuchos::ParameterList valid;
  declareString(valid, "Directory", "output",
                "Directory for the output files, created if missing (--output-dir overrides)");
  declareString(valid, "Prefix", "", "File name prefix (empty: the deck file's name)");
  declareInt(valid, "Every", 1, "Write the fields every this many steps (and at the last step)",
             Bounds::atLeast(1));
  declareBool(valid, "Exodus", true, "Write Exodus files of the grid and the particles");
  declareBool(valid, "CSV", true, "Write the particle table as CSV");
  declareBool(valid, "Timers", false,
              "Print the wall-clock time of each phase (map, graph, residual, Jacobian, Newton "
              "solve, particle update, output) at the end, over all ranks");
  return valid;
}

const std::vector<double>& ParticleTable::column(const std::string& name) const {
  for (std::size_t c = 0; c < names.size(); ++c)
    if (names[c] == name)
      return columns[c];
  throw std::logic_error("no particle column " + name);
}

namespace {

// The columns of the particle table, and how to read each from particle p.
template <int Dim>
std::vector<std::string> particleColumns() {
  static_assert(Dim == 1, "2-D output is not implemented yet");
  return {"id", "X", "x", "u", "strain", "stress", "volume", "mass", "section", "body"};
}

template <int Dim>
std::vector<double> particleRow(const ParticleSet<Dim>& ps, std::size_t p,
                                const typename ParticleSet<Dim>::Vectors::HostMirror& X,
                                const typename ParticleSet<Dim>::Vectors::HostMirror& x,
                                const typename ParticleSet<Dim>::Vectors::HostMirror& u,
                                const typename ParticleSet<Dim>::Tensors::HostMirror& F,
                                const typename ParticleSet<Dim>::Tensors::HostMirror& stress,
                                const typename ParticleSet<Dim>::Scalars::HostMirror& volume,
                                const typename ParticleSet<Dim>::Scalars::HostMirror& mass,
                                const typename ParticleSet<Dim>::Scalars::HostMirror& section,
                                const Kokkos::View<int*>::HostMirror& body,
                                const Kokkos::View<GlobalId*>::HostMirror& id) {
  (void)ps;
  return {double(id(p)),   X(p, 0),   x(p, 0), u(p, 0),    F(p, 0, 0) - 1.0,
          stress(p, 0, 0), volume(p), mass(p), section(p), double(body(p))};
}

// A map with every index 0..n-1 on rank 0 and nothing elsewhere.
Teuchos::RCP<const Map> rootMap(GlobalId n, const Teuchos::RCP<const Comm>& comm) {
  const std::size_t local = comm->getRank() == 0 ? static_cast<std::size_t>(n) : 0;
  return Teuchos::rcp(new Map(static_cast<Tpetra::global_size_t>(n), local, 0, comm));
}

std::vector<std::vector<double>> columnsOf(const MultiVector& mv) {
  std::vector<std::vector<double>> out(mv.getNumVectors());
  for (std::size_t c = 0; c < mv.getNumVectors(); ++c) {
    auto data = mv.getData(c);
    out[c].assign(data.begin(), data.end());
  }
  return out;
}

}  // namespace

template <int Dim>
ParticleTable gatherParticles(const ParticleSet<Dim>& ps, const Teuchos::RCP<const Comm>& comm,
                              GlobalId totalParticles) {
  ParticleTable table;
  table.names = particleColumns<Dim>();
  const std::size_t n = ps.size(), ncol = table.names.size();
  auto id = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), ps.id);
  auto X = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), ps.X);
  auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), ps.x);
  auto u = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), ps.u);
  auto F = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), ps.F);
  auto stress = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), ps.stress);
  auto volume = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), ps.volume);
  auto mass = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), ps.mass);
  auto section = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), ps.section);
  auto body = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), ps.body);

  std::vector<GO> gids(id.data(), id.data() + n);
  auto source = Teuchos::rcp(new Map(static_cast<Tpetra::global_size_t>(totalParticles),
                                     Teuchos::ArrayView<const GO>(gids), 0, comm));
  MultiVector local(source, ncol);
  for (std::size_t p = 0; p < n; ++p) {
    const auto row = particleRow<Dim>(ps, p, X, x, u, F, stress, volume, mass, section, body, id);
    for (std::size_t c = 0; c < ncol; ++c)
      local.replaceLocalValue(static_cast<LO>(p), c, row[c]);
  }
  auto target = rootMap(totalParticles, comm);
  MultiVector gathered(target, ncol);
  gathered.doImport(local, Import(source, target), Tpetra::INSERT);
  table.columns = columnsOf(gathered);
  return table;
}

template <int Dim>
Output<Dim>::Output(const Teuchos::ParameterList& params, const std::string& directory,
                    const std::string& prefix, const NodeOwnership<Dim>& ownership,
                    const ParticleSet<Dim>& particles, GlobalId totalParticles,
                    const std::vector<std::string>& historyColumns,
                    const std::vector<std::string>& globalNames)
    : ownership_(ownership),
      root_(ownership.comm()->getRank() == 0),
      every_(params.get<int>("Every")),
      exodus_(params.get<bool>("Exodus")),
      csv_(params.get<bool>("CSV")),
      totalParticles_(totalParticles),
      directory_(directory),
      prefix_(prefix) {
  const auto table = gatherParticles(particles, ownership.comm(), totalParticles);
  if (!root_)
    return;
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error)
    throw std::runtime_error("cannot create the output directory " + directory);
  const std::string base = directory + "/" + prefix;
  history_ = std::make_unique<CsvHistory>(base + "_history.csv", historyColumns);
  if (!exodus_)
    return;

  const auto& g = ownership.grid();
  ExodusMesh grid;
  grid.dimension = Dim;
  grid.coords.resize(Dim);
  for (GlobalId node = 0; node < g.numNodes(); ++node) {
    int idx[Dim];
    g.nodeIndex(node, idx);
    for (int d = 0; d < Dim; ++d)
      grid.coords[d].push_back(g.nodeCoord(d, idx[d]));
  }
  grid.elementType = "BAR2";
  grid.nodesPerElement = 2;
  for (int c = 0; c < g.cells[0]; ++c)
    grid.connectivity.push_back(c + 1), grid.connectivity.push_back(c + 2);
  gridFile_ = std::make_unique<ExodusFile>(base + "_grid.exo", "impm grid", grid,
                                           std::vector<std::string>{"displacementX"},
                                           std::vector<std::string>{}, globalNames);

  ExodusMesh points;
  points.dimension = Dim;
  points.coords = {table.column("X")};
  points.elementType = "SPHERE";
  points.nodesPerElement = 1;
  for (GlobalId p = 0; p < totalParticles; ++p) {
    points.connectivity.push_back(static_cast<int>(p + 1));
    points.elementIds.push_back(static_cast<int>(p + 1));
  }
  std::vector<std::string> elementVariables;
  for (const auto& name : table.names)
    if (name != "id" && name != "X" && name != "x" && name != "u")
      elementVariables.push_back(name);
  particleFile_ = std::make_unique<ExodusFile>(base + "_particles.exo", "impm particles", points,
                                               std::vector<std::string>{"displacementX"},
                                               elementVariables, globalNames);
}

template <int Dim>
void Output<Dim>::writeFields(double time, const ParticleSet<Dim>& particles,
                              const MultiVector& gridDisplacement,
                              const std::vector<double>& globals) {
  const auto table = gatherParticles(particles, ownership_.comm(), totalParticles_);
  const auto nodes = rootMap(ownership_.grid().numNodes(), ownership_.comm());
  MultiVector gridOnRoot(nodes, Dim);
  gridOnRoot.doImport(gridDisplacement, Import(gridDisplacement.getMap(), nodes), Tpetra::INSERT);
  if (!root_)
    return;
  if (csv_)
    writeCsvTable(directory_ + "/" + prefix_ + "_particles.csv", table.names, table.columns);
  if (!exodus_)
    return;
  gridFile_->append(time, columnsOf(gridOnRoot), {}, globals);
  std::vector<std::vector<double>> elementValues;
  for (std::size_t c = 0; c < table.names.size(); ++c) {
    const auto& name = table.names[c];
    if (name != "id" && name != "X" && name != "x" && name != "u")
      elementValues.push_back(table.columns[c]);
  }
  particleFile_->append(time, {table.column("u")}, elementValues, globals);
}

template <int Dim>
void Output<Dim>::appendHistory(const std::vector<double>& row) const {
  if (root_)
    history_->append(row);
}

template <int Dim>
std::vector<std::string> Output<Dim>::files() const {
  const std::string base = directory_ + "/" + prefix_;
  std::vector<std::string> out = {base + "_history.csv"};
  if (csv_)
    out.push_back(base + "_particles.csv");
  if (exodus_)
    out.push_back(base + "_grid.exo"), out.push_back(base + "_particles.exo");
  return out;
}

template ParticleTable gatherParticles<1>(const ParticleSet<1>&, const Teuchos::RCP<const Comm>&,
                                          GlobalId);
template class Output<1>;

}  // namespace impm

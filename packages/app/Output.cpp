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

// One column of the particle table: its CSV name, its Exodus element-variable name (empty:
// not an element variable) and how to read it from the host mirrors.
template <int Dim>
struct Mirrors {
  explicit Mirrors(const ParticleSet<Dim>& ps)
      : id(Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), ps.id)),
        body(Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), ps.body)),
        X(Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), ps.X)),
        x(Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), ps.x)),
        u(Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), ps.u)),
        v(Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), ps.v)),
        a(Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), ps.a)),
        F(Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), ps.F)),
        stress(Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), ps.stress)),
        volume(Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), ps.volume)),
        mass(Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), ps.mass)),
        section(Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), ps.section)) {}
  typename Kokkos::View<GlobalId*>::HostMirror id;
  typename Kokkos::View<int*>::HostMirror body;
  typename ParticleSet<Dim>::Vectors::HostMirror X, x, u, v, a;
  typename ParticleSet<Dim>::Tensors::HostMirror F, stress;
  typename ParticleSet<Dim>::Scalars::HostMirror volume, mass, section;
};

template <int Dim>
struct Column {
  std::string csv, exodus;
  std::function<double(const Mirrors<Dim>&, std::size_t)> read;
};

// 1-D: id,X,x,u,strain,stress,volume,v,a,mass,section,body.  X is the Exodus coordinate and
// u its nodal displacementX, so neither is an element variable.
template <int Dim>
std::vector<Column<Dim>> particleColumns() {
  static_assert(Dim == 1, "2-D output is not implemented yet");
  using M = Mirrors<Dim>;
  return {
      {"id", "", [](const M& m, std::size_t p) { return double(m.id(p)); }},
      {"X", "", [](const M& m, std::size_t p) { return m.X(p, 0); }},
      {"x", "", [](const M& m, std::size_t p) { return m.x(p, 0); }},
      {"u", "", [](const M& m, std::size_t p) { return m.u(p, 0); }},
      {"strain", "strain", [](const M& m, std::size_t p) { return m.F(p, 0, 0) - 1.0; }},
      {"stress", "stress", [](const M& m, std::size_t p) { return m.stress(p, 0, 0); }},
      {"volume", "volume", [](const M& m, std::size_t p) { return m.volume(p); }},
      {"v", "velocityX", [](const M& m, std::size_t p) { return m.v(p, 0); }},
      {"a", "accelerationX", [](const M& m, std::size_t p) { return m.a(p, 0); }},
      {"mass", "mass", [](const M& m, std::size_t p) { return m.mass(p); }},
      {"section", "section", [](const M& m, std::size_t p) { return m.section(p); }},
      {"body", "body", [](const M& m, std::size_t p) { return double(m.body(p)); }},
  };
}

// A map with every index 0..n-1 on rank 0 and nothing elsewhere.
Teuchos::RCP<const Map> rootMap(GlobalId n, const Teuchos::RCP<const Comm>& comm) {
  const std::size_t local = comm->getRank() == 0 ? static_cast<std::size_t>(n) : 0;
  return Teuchos::rcp(new Map(static_cast<Tpetra::global_size_t>(n), local, 0, comm));
}

std::vector<std::vector<double>> columnsOf(const MultiVector& mv, std::size_t count) {
  std::vector<std::vector<double>> out(count);
  for (std::size_t c = 0; c < count; ++c) {
    auto data = mv.getData(c);
    out[c].assign(data.begin(), data.end());
  }
  return out;
}

template <int Dim>
std::vector<std::string> exodusElementVariables() {
  std::vector<std::string> names;
  for (const auto& c : particleColumns<Dim>())
    if (!c.exodus.empty())
      names.push_back(c.exodus);
  return names;
}

template <int Dim>
std::vector<std::vector<double>> exodusElementValues(const ParticleTable& table) {
  std::vector<std::vector<double>> values;
  const auto columns = particleColumns<Dim>();
  for (std::size_t c = 0; c < columns.size(); ++c)
    if (!columns[c].exodus.empty())
      values.push_back(table.columns[c]);
  return values;
}

}  // namespace

template <int Dim>
ParticleTable gatherParticles(const ParticleSet<Dim>& ps, const Teuchos::RCP<const Comm>& comm,
                              GlobalId totalParticles) {
  const auto columns = particleColumns<Dim>();
  const Mirrors<Dim> mirrors(ps);
  const std::size_t n = ps.size();
  std::vector<GO> gids(mirrors.id.data(), mirrors.id.data() + n);
  auto source = Teuchos::rcp(new Map(static_cast<Tpetra::global_size_t>(totalParticles),
                                     Teuchos::ArrayView<const GO>(gids), 0, comm));
  MultiVector local(source, columns.size());
  for (std::size_t c = 0; c < columns.size(); ++c) {
    auto data = local.getDataNonConst(c);
    for (std::size_t p = 0; p < n; ++p)
      data[p] = columns[c].read(mirrors, p);
  }
  auto target = rootMap(totalParticles, comm);
  MultiVector gathered(target, columns.size());
  gathered.doImport(local, Import(source, target), Tpetra::INSERT);
  ParticleTable table;
  for (const auto& c : columns)
    table.names.push_back(c.csv);
  table.columns = columnsOf(gathered, columns.size());
  return table;
}

template <int Dim>
Output<Dim>::Output(const Teuchos::ParameterList& params, const std::string& directory,
                    const std::string& prefix, const NodeOwnership<Dim>& ownership,
                    const ParticleSet<Dim>& particles, GlobalId totalParticles,
                    const std::vector<std::string>& historyColumns,
                    const std::vector<std::string>& gridFieldNames,
                    const std::vector<std::string>& globalNames)
    : ownership_(ownership),
      root_(ownership.comm()->getRank() == 0),
      every_(params.get<int>("Every")),
      exodus_(params.get<bool>("Exodus")),
      csv_(params.get<bool>("CSV")),
      totalParticles_(totalParticles),
      gridFields_(gridFieldNames.size()),
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
  gridFile_ = std::make_unique<ExodusFile>(base + "_grid.exo", "impm grid", grid, gridFieldNames,
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
  particleFile_ = std::make_unique<ExodusFile>(base + "_particles.exo", "impm particles", points,
                                               std::vector<std::string>{"displacementX"},
                                               exodusElementVariables<Dim>(), globalNames);
}

template <int Dim>
void Output<Dim>::writeFields(double time, const ParticleSet<Dim>& particles,
                              const MultiVector& gridFields, const std::vector<double>& globals) {
  const auto table = gatherParticles(particles, ownership_.comm(), totalParticles_);
  const auto nodes = rootMap(ownership_.grid().numNodes(), ownership_.comm());
  MultiVector gridOnRoot(nodes, gridFields.getNumVectors());
  gridOnRoot.doImport(gridFields, Import(gridFields.getMap(), nodes), Tpetra::INSERT);
  if (!root_)
    return;
  if (csv_)
    writeCsvTable(directory_ + "/" + prefix_ + "_particles.csv", table.names, table.columns);
  if (!exodus_)
    return;
  gridFile_->append(time, columnsOf(gridOnRoot, gridFields_), {}, globals);
  particleFile_->append(time, {table.column("u")}, exodusElementValues<Dim>(table), globals);
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

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
              "Print the wall-clock time of each phase (set-up, particle-grid map, graph, "
              "residual, Jacobian, Newton solve, particle update, migration, output) at the end, "
              "over all ranks");
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
        domain(Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), ps.domain)),
        domain0(Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), ps.domain0)),
        stressZZ(Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), ps.stressZZ)),
        volume(Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), ps.volume)),
        mass(Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), ps.mass)),
        section(Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), ps.section)) {}
  typename Kokkos::View<GlobalId*>::HostMirror id;
  typename Kokkos::View<int*>::HostMirror body;
  typename ParticleSet<Dim>::Vectors::HostMirror X, x, u, v, a;
  typename ParticleSet<Dim>::Tensors::HostMirror F, stress, domain, domain0;
  typename ParticleSet<Dim>::Scalars::HostMirror stressZZ, volume, mass, section;
};

template <int Dim>
struct Column {
  std::string csv, exodus;
  std::function<double(const Mirrors<Dim>&, std::size_t)> read;
};

// 1-D: id,X,x,u,strain,stress,volume,v,a,mass,section,body.  X is the Exodus coordinate and
// u its nodal displacementX, so neither is an element variable.
template <int Dim>
std::vector<Column<Dim>> particleColumns();

template <>
std::vector<Column<1>> particleColumns<1>() {
  using M = Mirrors<1>;
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

// 2-D: id,X,Y,x,y,u_x,u_y,stress_xx,stress_yy,stress_xy,stress_zz,J,volume, then velocity,
// acceleration, F, mass, body and the domain half-vectors r1, r2 (columns of F r0) and their
// reference values r01, r02.
template <>
std::vector<Column<2>> particleColumns<2>() {
  using M = Mirrors<2>;
  std::vector<Column<2>> c = {
      {"id", "", [](const M& m, std::size_t p) { return double(m.id(p)); }},
      {"X", "", [](const M& m, std::size_t p) { return m.X(p, 0); }},
      {"Y", "", [](const M& m, std::size_t p) { return m.X(p, 1); }},
      {"x", "", [](const M& m, std::size_t p) { return m.x(p, 0); }},
      {"y", "", [](const M& m, std::size_t p) { return m.x(p, 1); }},
      {"u_x", "", [](const M& m, std::size_t p) { return m.u(p, 0); }},
      {"u_y", "", [](const M& m, std::size_t p) { return m.u(p, 1); }},
      {"stress_xx", "stress_xx", [](const M& m, std::size_t p) { return m.stress(p, 0, 0); }},
      {"stress_yy", "stress_yy", [](const M& m, std::size_t p) { return m.stress(p, 1, 1); }},
      {"stress_xy", "stress_xy", [](const M& m, std::size_t p) { return m.stress(p, 0, 1); }},
      {"stress_zz", "stress_zz", [](const M& m, std::size_t p) { return m.stressZZ(p); }},
      {"J", "J",
       [](const M& m, std::size_t p) {
         return m.F(p, 0, 0) * m.F(p, 1, 1) - m.F(p, 0, 1) * m.F(p, 1, 0);
       }},
      {"volume", "volume", [](const M& m, std::size_t p) { return m.volume(p); }},
      {"v_x", "velocityX", [](const M& m, std::size_t p) { return m.v(p, 0); }},
      {"v_y", "velocityY", [](const M& m, std::size_t p) { return m.v(p, 1); }},
      {"a_x", "accelerationX", [](const M& m, std::size_t p) { return m.a(p, 0); }},
      {"a_y", "accelerationY", [](const M& m, std::size_t p) { return m.a(p, 1); }},
  };
  const char* const xy = "xy";
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) {
      const std::string name = std::string("F_") + xy[a] + xy[b];
      c.push_back({name, name, [a, b](const M& m, std::size_t p) { return m.F(p, a, b); }});
    }
  c.push_back({"mass", "mass", [](const M& m, std::size_t p) { return m.mass(p); }});
  c.push_back({"body", "body", [](const M& m, std::size_t p) { return double(m.body(p)); }});
  for (const char* r : {"r1_", "r2_", "r01_", "r02_"})
    for (int a = 0; a < 2; ++a) {
      const int k = r[1] == '0' ? r[2] - '1' : r[1] - '1';
      const bool reference = r[1] == '0';
      c.push_back({std::string(r) + xy[a], "", [a, k, reference](const M& m, std::size_t p) {
                     return reference ? m.domain0(p, a, k) : m.domain(p, a, k);
                   }});
    }
  return c;
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
std::vector<ParticleTable> gatherParticles(const ParticleSet<Dim>& ps,
                                           const Teuchos::RCP<const Comm>& comm,
                                           GlobalId totalParticles,
                                           const std::vector<TableRows>& rows) {
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
  std::vector<ParticleTable> tables;
  for (const TableRows where : rows) {
    const Teuchos::RCP<const Map> target =
        where == TableRows::onRoot
            ? rootMap(totalParticles, comm)
            : Teuchos::rcp<const Map>(
                  new Map(static_cast<Tpetra::global_size_t>(totalParticles), 0, comm));
    MultiVector gathered(target, columns.size());
    gathered.doImport(local, Import(source, target), Tpetra::INSERT);
    ParticleTable table;
    for (const auto& c : columns)
      table.names.push_back(c.csv);
    table.columns = columnsOf(gathered, columns.size());
    tables.push_back(std::move(table));
  }
  return tables;
}

template <int Dim>
ParticleTable gatherParticles(const ParticleSet<Dim>& ps, const Teuchos::RCP<const Comm>& comm,
                              GlobalId totalParticles, TableRows rows) {
  return gatherParticles(ps, comm, totalParticles, std::vector<TableRows>{rows}).front();
}

template <int Dim>
Output<Dim>::Output(const Teuchos::ParameterList& params, const std::string& directory,
                    const std::string& prefix, const NodeOwnership<Dim>& ownership,
                    const ParticleSet<Dim>& particles, GlobalId totalParticles,
                    const std::vector<std::string>& historyColumns,
                    const std::vector<std::string>& gridFieldNames,
                    const std::vector<std::string>& globalNames, Domains domains)
    : ownership_(ownership),
      domains_(domains),
      root_(ownership.comm()->getRank() == 0),
      every_(params.get<int>("Every")),
      exodus_(params.get<bool>("Exodus")),
      csv_(params.get<bool>("CSV")),
      totalParticles_(totalParticles),
      gridFields_(gridFieldNames.size()),
      directory_(directory),
      prefix_(prefix) {
  // The particles are needed here only for the Exodus meshes.
  const auto table =
      exodus_ ? gatherParticles(particles, ownership.comm(), totalParticles) : ParticleTable();
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
  grid.elementType = Dim == 1 ? "BAR2" : "QUAD4";
  grid.nodesPerElement = 1 << Dim;
  for (GlobalId cell = 0; cell < g.numCells(); ++cell) {
    int idx[Dim];
    g.cellIndex(cell, idx);
    for (int k = 0; k < grid.nodesPerElement; ++k) {  // counter-clockwise in 2-D
      int corner[Dim];
      corner[0] = idx[0] + ((k == 1 || k == 2) ? 1 : 0);
      if constexpr (Dim == 2)
        corner[1] = idx[1] + (k >= 2 ? 1 : 0);
      grid.connectivity.push_back(static_cast<int>(g.nodeId(corner) + 1));
    }
  }
  gridFile_ = std::make_unique<ExodusFile>(base + "_grid.exo", "impm grid", grid, gridFieldNames,
                                           std::vector<std::string>{}, globalNames);

  ExodusMesh points;
  points.dimension = Dim;
  for (const char* X : {"X", "Y"}) {
    if (static_cast<int>(points.coords.size()) < Dim)
      points.coords.push_back(table.column(X));
  }
  points.elementType = "SPHERE";
  points.nodesPerElement = 1;
  for (GlobalId p = 0; p < totalParticles; ++p) {
    points.connectivity.push_back(static_cast<int>(p + 1));
    points.elementIds.push_back(static_cast<int>(p + 1));
  }
  const std::vector<std::string> displacement = {"displacementX", "displacementY"};
  const std::vector<std::string> nodal(displacement.begin(), displacement.begin() + Dim);
  particleFile_ = std::make_unique<ExodusFile>(base + "_particles.exo", "impm particles", points,
                                               nodal, exodusElementVariables<Dim>(), globalNames);
  if (Dim == 2 && domains_ != Domains::none)
    domainFile_ = std::make_unique<ExodusFile>(base + "_domains.exo", "impm particle domains",
                                               domainMesh(table), nodal,
                                               exodusElementVariables<Dim>(), globalNames);
}

namespace {

// The columns that place the domain corners, looked up by name once per table (not once per
// particle: a million particles made the lookups a visible part of the output phase).
struct CornerColumns {
  // isBox: gimp's axis-aligned domains, else cpdi's parallelograms.
  CornerColumns(const ParticleTable& t, bool reference, bool isBox)
      : cx(t.column(reference ? "X" : "x")),
        cy(t.column(reference ? "Y" : "y")),
        r1x(t.column(reference ? "r01_x" : "r1_x")),
        r1y(t.column(reference ? "r01_y" : "r1_y")),
        r2x(t.column(reference ? "r02_x" : "r2_x")),
        r2y(t.column(reference ? "r02_y" : "r2_y")),
        box(isBox) {}
  // Counter-clockwise: (-,-), (+,-), (+,+), (-,+) in the half-vectors r1, r2.
  std::array<std::array<double, 2>, 4> operator()(std::size_t p) const {
    double r1[2] = {r1x[p], r1y[p]}, r2[2] = {r2x[p], r2y[p]};
    if (box)  // gimp integrates over the box of half-widths r1_x, r2_y
      r1[1] = 0.0, r2[0] = 0.0;
    std::array<std::array<double, 2>, 4> out;
    const double sign[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (int k = 0; k < 4; ++k)
      out[k] = {cx[p] + sign[k][0] * r1[0] + sign[k][1] * r2[0],
                cy[p] + sign[k][0] * r1[1] + sign[k][1] * r2[1]};
    return out;
  }
  const std::vector<double>&cx, &cy, &r1x, &r1y, &r2x, &r2y;
  bool box;
};

}  // namespace

template <int Dim>
ExodusMesh Output<Dim>::domainMesh(const ParticleTable& table) const {
  ExodusMesh mesh;
  mesh.dimension = 2;
  mesh.coords.resize(2);
  mesh.elementType = "QUAD4";
  mesh.nodesPerElement = 4;
  const CornerColumns reference(table, true, domains_ == Domains::box);
  for (GlobalId p = 0; p < totalParticles_; ++p) {
    for (const auto& c : reference(p)) {
      mesh.coords[0].push_back(c[0]), mesh.coords[1].push_back(c[1]);
      mesh.connectivity.push_back(static_cast<int>(mesh.coords[0].size()));
    }
    mesh.elementIds.push_back(static_cast<int>(p + 1));
  }
  return mesh;
}

template <int Dim>
std::vector<std::vector<double>> Output<Dim>::domainDisplacements(
    const ParticleTable& table) const {
  std::vector<std::vector<double>> u(2);
  const bool box = domains_ == Domains::box;
  const CornerColumns current(table, false, box), reference(table, true, box);
  for (GlobalId p = 0; p < totalParticles_; ++p) {
    const auto now = current(p), then = reference(p);
    for (int k = 0; k < 4; ++k)
      for (int d = 0; d < 2; ++d)
        u[d].push_back(now[k][d] - then[k][d]);
  }
  return u;
}

template <int Dim>
void Output<Dim>::writeFields(double time, const ParticleSet<Dim>& particles,
                              const MultiVector& gridFields, const std::vector<double>& globals) {
  const auto& comm = ownership_.comm();
  // The CSV in blocks of ids on every rank, the Exodus fields on rank 0: one read of the
  // particles for both.
  std::vector<TableRows> wanted;
  if (csv_)
    wanted.push_back(TableRows::inBlocks);
  if (exodus_)
    wanted.push_back(TableRows::onRoot);
  const auto tables = gatherParticles(particles, comm, totalParticles_, wanted);
  if (csv_) {  // every rank formats and writes its block
    const auto& block = tables.front();
    writeCsvTableCollectively(directory_ + "/" + prefix_ + "_particles.csv", *comm, block.names,
                              block.columns);
  }
  if (!exodus_)
    return;
  const auto& table = tables.back();
  const auto nodes = rootMap(ownership_.grid().numNodes(), comm);
  MultiVector gridOnRoot(nodes, gridFields.getNumVectors());
  gridOnRoot.doImport(gridFields, Import(gridFields.getMap(), nodes), Tpetra::INSERT);
  if (!root_)
    return;
  gridFile_->append(time, columnsOf(gridOnRoot, gridFields_), {}, globals);
  const auto elements = exodusElementValues<Dim>(table);
  if constexpr (Dim == 1) {
    particleFile_->append(time, {table.column("u")}, elements, globals);
  } else {
    particleFile_->append(time, {table.column("u_x"), table.column("u_y")}, elements, globals);
    if (domainFile_)
      domainFile_->append(time, domainDisplacements(table), elements, globals);
  }
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
  if (domainFile_)
    out.push_back(base + "_domains.exo");
  return out;
}

template ParticleTable gatherParticles<1>(const ParticleSet<1>&, const Teuchos::RCP<const Comm>&,
                                          GlobalId, TableRows);
template ParticleTable gatherParticles<2>(const ParticleSet<2>&, const Teuchos::RCP<const Comm>&,
                                          GlobalId, TableRows);
template class Output<1>;
template class Output<2>;

}  // namespace impm

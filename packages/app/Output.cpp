#include "app/Output.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <iostream>

#include "core/Axes.hpp"
#include "core/Collective.hpp"
#include "core/Errors.hpp"
#include "core/Parameters.hpp"

namespace impm {

namespace {

// Along direction d, the offset of corner k of an Exodus BAR2, QUAD4 or HEX8 cell from its
// lower corner: the lower face counter-clockwise (0, 1, 2, 3), then the upper one (4 ... 7).
int exodusCornerOffset(int k, int d) {
  const int inFace = k & 3;
  if (d == 0)
    return inFace == 1 || inFace == 2 ? 1 : 0;
  if (d == 1)
    return inFace >= 2 ? 1 : 0;
  return k >> 2;
}

}  // namespace

Teuchos::ParameterList outputValidParameters() {
  Teuchos::ParameterList valid;
  declareString(valid, "Directory", "output",
                "Directory for the output files, created if missing (--output-dir overrides)");
  declareString(valid, "Prefix", "",
                "File name prefix, without a '/' (empty: the deck file's name)");
  declareInt(valid, "Every", 1, "Write the fields every this many steps (and at the last step)",
             Bounds::atLeast(1));
  declareInt(valid, "History Every", 1,
             "Write a row of the history file every this many steps (and at the last step); "
             "the energies it reports are computed for those steps only, and explicit steps "
             "on a fixed grid (total Lagrangian) map the particles' motion only for those "
             "steps and the outputs, which makes a long explicit run's steps up to 40 % "
             "faster",
             Bounds::atLeast(1));
  declareBool(valid, "Exodus", true, "Write Exodus files of the grid and the particles");
  declareBool(valid, "CSV", true, "Write the particle table as CSV");
  declareInt(valid, "Checkpoint Every", 0,
             "Write a checkpoint every this many steps and at the last step (0: never), as "
             "<prefix>_checkpoint_<step>.nc, the newest also as <prefix>_checkpoint.nc; "
             "impm --restart continues from one",
             Bounds::atLeast(0));
  declareInt(valid, "Checkpoints Kept", 2,
             "How many checkpoints stay in the output directory, the newest (0: all)",
             Bounds::atLeast(0));
  declareStringArray(valid, "Fields", {},
                     "Particle fields written to the particle CSV and Exodus files (empty: all); "
                     "the framework's (id, X, x, u, strain, stress, stress_zz, J, volume, v, a, "
                     "F, mass, section, body, domain, domain0, as the dimension has them) and "
                     "those the materials declare");
  declareBool(valid, "Timers", false,
              "Print the wall-clock time of each phase (set-up, particle-grid map, graph, "
              "residual, Jacobian, Newton solve, particle update, migration, output, checkpoint, "
              "checkpoint read) at the end, over all ranks");
  return valid;
}

std::vector<std::string> outputFields(const Teuchos::ParameterList& output) {
  const auto& names = output.get<Teuchos::Array<std::string>>("Fields");
  return std::vector<std::string>(names.begin(), names.end());
}

const std::vector<double>& ParticleTable::column(const std::string& name) const {
  for (std::size_t c = 0; c < names.size(); ++c)
    if (names[c] == name)
      return columns[c];
  throw std::logic_error("no particle column " + name);
}

template <int Dim>
std::vector<TableColumn> outputColumns(const ParticleSet<Dim>& particles,
                                       const std::vector<std::string>& fields) {
  std::vector<std::string> available;
  particles.forEachField([&](const FieldSpec& spec, const auto&) {
    if (spec.output())
      available.push_back(spec.name);
  });
  for (const auto& f : fields)
    if (std::find(available.begin(), available.end(), f) == available.end()) {
      std::string list;
      for (const auto& a : available)
        list += (list.empty() ? "" : ", ") + a;
      throw InputError("Output/Fields", "'" + f + "' is not an output field" +
                                            didYouMean(f, available) + "; the fields are " + list);
    }
  std::vector<TableColumn> out;
  particles.forEachField([&](const FieldSpec& spec, const auto&) {
    const bool wanted = fields.empty() || spec.name == "id" ||
                        std::find(fields.begin(), fields.end(), spec.name) != fields.end();
    if (wanted)
      for (const auto& c : spec.columns)
        out.push_back({spec.name, c.component, c.csv, c.exodus});
  });
  return out;
}

namespace {

std::vector<std::vector<double>> columnsOf(const MultiVector& mv, std::size_t count) {
  std::vector<std::vector<double>> out(count);
  for (std::size_t c = 0; c < count; ++c) {
    auto data = mv.getData(c);
    out[c].assign(data.begin(), data.end());
  }
  return out;
}

// The columns of `wanted` that `all` holds, by CSV name, in the order of `all`.
std::vector<TableColumn> unionOf(const std::vector<TableColumn>& all,
                                 const std::vector<std::vector<TableColumn>>& wanted) {
  std::vector<TableColumn> out;
  for (const auto& c : all)
    for (const auto& w : wanted)
      if (std::any_of(w.begin(), w.end(), [&](const TableColumn& x) { return x.csv == c.csv; })) {
        out.push_back(c);
        break;
      }
  return out;
}

}  // namespace

template <int Dim>
ParticleTable gatherParticles(const ParticleSet<Dim>& ps, const Teuchos::RCP<const Comm>& comm,
                              GlobalId totalParticles, const std::vector<TableColumn>& columns,
                              TableRows rows) {
  const auto host = ps.mirror(Kokkos::DefaultHostExecutionSpace());
  const std::size_t n = ps.size();
  // Copies each column's values to out(c), particle p's to out(c)[place(p)].
  const auto fill = [&](const auto& out, const auto& place) {
    host.forEachField([&](const FieldSpec& spec, const auto& view) {
      for (std::size_t c = 0; c < columns.size(); ++c) {
        if (columns[c].field != spec.name)
          continue;
        auto data = out(c);
        for (std::size_t p = 0; p < n; ++p)
          data[place(p)] = fieldComponent(view, p, columns[c].component);
      }
    });
  };
  ParticleTable table;
  for (const auto& c : columns)
    table.names.push_back(c.csv);
  if (comm->getSize() == 1) {
    // Every row is here, and both layouts are the rows in id order: each value goes to its
    // place in the table at once, without the maps, the import and two copies of the table.
    table.columns.assign(columns.size(), std::vector<double>(n));
    for (std::size_t p = 0; p < n; ++p)
      if (host.id(p) < 0 || static_cast<GlobalId>(host.id(p)) >= totalParticles)
        throw std::logic_error("gatherParticles: particle id " + std::to_string(host.id(p)) +
                               " outside [0, " + std::to_string(totalParticles) + ")");
    fill([&](std::size_t c) { return table.columns[c].data(); },
         [&](std::size_t p) { return static_cast<std::size_t>(host.id(p)); });
    return table;
  }
  std::vector<GO> gids(host.id.data(), host.id.data() + n);
  auto source = Teuchos::rcp(new Map(static_cast<Tpetra::global_size_t>(totalParticles),
                                     Teuchos::ArrayView<const GO>(gids), 0, comm));
  MultiVector local(source, std::max<std::size_t>(columns.size(), 1));
  fill([&](std::size_t c) { return local.getDataNonConst(c); }, [](std::size_t p) { return p; });
  const Teuchos::RCP<const Map> target =
      rows == TableRows::onRoot ? rootMap(totalParticles, comm)
                                : Teuchos::rcp<const Map>(new Map(
                                      static_cast<Tpetra::global_size_t>(totalParticles), 0, comm));
  MultiVector gathered(target, local.getNumVectors());
  gathered.doImport(local, Import(source, target), Tpetra::INSERT);
  table.columns = columnsOf(gathered, columns.size());
  return table;
}

template <int Dim>
ParticleTable gatherParticles(const ParticleSet<Dim>& ps, const Teuchos::RCP<const Comm>& comm,
                              GlobalId totalParticles, TableRows rows) {
  return gatherParticles(ps, comm, totalParticles, outputColumns(ps), rows);
}

template <int Dim>
Output<Dim>::Output(const Teuchos::ParameterList& params, const std::string& directory,
                    const std::string& prefix, const NodeOwnership<Dim>& ownership,
                    const ParticleSet<Dim>& particles, GlobalId totalParticles,
                    const std::vector<std::string>& historyColumns,
                    const std::vector<std::string>& gridFieldNames,
                    const std::vector<std::string>& globalNames, Domains domains,
                    const OutputResume* resume)
    : ownership_(ownership),
      domains_(domains),
      root_(ownership.comm()->getRank() == 0),
      every_(params.get<int>("Every")),
      exodus_(params.get<bool>("Exodus")),
      csv_(params.get<bool>("CSV")),
      totalParticles_(totalParticles),
      gridFields_(gridFieldNames.size()),
      directory_(directory),
      prefix_(prefix),
      exodusSteps_(resume ? resume->exodusSteps : 0) {
  const auto all = outputColumns(particles);
  csvColumns_ = outputColumns(particles, outputFields(params));
  for (const auto& c : csvColumns_)
    if (!c.exodus.empty())
      exodusColumns_.push_back(c);
  // The points sit at X and move by u; domains are drawn from x, X and the half-vectors.
  std::vector<TableColumn> geometry;
  for (const auto& c : all)
    if (c.field == "X" || c.field == "u" ||
        (domains_ != Domains::none &&
         (c.field == "x" || c.field == "domain" || c.field == "domain0" || c.field == "corners" ||
          c.field == "corners0")))
      geometry.push_back(c);
  gathered_ = unionOf(all, {csvColumns_, exodusColumns_, geometry});
  // The particles are read here for the Exodus meshes and a fresh start's initial state
  // (writeInitialFields): one gather for both.
  if (exodus_ || (csv_ && !resume))
    initial_ = gatherParticles(particles, ownership.comm(), totalParticles, gathered_, tableRows());
  const ParticleTable none;
  const ParticleTable& table = initial_ ? *initial_ : none;
  if (!root_) {
    if (resume)  // as below: every rank drops it, so that none writes it
      initial_.reset();
    return;
  }
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error)
    throw FileError(directory, "cannot create the output directory (" + error.message() + ")");
  const std::string base = directory + "/" + prefix;
  requireWritable(plannedFiles(base));
  history_ = std::make_unique<CsvHistory>(base + "_history.csv", historyColumns,
                                          resume ? resume->step : -1,
                                          resume ? resume->notes : std::vector<std::string>{});
  std::vector<std::string> restarted;  // files that could not be continued
  if (resume && !history_->continued())
    restarted.push_back(history_->path());
  const auto report = [&] {
    if (restarted.empty())
      return;
    std::cout << "impm: note: these files did not hold the steps before the checkpoint and "
                 "start at the restart:";
    for (const auto& f : restarted)
      std::cout << " " << f;
    std::cout << "\n";
  };
  if (!exodus_) {
    report();
    return;
  }
  const int keep = resume ? resume->exodusSteps : 0;

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
  grid.elementType = Dim == 1 ? "BAR2" : (Dim == 2 ? "QUAD4" : "HEX8");
  grid.nodesPerElement = 1 << Dim;
  for (GlobalId cell = 0; cell < g.numCells(); ++cell) {
    int idx[Dim];
    g.cellIndex(cell, idx);
    for (int k = 0; k < grid.nodesPerElement; ++k) {
      int corner[Dim];
      for (int d = 0; d < Dim; ++d)
        corner[d] = idx[d] + exodusCornerOffset(k, d);
      grid.connectivity.push_back(static_cast<int>(g.nodeId(corner) + 1));
    }
  }
  gridFile_ = std::make_unique<ExodusFile>(base + "_grid.exo", "impm grid", grid, gridFieldNames,
                                           std::vector<std::string>{}, globalNames, keep);

  ExodusMesh points;
  points.dimension = Dim;
  for (const auto& c : gathered_)
    if (c.field == "X")
      points.coords.push_back(table.column(c.csv));
  points.elementType = "SPHERE";
  points.nodesPerElement = 1;
  for (GlobalId p = 0; p < totalParticles; ++p) {
    points.connectivity.push_back(static_cast<int>(p + 1));
    points.elementIds.push_back(static_cast<int>(p + 1));
  }
  const std::vector<std::string> displacement = {"displacementX", "displacementY", "displacementZ"};
  const std::vector<std::string> nodal(displacement.begin(), displacement.begin() + Dim);
  std::vector<std::string> elements;
  for (const auto& c : exodusColumns_)
    elements.push_back(c.exodus);
  particleFile_ = std::make_unique<ExodusFile>(base + "_particles.exo", "impm particles", points,
                                               nodal, elements, globalNames, keep);
  if (Dim > 1 && domains_ != Domains::none)  // 1-D domains are the particles' segments
    domainFile_ =
        std::make_unique<ExodusFile>(base + "_domains.exo", "impm particle domains",
                                     domainMesh(table), nodal, elements, globalNames, keep);
  for (const auto* f : {gridFile_.get(), particleFile_.get(), domainFile_.get()})
    if (f && keep > 0 && !f->continued())
      restarted.push_back(f->path());
  report();
  if (resume)  // a restart's initial state is in the files already
    initial_.reset();
}

namespace {

// The columns that place the domain corners, looked up by name once per table (not once per
// particle: a million particles made the lookups a visible part of the output phase).
template <int Dim>
struct CornerColumns {
  static constexpr int kCorners = 1 << Dim;
  // tracked: the corners c1 ... c(2^Dim); box: gimp's axis-aligned domains; else cpdi's
  // parallelograms (parallelepipeds).
  CornerColumns(const ParticleTable& t, bool reference, bool isTracked, bool isBox)
      : tracked(isTracked), box(isBox) {
    const std::string r = reference ? "0" : "";
    for (int d = 0; d < Dim; ++d)
      centre[d] = &t.column(reference ? referenceAxisName(d) : axisName(d));
    const int vectors = tracked ? kCorners : Dim;  // the corners, or the half-vectors r_k
    for (int k = 0; k < vectors; ++k)
      for (int d = 0; d < Dim; ++d)
        columns[Dim * k + d] =
            &t.column((tracked ? "c" : "r") + r + std::to_string(k + 1) + "_" + axisName(d));
  }
  // In Exodus order (QUAD4: counter-clockwise (-,-), (+,-), (+,+), (-,+) in r1, r2; HEX8: the
  // same at -r3, then at +r3).
  std::array<std::array<double, Dim>, kCorners> operator()(std::size_t p) const {
    std::array<std::array<double, Dim>, kCorners> out;
    if (tracked) {
      for (int c = 0; c < kCorners; ++c)
        for (int d = 0; d < Dim; ++d)
          out[c][d] = (*columns[Dim * c + d])[p];
      return out;
    }
    double half[Dim][Dim];  // half[k][d]: component d of r_k
    for (int k = 0; k < Dim; ++k)
      for (int d = 0; d < Dim; ++d)  // gimp integrates over the box of half-widths r_k,k
        half[k][d] = box && k != d ? 0.0 : (*columns[Dim * k + d])[p];
    for (int c = 0; c < kCorners; ++c)
      for (int d = 0; d < Dim; ++d) {
        out[c][d] = (*centre[d])[p];
        for (int k = 0; k < Dim; ++k)
          out[c][d] += (exodusCornerOffset(c, k) ? 1.0 : -1.0) * half[k][d];
      }
    return out;
  }
  bool tracked, box;
  const std::vector<double>* centre[Dim] = {};
  const std::vector<double>* columns[Dim * kCorners] = {};
};

}  // namespace

template <int Dim>
ExodusMesh Output<Dim>::domainMesh(const ParticleTable& table) const {
  ExodusMesh mesh;
  mesh.dimension = Dim;
  mesh.coords.resize(Dim);
  mesh.elementType = Dim == 2 ? "QUAD4" : "HEX8";
  mesh.nodesPerElement = 1 << Dim;
  const CornerColumns<Dim> reference(table, true, domains_ == Domains::corners,
                                     domains_ == Domains::box);
  for (GlobalId p = 0; p < totalParticles_; ++p) {
    for (const auto& c : reference(p)) {
      for (int d = 0; d < Dim; ++d)
        mesh.coords[d].push_back(c[d]);
      mesh.connectivity.push_back(static_cast<int>(mesh.coords[0].size()));
    }
    mesh.elementIds.push_back(static_cast<int>(p + 1));
  }
  return mesh;
}

template <int Dim>
std::vector<std::vector<double>> Output<Dim>::domainDisplacements(
    const ParticleTable& table) const {
  std::vector<std::vector<double>> u(Dim);
  const bool tracked = domains_ == Domains::corners, box = domains_ == Domains::box;
  const CornerColumns<Dim> current(table, false, tracked, box),
      reference(table, true, tracked, box);
  for (GlobalId p = 0; p < totalParticles_; ++p) {
    const auto now = current(p), then = reference(p);
    for (int k = 0; k < (1 << Dim); ++k)
      for (int d = 0; d < Dim; ++d)
        u[d].push_back(now[k][d] - then[k][d]);
  }
  return u;
}

template <int Dim>
std::vector<std::vector<double>> Output<Dim>::elementValues(const ParticleTable& table) const {
  std::vector<std::vector<double>> values;
  for (const auto& c : exodusColumns_)
    values.push_back(table.column(c.csv));
  return values;
}

template <int Dim>
void Output<Dim>::writeFields(double time, const ParticleSet<Dim>& particles,
                              const MultiVector& gridFields, const std::vector<double>& globals) {
  if (!writesFields())
    return;
  write(time,
        gatherParticles(particles, ownership_.comm(), totalParticles_, gathered_, tableRows()),
        gridFields, globals);
}

template <int Dim>
void Output<Dim>::writeInitialFields(double time, const MultiVector& gridFields,
                                     const std::vector<double>& globals) {
  if (!writesFields())
    return;
  if (!initial_)
    throw std::logic_error("Output::writeInitialFields: no initial state (written, or a restart)");
  const ParticleTable table = std::move(*initial_);
  initial_.reset();
  write(time, table, gridFields, globals);
}

template <int Dim>
void Output<Dim>::write(double time, const ParticleTable& table, const MultiVector& gridFields,
                        const std::vector<double>& globals) {
  // The table's rows are where tableRows() put them; the collective CSV write takes either.
  const auto& comm = ownership_.comm();
  if (csv_) {
    std::vector<std::string> names;
    for (const auto& c : csvColumns_)
      names.push_back(c.csv);
    // The table's own columns when they are the CSV's, in order; a selection otherwise.
    std::vector<std::vector<double>> selected;
    if (names != table.names)
      for (const auto& name : names)
        selected.push_back(table.column(name));
    writeCsvTableCollectively(directory_ + "/" + prefix_ + "_particles.csv", *comm, names,
                              names == table.names ? table.columns : selected);
  }
  if (!exodus_)
    return;
  ++exodusSteps_;
  const auto nodes = rootMap(ownership_.grid().numNodes(), comm);
  MultiVector gridOnRoot(nodes, gridFields.getNumVectors());
  gridOnRoot.doImport(gridFields, Import(gridFields.getMap(), nodes), Tpetra::INSERT);
  if (!root_)
    return;
  gridFile_->append(time, columnsOf(gridOnRoot, gridFields_), {}, globals);
  const auto elements = elementValues(table);
  std::vector<std::vector<double>> u;
  for (const auto& c : gathered_)
    if (c.field == "u")
      u.push_back(table.column(c.csv));
  particleFile_->append(time, u, elements, globals);
  if (domainFile_)
    domainFile_->append(time, domainDisplacements(table), elements, globals);
}

template <int Dim>
void Output<Dim>::appendHistory(const std::vector<double>& row) const {
  collectively(*ownership_.comm(), [&] {
    if (root_)
      history_->append(row);
  });
}

template <int Dim>
std::vector<std::string> Output<Dim>::plannedFiles(const std::string& base) const {
  std::vector<std::string> out = {base + "_history.csv", base + "_verification.csv"};
  if (csv_)
    out.push_back(base + "_particles.csv");
  if (exodus_) {
    out.push_back(base + "_grid.exo"), out.push_back(base + "_particles.exo");
    if (Dim > 1 && domains_ != Domains::none)
      out.push_back(base + "_domains.exo");
  }
  return out;
}

template <int Dim>
void Output<Dim>::requireWritable(const std::vector<std::string>& paths) {
  // A run that failed on its third file had already reset the first two: every file a
  // previous run left is tried for writing before any is touched.
  for (const auto& path : paths) {
    if (!std::filesystem::exists(path))
      continue;
    const int fd = ::open(path.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
    if (fd < 0)
      throw FileError(path, std::string("cannot be written, so no output was changed (") +
                                std::strerror(errno) + ")");
    ::close(fd);
  }
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

#define IMPM_INSTANTIATE(D)                                                                        \
  template std::vector<TableColumn> outputColumns<D>(const ParticleSet<D>&,                        \
                                                     const std::vector<std::string>&);             \
  template ParticleTable gatherParticles<D>(const ParticleSet<D>&,                                 \
                                            const Teuchos::RCP<const Comm>&, GlobalId, TableRows); \
  template ParticleTable gatherParticles<D>(const ParticleSet<D>&,                                 \
                                            const Teuchos::RCP<const Comm>&, GlobalId,             \
                                            const std::vector<TableColumn>&, TableRows);
IMPM_INSTANTIATE(1)
IMPM_INSTANTIATE(2)
IMPM_INSTANTIATE(3)
#undef IMPM_INSTANTIATE
template class Output<1>;
template class Output<2>;
template class Output<3>;

}  // namespace impm

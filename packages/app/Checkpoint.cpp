#include "app/Checkpoint.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <algorithm>
#include <array>
#include <charconv>
#include <cstring>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <map>
#include <set>
#include <sstream>

#include "core/Collective.hpp"
#include "core/Errors.hpp"
#include "core/MpiComm.hpp"
#include "io/CheckpointFile.hpp"

namespace impm {

namespace {

// Rows of the particle fields read at a time (bounds the memory a restart needs).
constexpr std::size_t kChunk = 1 << 16;

std::string particleVariable(const std::string& field) {
  return "particle_" + field;
}

// "name:model,..." of the deck's materials; "name,..." of its bodies.
std::string materialList(const Teuchos::ParameterList& deck) {
  std::string out;
  const auto& materials = deck.sublist("Materials");
  for (auto it = materials.begin(); it != materials.end(); ++it)
    out += (out.empty() ? "" : ",") + materials.name(it) + ":" +
           materials.sublist(materials.name(it)).get<std::string>("Model");
  return out;
}

std::string bodyList(const Teuchos::ParameterList& deck) {
  std::string out;
  const auto& bodies = deck.sublist("Bodies");
  for (auto it = bodies.begin(); it != bodies.end(); ++it)
    out += (out.empty() ? "" : ",") + bodies.name(it);
  return out;
}

template <class T>
std::string listed(const std::vector<T>& v) {
  std::ostringstream s;
  s << std::setprecision(17) << "{";
  for (std::size_t k = 0; k < v.size(); ++k)
    s << (k ? ", " : "") << v[k];
  return s.str() + "}";
}

// The parameters a restart may change: how the run is solved, written, checked and shared,
// and how far it goes.
bool isRunControl(const std::string& path) {
  for (const char* list : {"Output/", "Solver/", "Verification/", "Load Balance/"})
    if (path.rfind(list, 0) == 0)
      return true;
  return path == "Time Integration/Final Time";
}

// The shortest text that reads back as the same double (2e6 as "2000000", 0.3 as "0.3").
std::string shortest(double v) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, v).ptr;
  return std::string(text, end);
}

// A parameter's value as text that tells any two values apart.
std::string exactText(const Teuchos::ParameterEntry& entry) {
  if (entry.isType<double>())
    return shortest(Teuchos::getValue<double>(entry));
  if (entry.isType<Teuchos::Array<double>>()) {
    std::string text = "{";
    for (double v : Teuchos::getValue<Teuchos::Array<double>>(entry))
      text += (text.size() > 1 ? ", " : "") + shortest(v);
    return text + "}";
  }
  std::ostringstream value;
  entry.getAny(false).print(value);
  return value.str();
}

void physicsLines(const Teuchos::ParameterList& list, const std::string& prefix,
                  std::vector<std::string>& lines) {
  for (auto it = list.begin(); it != list.end(); ++it) {
    const std::string path = prefix + list.name(it);
    const auto& entry = list.entry(it);
    if (entry.isList()) {
      physicsLines(Teuchos::getValue<Teuchos::ParameterList>(entry), path + "/", lines);
    } else if (!isRunControl(path)) {
      lines.push_back(path + " = " + exactText(entry));
    }
  }
}

// path -> value of RunIdentity::physics lines.
std::map<std::string, std::string> physicsByPath(const std::string& text) {
  std::map<std::string, std::string> byPath;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    const auto at = line.find(" = ");
    if (at != std::string::npos)
      byPath[line.substr(0, at)] = line.substr(at + 3);
  }
  return byPath;
}

// "path: theirs -> ours" for every parameter that defines the problem and differs.
std::vector<std::string> physicsChanges(const std::string& theirs, const std::string& ours) {
  const auto before = physicsByPath(theirs), now = physicsByPath(ours);
  std::vector<std::string> changes;
  const auto shown = [](const std::map<std::string, std::string>& m, const std::string& path) {
    const auto it = m.find(path);
    return it == m.end() ? std::string("(not set)") : it->second;
  };
  std::set<std::string> paths;
  for (const auto& [path, value] : before)
    paths.insert(path);
  for (const auto& [path, value] : now)
    paths.insert(path);
  for (const auto& path : paths)
    if (shown(before, path) != shown(now, path))
      changes.push_back(path + ": " + shown(before, path) + " -> " + shown(now, path));
  return changes;
}

}  // namespace

std::string physicsParameters(const Teuchos::ParameterList& deck) {
  std::vector<std::string> lines;
  physicsLines(deck, "", lines);
  std::sort(lines.begin(), lines.end());
  std::string text;
  for (const auto& line : lines)
    text += line + "\n";
  return text;
}

namespace {

void writeIdentity(CheckpointWriter& file, const RunIdentity& id) {
  file.attribute("grid_cells", id.cells);
  file.attribute("grid_origin", id.origin);
  file.attribute("grid_spacing", id.spacing);
  file.attribute("method", id.method);
  file.attribute("kinematics", id.kinematics);
  file.attribute("time_integration", id.timeIntegration);
  file.attribute("materials", id.materials);
  file.attribute("bodies", id.bodies);
  file.attribute("particles", std::vector<long long>{id.particles});
  file.attribute("fingerprint", std::vector<long long>{id.fingerprint});
  file.attribute("physics", id.physics);
}

// The first difference between the checkpoint's problem and this deck's, or "".
std::string identityDifference(const CheckpointReader& file, const RunIdentity& id) {
  const auto differs = [](const std::string& what, const std::string& theirs,
                          const std::string& ours) {
    return "is a checkpoint of another problem: its " + what + " is " + theirs + ", this deck's " +
           ours;
  };
  if (file.integers("grid_cells").size() != id.cells.size())
    return differs("dimension", std::to_string(file.integers("grid_cells").size()) + "-D",
                   std::to_string(id.cells.size()) + "-D");
  if (file.text("method") != id.method)
    return differs("method", file.text("method"), id.method);
  if (file.text("kinematics") != id.kinematics)
    return differs("kinematics", file.text("kinematics"), id.kinematics);
  if (file.text("time_integration") != id.timeIntegration)
    return differs("time integration", file.text("time_integration"), id.timeIntegration);
  if (file.integers("grid_cells") != id.cells)
    return differs("grid", listed(file.integers("grid_cells")) + " cells", listed(id.cells));
  if (file.numbers("grid_origin") != id.origin || file.numbers("grid_spacing") != id.spacing)
    return differs("grid",
                   "at " + listed(file.numbers("grid_origin")) + " with spacing " +
                       listed(file.numbers("grid_spacing")),
                   "at " + listed(id.origin) + " with spacing " + listed(id.spacing));
  if (file.text("materials") != id.materials)
    return differs("materials", "'" + file.text("materials") + "'", "'" + id.materials + "'");
  if (file.text("bodies") != id.bodies)
    return differs("bodies", "'" + file.text("bodies") + "'", "'" + id.bodies + "'");
  if (file.integers("particles") != std::vector<long long>{id.particles})
    return differs("particle count", std::to_string(file.integers("particles").at(0)),
                   std::to_string(id.particles));
  if (file.integers("fingerprint") != std::vector<long long>{id.fingerprint})
    return "is a checkpoint of another problem: its particles start at other reference "
           "positions (or have other ids) than this deck's";
  return "";
}

}  // namespace

template <int Dim>
RunIdentity runIdentity(const Teuchos::ParameterList& deck, const GridGeometry<Dim>& grid,
                        const ParticleSet<Dim>& particles, GlobalId totalParticles,
                        const Comm& comm) {
  RunIdentity id;
  for (int d = 0; d < Dim; ++d) {
    id.cells.push_back(grid.cells[d]);
    id.origin.push_back(grid.origin[d]);
    id.spacing.push_back(grid.spacing[d]);
  }
  const auto& discretization = deck.sublist("Discretization");
  id.method = discretization.get<std::string>("Method");
  // F-bar changes what the particles' F means: part of the kinematics (a run without it
  // writes the kinematics alone, as checkpoints did before F-bar).
  id.kinematics = discretization.get<std::string>("Kinematics");
  if (discretization.get<std::string>("F-bar") != "none")
    id.kinematics += " with F-bar = " + discretization.get<std::string>("F-bar");
  id.timeIntegration = deck.sublist("Time Integration").get<std::string>("Type");
  id.materials = materialList(deck);
  id.bodies = bodyList(deck);
  id.particles = totalParticles;
  // The fingerprint sums a hash of each particle's id and reference position: independent
  // of the particles' order and ranks, and of everything that changes while the run goes.
  const auto host = particles.mirror(Kokkos::DefaultHostExecutionSpace());
  std::uint64_t local = 0, global = 0;
  for (std::size_t p = 0; p < particles.size(); ++p) {
    double row[Dim + 1];
    row[0] = static_cast<double>(host.id(p));
    for (int d = 0; d < Dim; ++d)
      row[d + 1] = host.X(p, d);
    local += rowHash(static_cast<std::size_t>(host.id(p)), row, sizeof row);
  }
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, local, Teuchos::outArg(global));
  id.fingerprint = static_cast<long long>(global);
  id.physics = physicsParameters(deck);
  return id;
}

namespace {

// Runs f on rank 0; every rank learns of its failure (a full disk).  Collective.
void onRoot(const Comm& comm, const std::function<void()>& f) {
  collectively(comm, [&] {
    if (comm.getRank() == 0)
      f();
  });
}

// Rows (unknown, u, v, a) of a fixed grid's nodal state, gathered to rank 0 and sorted by
// unknown, so that the file does not depend on the ranks.  Collective.
std::vector<double> gatherNodalState(const StepperState& s, const Comm& comm) {
  std::vector<std::array<double, 4>> rows;
  for (std::size_t k = 0; k < s.nodalDofs.size(); ++k)
    rows.push_back({static_cast<double>(s.nodalDofs[k]), s.nodalU[k], s.nodalV[k], s.nodalA[k]});
  int count = static_cast<int>(4 * rows.size());
  std::vector<int> counts(comm.getSize()), offsets(comm.getSize(), 0);
  const MPI_Comm mpi = rawComm(comm);
  MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, mpi);
  for (int r = 1; r < comm.getSize(); ++r)
    offsets[r] = offsets[r - 1] + counts[r - 1];
  std::vector<std::array<double, 4>> all(comm.getRank() == 0 ? (offsets.back() + counts.back()) / 4
                                                             : 0);
  MPI_Gatherv(rows.data(), count, MPI_DOUBLE, all.data(), counts.data(), offsets.data(), MPI_DOUBLE,
              0, mpi);
  std::sort(all.begin(), all.end());
  std::vector<double> flat;
  for (const auto& row : all)
    flat.insert(flat.end(), row.begin(), row.end());
  return flat;
}

// A vector's values on rank 0 (`target`: every index there), row-major (row: global
// index); `import` from its map to target, or null to make one.  Collective.
std::vector<double> gatherRows(const MultiVector& v, const Import* import,
                               const Teuchos::RCP<const Map>& target) {
  MultiVector all(target, v.getNumVectors());
  if (import)
    all.doImport(v, *import, Tpetra::INSERT);
  else
    all.doImport(v, Import(v.getMap(), target), Tpetra::INSERT);
  const std::size_t width = v.getNumVectors();
  std::vector<double> values(all.getLocalLength() * width);
  for (std::size_t c = 0; c < width; ++c) {
    auto data = all.getData(c);
    for (std::size_t i = 0; i < all.getLocalLength(); ++i)
      values[i * width + c] = data[i];
  }
  return values;
}

}  // namespace

template <int Dim>
void writeCheckpoint(const std::string& path, const RunIdentity& identity,
                     const ParticleSet<Dim>& particles, GlobalId totalParticles,
                     const RunState<Dim>& state, const MultiVector& gridFields) {
  const auto& comm = gridFields.getMap()->getComm();
  const auto& s = state.stepper;
  const auto nodal = gatherNodalState(s, *comm);
  std::unique_ptr<CheckpointWriter> file;
  onRoot(*comm, [&] {
    file = std::make_unique<CheckpointWriter>(path);
    writeIdentity(*file, identity);
    file->attribute(
        "step", std::vector<long long>{s.step, s.attempts, s.started ? 1 : 0, state.exodusSteps});
    file->attribute("time", std::vector<double>{s.time, s.loadFactor, s.size, s.bodyWork});
    file->attribute("contributions",
                    std::vector<long long>{static_cast<long long>(state.contributions.size())});
    for (std::size_t c = 0; c < state.contributions.size(); ++c)
      file->attribute("contribution_" + std::to_string(c), state.contributions[c]);
    particles.forEachField([&](const FieldSpec& spec, const auto& view) {
      if (spec.checkpoint)
        file->declare(particleVariable(spec.name), totalParticles, fieldWidth(view),
                      std::is_integral_v<typename std::decay_t<decltype(view)>::value_type>);
    });
    file->declare("grid_fields", gridFields.getGlobalLength(), gridFields.getNumVectors(), false);
    file->declare("nodal_state", nodal.size() / 4, 4, false);
    const auto& partition = state.partition;
    file->attribute("partition_ranks", std::vector<long long>{partition.ranks});
    file->attribute("partition_imbalance",
                    std::vector<double>{partition.imbalanceAfterRepartition});
    if (!partition.cellOwners.empty())  // blocks: no table (and no dimension of length 0)
      file->declare("cell_owners", partition.cellOwners.size(), 1, true);
  });
  // Particle fields, one at a time: gathered to rank 0 by id.
  const auto host = particles.mirror(Kokkos::DefaultHostExecutionSpace());
  std::vector<GO> gids(host.id.data(), host.id.data() + particles.size());
  auto source = Teuchos::rcp(new Map(static_cast<Tpetra::global_size_t>(totalParticles),
                                     Teuchos::ArrayView<const GO>(gids), 0, comm));
  const auto target = rootMap(totalParticles, comm);
  const Import gather(source, target);
  host.forEachField([&](const FieldSpec& spec, const auto& view) {
    if (!spec.checkpoint)
      return;
    const int width = fieldWidth(view);
    MultiVector local(source, width);
    for (int c = 0; c < width; ++c) {
      auto data = local.getDataNonConst(c);
      for (std::size_t p = 0; p < particles.size(); ++p)
        data[p] = fieldComponent(view, p, c);
    }
    const auto values = gatherRows(local, &gather, target);
    onRoot(*comm, [&] {
      using Value = typename std::decay_t<decltype(view)>::value_type;
      if constexpr (std::is_integral_v<Value>)
        file->write(particleVariable(spec.name),
                    std::vector<long long>(values.begin(), values.end()));
      else
        file->write(particleVariable(spec.name), values);
    });
  });
  const auto grid = gatherRows(gridFields, nullptr, rootMap(gridFields.getGlobalLength(), comm));
  onRoot(*comm, [&] {
    file->write("grid_fields", grid);
    file->write("nodal_state", nodal);
    const auto& owners = state.partition.cellOwners;
    if (!owners.empty())
      file->write("cell_owners", std::vector<long long>(owners.begin(), owners.end()));
    file->commit();
  });
}

namespace {

template <int Dim>
void readStepperState(const CheckpointReader& file, RunState<Dim>& state) {
  const auto steps = file.integers("step");
  const auto times = file.numbers("time");
  const auto contributions = file.integers("contributions");
  if (steps.size() != 4 || times.size() != 4 || contributions.size() != 1)
    throw FileError(file.path(), "has a malformed stepper state");
  auto& s = state.stepper;
  s.step = static_cast<int>(steps[0]), s.attempts = static_cast<int>(steps[1]);
  s.started = steps[2] != 0, state.exodusSteps = static_cast<int>(steps[3]);
  s.time = times[0], s.loadFactor = times[1], s.size = times[2], s.bodyWork = times[3];
  for (long long c = 0; c < contributions[0]; ++c)
    state.contributions.push_back(file.numbers("contribution_" + std::to_string(c)));
  const auto nodal = file.rows("nodal_state", 0, file.shape("nodal_state").first);
  for (std::size_t k = 0; k + 3 < nodal.size(); k += 4) {
    s.nodalDofs.push_back(static_cast<GO>(nodal[k]));
    s.nodalU.push_back(nodal[k + 1]), s.nodalV.push_back(nodal[k + 2]);
    s.nodalA.push_back(nodal[k + 3]);
  }
}

// Rows `keep` (ascending) of a particle variable, read in chunks, into field `view`.
template <class View>
void readParticleField(const CheckpointReader& file, const std::string& name, std::size_t total,
                       const std::vector<std::size_t>& keep, const View& view) {
  const int width = fieldWidth(view);
  if (file.shape(name) != std::make_pair(total, static_cast<std::size_t>(width)))
    throw FileError(file.path(), "variable '" + name + "' has the wrong shape");
  std::size_t next = 0;  // index into keep
  for (std::size_t first = 0; first < total; first += kChunk) {
    const std::size_t count = std::min(kChunk, total - first);
    std::vector<double> values;
    if constexpr (std::is_integral_v<typename View::non_const_value_type>) {
      const auto integers = file.integerRows(name, first, count);
      values.assign(integers.begin(), integers.end());
    } else {
      values = file.rows(name, first, count);
    }
    for (; next < keep.size() && keep[next] < first + count; ++next)
      for (int c = 0; c < width; ++c)
        setFieldComponent(view, next, c, values[(keep[next] - first) * width + c]);
  }
}

}  // namespace

namespace {

// A checkpoint written with other values of the parameters that define the problem (a
// modulus, a boundary value, the time step) continued silently into a run that matched
// neither: refused, unless allowed, and then each change is printed and returned.
std::vector<std::string> requireSamePhysics(const CheckpointReader& file,
                                            const RunIdentity& identity, const Comm& comm) {
  if (!file.hasAttribute("physics"))
    return {};  // written before the checkpoints recorded it
  auto changes = physicsChanges(file.text("physics"), identity.physics);
  if (changes.empty())
    return changes;
  if (!identity.allowPhysicsChange) {
    std::string listedChanges;
    for (const auto& c : changes)
      listedChanges += (listedChanges.empty() ? "" : "; ") + c;
    throw FileError(file.path(),
                    "was written with other values of parameters that define the problem (" +
                        listedChanges +
                        "); a restart may change only Output, Solver, Verification, Load Balance "
                        "and Time Integration/Final Time, or add --allow-physics-change to go on "
                        "with this deck's values");
  }
  if (comm.getRank() == 0)
    for (const auto& c : changes)
      std::cout << "impm: note: the restart changes " << c << " (--allow-physics-change)\n";
  return changes;
}

}  // namespace

template <int Dim>
RunState<Dim> readCheckpoint(const std::string& path, const RunIdentity& identity,
                             const Decomposition<Dim>& decomposition, bool byReference,
                             ParticleSet<Dim>& particles, MultiVector& gridFields,
                             const Teuchos::RCP<const Comm>& comm) {
  RunState<Dim> state;
  collectively(*comm, [&] {
    const CheckpointReader file(path);
    const std::string difference = identityDifference(file, identity);
    if (!difference.empty())
      throw FileError(path, difference);
    state.physicsChanges = requireSamePhysics(file, identity, *comm);
    readStepperState(file, state);
    // Each rank keeps the particles in its cells, in id order.
    const auto total = static_cast<std::size_t>(identity.particles);
    const std::string place = particleVariable(byReference ? "X" : "x");
    std::vector<std::size_t> keep;
    for (std::size_t first = 0; first < total; first += kChunk) {
      const std::size_t count = std::min(kChunk, total - first);
      const auto x = file.rows(place, first, count, false);  // checked when read as a field
      for (std::size_t r = 0; r < count; ++r)
        if (decomposition.ownerOfPoint(&x[r * Dim]) == comm->getRank())
          keep.push_back(first + r);
    }
    auto host = particles.mirror(Kokkos::DefaultHostExecutionSpace());
    host.resize(keep.size());
    host.forEachField([&](const FieldSpec& spec, auto& view) {
      if (!spec.checkpoint)
        return;
      if (!file.has(particleVariable(spec.name)))
        throw FileError(path, "has no particle field '" + spec.name + "'");
      readParticleField(file, particleVariable(spec.name), total, keep, view);
    });
    const auto [rows, columns] = file.shape("grid_fields");
    if (rows != gridFields.getGlobalLength() || columns != gridFields.getNumVectors())
      throw FileError(path, "its grid fields do not fit this grid's");
    const auto grid = file.rows("grid_fields", 0, rows);
    const auto& map = *gridFields.getMap();
    for (std::size_t i = 0; i < map.getNodeNumElements(); ++i)
      for (std::size_t c = 0; c < columns; ++c)
        gridFields.replaceLocalValue(static_cast<LO>(i), c,
                                     grid[map.getGlobalElement(static_cast<LO>(i)) * columns + c]);
    file.checkSums();
    particles.copyFrom(host);
  });
  return state;
}

Partition readPartition(const std::string& path, const Comm& comm) {
  Partition partition;
  collectively(comm, [&] {
    const CheckpointReader file(path);
    if (!file.has("cell_owners"))
      return;  // blocks
    const auto ranks = file.integers("partition_ranks");
    const auto imbalance = file.numbers("partition_imbalance");
    if (ranks.size() != 1 || imbalance.size() != 1)
      throw FileError(path, "has a malformed partition");
    partition.ranks = static_cast<int>(ranks[0]);
    partition.imbalanceAfterRepartition = imbalance[0];
    const auto owners = file.integerRows("cell_owners", 0, file.shape("cell_owners").first);
    partition.cellOwners.assign(owners.begin(), owners.end());
    file.checkSums();
  });
  return partition;
}

CheckpointSeries::CheckpointSeries(const Teuchos::ParameterList& output,
                                   const std::string& directory, const std::string& prefix)
    : every_(output.get<int>("Checkpoint Every")),
      kept_(output.get<int>("Checkpoints Kept")),
      directory_(directory),
      prefix_(prefix) {}

bool CheckpointSeries::due(int step, bool last) const {
  return every_ > 0 && (step % every_ == 0 || last);
}

std::string CheckpointSeries::pathOf(int step) const {
  std::ostringstream s;
  s << directory_ << "/" << prefix_ << "_checkpoint_" << std::setw(6) << std::setfill('0') << step
    << ".nc";
  return s.str();
}

void CheckpointSeries::written(int step) {
  namespace fs = std::filesystem;
  std::error_code error;
  // The newest, under a fixed name: a link replaced in one rename.
  const fs::path link = fs::path(directory_) / (prefix_ + "_checkpoint.nc");
  const fs::path staged = link.string() + ".link";
  fs::remove(staged, error);
  fs::create_symlink(fs::path(pathOf(step)).filename(), staged, error);
  if (!error)
    fs::rename(staged, link, error);
  if (kept_ <= 0)
    return;
  // The checkpoints of this prefix in the directory, oldest first; unfinished ones go.
  std::vector<std::pair<int, fs::path>> found;
  const std::string head = prefix_ + "_checkpoint_";
  for (const auto& entry : fs::directory_iterator(directory_, error)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(head, 0) != 0)
      continue;
    const std::string rest = name.substr(head.size());
    if (rest.size() > 7 && rest.compare(rest.size() - 7, 7, ".nc.tmp") == 0) {
      fs::remove(entry.path(), error);
      continue;
    }
    if (rest.size() == 9 && rest.compare(6, 3, ".nc") == 0 &&
        std::all_of(rest.begin(), rest.begin() + 6, ::isdigit))
      found.emplace_back(std::stoi(rest.substr(0, 6)), entry.path());
  }
  std::sort(found.begin(), found.end());
  for (std::size_t k = 0; k + kept_ < found.size(); ++k)
    if (found[k].first != step)
      fs::remove(found[k].second, error);
}

#define IMPM_INSTANTIATE(D)                                                                       \
  template RunIdentity runIdentity<D>(const Teuchos::ParameterList&, const GridGeometry<D>&,      \
                                      const ParticleSet<D>&, GlobalId, const Comm&);              \
  template void writeCheckpoint<D>(const std::string&, const RunIdentity&, const ParticleSet<D>&, \
                                   GlobalId, const RunState<D>&, const MultiVector&);             \
  template RunState<D> readCheckpoint<D>(const std::string&, const RunIdentity&,                  \
                                         const Decomposition<D>&, bool, ParticleSet<D>&,          \
                                         MultiVector&, const Teuchos::RCP<const Comm>&);
IMPM_INSTANTIATE(1)
IMPM_INSTANTIATE(2)
IMPM_INSTANTIATE(3)
#undef IMPM_INSTANTIATE

}  // namespace impm

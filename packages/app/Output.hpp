#pragma once
// What a run writes (the output contract of doc/design.md), all gathered to rank 0 so that
// the files do not depend on the number of ranks:
//  <prefix>_grid.exo       grid nodes and cells (BAR2 / QUAD4) with nodal fields
//  <prefix>_particles.exo  one SPHERE element per particle at its reference position, with
//                          displacementX... as nodal fields (ParaView moves the points) and
//                          the other particle fields as element variables
//  <prefix>_domains.exo    2-D gimp and cpdi: each particle's domain as a QUAD4 cell at its
//                          reference corners, with the corners' displacementX, Y as nodal
//                          fields (ParaView's Warp By Vector draws the deformed domains)
//  <prefix>_particles.csv  the particles at the last output step, sorted by id
//  <prefix>_history.csv    one row per step

#include <Teuchos_ParameterList.hpp>

#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/NodeOwnership.hpp"
#include "core/ParticleSet.hpp"
#include "io/CsvFile.hpp"
#include "io/ExodusFile.hpp"

namespace impm {

Teuchos::ParameterList outputValidParameters();
// The names of Output/Fields (empty: every output field).
std::vector<std::string> outputFields(const Teuchos::ParameterList& output);

// One column of the particle tables: a component of a registry field, with its CSV name and
// its Exodus element-variable name ("" when it is not one).
struct TableColumn {
  std::string field;
  int component = 0;
  std::string csv, exodus;
};

// The output columns of the particle set's fields named in `fields` (all output fields
// when empty; id always), in registry order.  Throws InputError("Output/Fields") naming a
// field that is not an output field, with a suggestion.
template <int Dim>
std::vector<TableColumn> outputColumns(const ParticleSet<Dim>& particles,
                                       const std::vector<std::string>& fields = {});

// Particle fields sorted by id, a row per particle.
struct ParticleTable {
  std::vector<std::string> names;  // CSV names
  std::vector<std::vector<double>> columns;
  const std::vector<double>& column(const std::string& name) const;
};
// Where gatherParticles puts the rows: all on rank 0 (empty elsewhere), or in consecutive
// blocks of ids of about equal size, rank 0 the first.
enum class TableRows { onRoot, inBlocks };
// Collective: the table of `columns`.
template <int Dim>
ParticleTable gatherParticles(const ParticleSet<Dim>& particles,
                              const Teuchos::RCP<const Comm>& comm, GlobalId totalParticles,
                              const std::vector<TableColumn>& columns, TableRows rows);
// Collective: every output column.
template <int Dim>
ParticleTable gatherParticles(const ParticleSet<Dim>& particles,
                              const Teuchos::RCP<const Comm>& comm, GlobalId totalParticles,
                              TableRows rows = TableRows::onRoot);

// A restarted run continues the files of the run it restarts: the history keeps its rows
// through `step`, the Exodus files their first `exodusSteps` time steps.
struct OutputResume {
  int step = 0;
  int exodusSteps = 0;
  std::vector<std::string> notes;  // lines for the history at the restart (CsvHistory)
};

template <int Dim>
class Output {
 public:
  // The particle domains to draw: none, the box of half-widths r1_x, r2_y (gimp), the
  // parallelogram spanned by r1, r2 (cpdi), the tracked corners (mesh bodies).
  enum class Domains { none, box, parallelogram, corners };
  // Creates the directory and the files (rank 0).  Collective.  The particle columns are
  // those of the fields of Output/Fields (outputColumns).
  Output(const Teuchos::ParameterList& params, const std::string& directory,
         const std::string& prefix, const NodeOwnership<Dim>& ownership,
         const ParticleSet<Dim>& particles, GlobalId totalParticles,
         const std::vector<std::string>& historyColumns,
         const std::vector<std::string>& gridFieldNames,
         const std::vector<std::string>& globalNames, Domains domains = Domains::none,
         const OutputResume* resume = nullptr);

  bool due(int step) const { return step % every_ == 0; }
  // Whether any particle or grid field file is written (the history always is).
  bool writesFields() const { return csv_ || exodus_; }
  // Particle and grid fields at `time`.  gridFields: the named columns on the node map.
  // Collective.
  void writeFields(double time, const ParticleSet<Dim>& particles, const MultiVector& gridFields,
                   const std::vector<double>& globals);
  // The initial state's fields after a fresh start: the particles as the constructor read
  // them (it gathered them for the Exodus meshes; the caller changes none in between), so that
  // they are not gathered twice.  Once, not after a restart.  Collective.
  void writeInitialFields(double time, const MultiVector& gridFields,
                          const std::vector<double>& globals);
  // Rank 0 appends the row; a failed write stops every rank.  Collective.
  void appendHistory(const std::vector<double>& row) const;
  // Paths of the files written, for the user.
  std::vector<std::string> files() const;
  // Time steps in the Exodus files so far (the same on every rank).
  int exodusSteps() const { return exodusSteps_; }

 private:
  // The files a fresh start writes under base (directory/prefix).
  std::vector<std::string> plannedFiles(const std::string& base) const;
  // FileError naming the first of `paths` that exists and cannot be opened for writing.
  static void requireWritable(const std::vector<std::string>& paths);
  // Where the gathered rows go: every row on rank 0 for the Exodus files, which then writes
  // the CSV from them too (one gather per write, where the CSV's blocks of ids on every rank
  // took a second one and their formatting in parallel did not pay for it,
  // doc/performance.md); without the Exodus files, the CSV's blocks on every rank.
  TableRows tableRows() const { return exodus_ ? TableRows::onRoot : TableRows::inBlocks; }
  void write(double time, const ParticleTable& table, const MultiVector& gridFields,
             const std::vector<double>& globals);
  ExodusMesh domainMesh(const ParticleTable& table) const;
  std::vector<std::vector<double>> domainDisplacements(const ParticleTable& table) const;
  std::vector<std::vector<double>> elementValues(const ParticleTable& table) const;

  const NodeOwnership<Dim>& ownership_;
  Domains domains_;
  bool root_;
  int every_;
  bool exodus_, csv_;
  GlobalId totalParticles_;
  std::size_t gridFields_;
  std::string directory_, prefix_;
  // The CSV's columns, the Exodus element variables, and all columns gathered (theirs and
  // the points' and domains' geometry).
  std::vector<TableColumn> csvColumns_, exodusColumns_, gathered_;
  int exodusSteps_ = 0;
  std::unique_ptr<ExodusFile> gridFile_, particleFile_, domainFile_;
  std::unique_ptr<CsvHistory> history_;
  std::optional<ParticleTable> initial_;  // the constructor's, until writeInitialFields
};

}  // namespace impm

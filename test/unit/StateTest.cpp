// A law with state, written the way doc/design.md ("How to add a law with state") says, run
// through a whole simulation: the framework commits its state when a step is accepted and
// drops it on a cutback, writes it to the particle CSV and Exodus files, and restarts it.

#include <gtest/gtest.h>

#include <Teuchos_DefaultComm.hpp>

#include <exodusII.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "app/AppParameters.hpp"
#include "app/Simulation.hpp"
#include "core/Errors.hpp"
#include "core/Parameters.hpp"
#include "material/MaterialFactory.hpp"

namespace impm {
namespace {

// 1-D Hooke's law, P = E (F - 1), that counts the steps its particles accepted and refuses a
// step whose strain increment exceeds Largest Increment (a NumericalError, which cuts the
// step back).  Its state: accepted_steps (written to the outputs) and the strain of the last
// accepted step, last_strain; both must be rolled back on a cutback for the count and the
// refusals to come out right.
class CountingLaw : public Material<1> {
 public:
  static const char* model() { return "counting"; }
  static Teuchos::ParameterList validParameters() {
    Teuchos::ParameterList valid;
    declareDouble(valid, "E", 1.0, "modulus", Bounds::positive(), true);
    declareDouble(valid, "Largest Increment", 1.0, "largest strain increment of a step",
                  Bounds::positive(), true);
    return valid;
  }
  CountingLaw(const std::string& name, const Teuchos::ParameterList& params)
      : Material<1>(name, params.get<double>("Density")),
        E_(params.get<double>("E")),
        largest_(params.get<double>("Largest Increment")) {}

  std::vector<Variable> variables() const override {
    FieldSpec count;
    count.name = "accepted_steps", count.twoLevels = true;
    count.columns = defaultColumns<1>(count.name, FieldShape::scalar);
    FieldSpec strain;
    strain.name = "last_strain", strain.twoLevels = true;
    return {{count, {0.0}}, {strain, {0.0}}};
  }

  void firstPiola(const Evaluation& at, Tensors& P, Tangents& A) const override {
    const auto members = at.members;
    const auto F = at.F;
    const auto count = at.variables[0], strain = at.variables[1];
    const auto countTrial = at.trial[0], strainTrial = at.trial[1];
    const double E = E_, largest = largest_;
    int refused = 0;
    Kokkos::parallel_reduce(
        "CountingLaw", RangePolicy<ExecutionSpace>(0, members.extent(0)),
        KOKKOS_LAMBDA(const int i, int& bad) {
          const int p = members(i);
          const double e = F(p, 0, 0) - 1.0;
          P(p, 0, 0) = E * e;
          A(p, 0, 0, 0, 0) = E;
          countTrial(p, 0) = count(p, 0) + 1.0;
          strainTrial(p, 0) = e;
          const double increment = e - strain(p, 0);
          bad += increment > largest * (1 + 1e-12) || -increment > largest * (1 + 1e-12);
        },
        refused);
    if (refused)
      throw NumericalError("the strain increment exceeds the counting law's limit");
  }
  void energyDensity(const Evaluation& at, Scalars& W) const override {
    const auto F = at.F;
    const double E = E_;
    setForMembers<ExecutionSpace>(
        "CountingLaw::energy", at.members, W, KOKKOS_LAMBDA(const int p) {
          const double e = F(p, 0, 0) - 1.0;
          return 0.5 * E * e * e;
        });
  }
  double maxModulus(const Evaluation&) const override { return E_; }

 private:
  double E_, largest_;
};

// A bar [0, 1], fixed at the left, pulled at the right by an end force ramped to 1 in two
// load steps: uniform strain 1 at the end.  Increments of 0.5 are refused and 0.25 taken:
// load factors 0.25, 0.5, 0.75, 1 accepted after 3 cutbacks (the step size grows back to
// 0.5 after every accepted step and is cut again).
Teuchos::ParameterList countingDeck(const std::string& directory) {
  Teuchos::ParameterList deck;
  auto& d = deck.sublist("Discretization");
  d.set("Method", std::string("fem"));
  auto& g = deck.sublist("Grid");
  g.set("Cells", Teuchos::Array<int>(std::vector<int>{8}));
  g.set("Length", Teuchos::Array<double>(std::vector<double>{1.0}));
  auto& m = deck.sublist("Materials").sublist("counter");
  m.set("Model", std::string("counting")), m.set("E", 1.0), m.set("Largest Increment", 0.3);
  auto& b = deck.sublist("Bodies").sublist("bar");
  b.set("Material", std::string("counter"));
  b.set("Extent", Teuchos::Array<double>(std::vector<double>{0.0, 1.0}));
  auto& left = deck.sublist("Boundary Conditions").sublist("fixed");
  left.set("Body", std::string("bar")), left.set("End", std::string("left"));
  left.set("alpha", 0.0), left.set("beta", 1.0);
  auto& right = deck.sublist("Boundary Conditions").sublist("pull");
  right.set("Body", std::string("bar")), right.set("End", std::string("right"));
  right.set("alpha", 1.0), right.set("beta", 0.0), right.set("gamma", 1.0);
  deck.sublist("Time Integration").set("Load Steps", 2);
  auto& o = deck.sublist("Output");
  o.set("Directory", directory), o.set("Checkpoint Every", 2), o.set("Checkpoints Kept", 0);
  deck.sublist("Solver").set("Print Iterations", false);
  validateParameters(deck, deckValidParameters());
  return deck;
}

std::vector<std::vector<double>> readCsv(const std::string& path, const std::string& column,
                                         std::size_t* index = nullptr) {
  std::ifstream in(path);
  std::string line, cell;
  std::getline(in, line);
  std::stringstream header(line);
  std::size_t c = 0, wanted = std::string::npos;
  for (; std::getline(header, cell, ','); ++c)
    if (cell == column)
      wanted = c;
  if (index)
    *index = wanted;
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::stringstream s(line);
    rows.emplace_back();
    while (std::getline(s, cell, ','))
      rows.back().push_back(std::stod(cell));
  }
  return rows;
}

TEST(LawWithState, CommitsAcceptedStepsRollsBackCutbacksWritesAndRestarts) {
  static bool registered = false;
  if (!registered)
    registerMaterialModel(materialModel<CountingLaw>()), registered = true;
  auto comm = Teuchos::DefaultComm<int>::getComm();
  const std::string dir = "counting_law_np" + std::to_string(comm->getSize());
  if (comm->getRank() == 0)  // one rank: two removing the same files would race
    std::filesystem::remove_all(dir);
  comm->barrier();
  const auto deck = countingDeck(dir);
  {
    Simulation<1> run(deck, "counting.xml", dir, comm);
    EXPECT_TRUE(run.run().empty());
    const auto host = run.particles().mirror(Kokkos::DefaultHostExecutionSpace());
    for (std::size_t p = 0; p < host.size(); ++p) {
      EXPECT_EQ(host.values("accepted_steps")(p, 0), 4.0);  // N = 4, not N + k = 7
      EXPECT_NEAR(host.values("last_strain")(p, 0), 1.0, 1e-12);
    }
  }
  comm->barrier();
  // The history: 4 steps taken in 7 attempts; the state in the particle CSV and Exodus file.
  std::size_t attemptsColumn = 0, stateColumn = 0;
  const auto history = readCsv(dir + "/counting_history.csv", "attempts", &attemptsColumn);
  ASSERT_EQ(history.size(), 5u);
  double attempts = 0;
  for (std::size_t k = 1; k < history.size(); ++k)
    attempts += history[k][attemptsColumn];
  EXPECT_EQ(attempts, 7.0);
  const auto table = readCsv(dir + "/counting_particles.csv", "accepted_steps", &stateColumn);
  ASSERT_NE(stateColumn, std::string::npos);
  for (const auto& row : table)
    EXPECT_EQ(row[stateColumn], 4.0);
  if (comm->getRank() == 0) {
    int cpu = sizeof(double), io = 0;
    float version = 0;
    const int exo =
        ex_open((dir + "/counting_particles.exo").c_str(), EX_READ, &cpu, &io, &version);
    ASSERT_GE(exo, 0);
    int count = 0;
    ex_get_variable_param(exo, EX_ELEM_BLOCK, &count);
    std::vector<std::vector<char>> names(count, std::vector<char>(MAX_STR_LENGTH + 1));
    std::vector<char*> pointers;
    for (auto& n : names)
      pointers.push_back(n.data());
    ex_get_variable_names(exo, EX_ELEM_BLOCK, count, pointers.data());
    bool found = false;
    for (auto& n : names)
      found = found || std::string(n.data()) == "accepted_steps";
    EXPECT_TRUE(found);
    ex_close(exo);
  }
  // From the checkpoint of step 2 the restarted run takes steps 3 and 4 (one cutback) and
  // ends with the same count.
  {
    Simulation<1> run(deck, "counting.xml", dir, comm, dir + "/counting_checkpoint_000002.nc");
    EXPECT_TRUE(run.run().empty());
    const auto host = run.particles().mirror(Kokkos::DefaultHostExecutionSpace());
    for (std::size_t p = 0; p < host.size(); ++p)
      EXPECT_EQ(host.values("accepted_steps")(p, 0), 4.0);
  }
  comm->barrier();
  EXPECT_EQ(readCsv(dir + "/counting_history.csv", "attempts").size(), 5u);
}

}  // namespace
}  // namespace impm

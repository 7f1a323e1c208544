// app: integration points from bodies (material points and FEM Gauss points, cut cells
// included), ids independent of the rank count, and output gathered by id.

#include <gtest/gtest.h>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultComm.hpp>

#include "app/Bodies.hpp"
#include "app/Output.hpp"
#include "core/Errors.hpp"
#include "core/NodeOwnership.hpp"
#include "core/Parameters.hpp"
#include "material/MaterialFactory.hpp"

namespace impm {
namespace {

Teuchos::ParameterList deckWithBar(double lower, double upper, int perCell) {
  Teuchos::ParameterList deck;
  auto& mat = deck.sublist("Materials").sublist("steel");
  mat.set("Model", std::string("linear")), mat.set("E", 1.0), mat.set("Density", 2.0);
  validateParameters(mat, materialValidParameters());
  auto& bar = deck.sublist("Bodies").sublist("bar");
  bar.set("Material", std::string("steel"));
  bar.set("Extent", Teuchos::Array<double>(std::vector<double>{lower, upper}));
  bar.set("Particles Per Cell", perCell);
  bar.set("Section", std::string("1 + x"));
  validateParameters(bar, bodyValidParameters());
  return deck;
}

struct Totals {
  GlobalId count = 0;
  double volume = 0, mass = 0;
};

Totals totals(const ParticleSet<1>& ps, const Comm& comm) {
  auto V = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), ps.volume);
  auto m = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), ps.mass);
  double local[2] = {0, 0}, global[2];
  for (std::size_t p = 0; p < ps.size(); ++p)
    local[0] += V(p), local[1] += m(p);
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, 2, local, global);
  Totals t;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, GlobalId(ps.size()), Teuchos::outArg(t.count));
  t.volume = global[0], t.mass = global[1];
  return t;
}

TEST(Bodies, MaterialPointsAndGaussPointsFillTheBody) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  // The bar [0, 1] on a grid of 8 cells over [0, 1.3]: the end cuts a cell.
  NodeOwnership<1> own(makeGridGeometry<1>({0.0}, {1.3}, {8}), comm);
  const auto deck = deckWithBar(0.0, 1.0, 3);
  Bodies<1> bodies(deck, {"steel"}, own.grid());
  std::vector<std::shared_ptr<Material<1>>> mats = {
      createMaterial<1>("steel", deck.sublist("Materials").sublist("steel"))};
  // Material points: round(3 * 1 / 0.1625) = 18 equal particles.
  const auto mp =
      totals(bodies.createParticles(Method::gimp, own.decomposition(), comm->getRank(), mats, true),
             *comm);
  EXPECT_EQ(mp.count, 18);
  EXPECT_NEAR(mp.volume, 1.0, 1e-14);
  // Gauss points: 2 per cell on the part of each cell inside the bar (7 cells, the 7th cut).
  const auto gp = totals(
      bodies.createParticles(Method::fem, own.decomposition(), comm->getRank(), mats, true), *comm);
  EXPECT_EQ(gp.count, 14);
  EXPECT_NEAR(gp.volume, 1.0, 1e-14);
  // Mass = density * integral of the section 1 + x: Gauss points are exact for it.
  EXPECT_NEAR(gp.mass, 2.0 * 1.5, 1e-14);
}

TEST(Bodies, ABodyOutsideTheGridIsAnInputError) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  NodeOwnership<1> own(makeGridGeometry<1>({0.0}, {1.0}, {8}), comm);
  try {
    Bodies<1> bodies(deckWithBar(-0.1, 1.0, 2), {"steel"}, own.grid());
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.path(), "Bodies/bar/Extent");
  }
}

TEST(Output, ParticlesAreGatheredSortedById) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  NodeOwnership<1> own(makeGridGeometry<1>({0.0}, {1.0}, {10}), comm);
  const auto deck = deckWithBar(0.0, 1.0, 2);
  Bodies<1> bodies(deck, {"steel"}, own.grid());
  std::vector<std::shared_ptr<Material<1>>> mats = {
      createMaterial<1>("steel", deck.sublist("Materials").sublist("steel"))};
  const auto ps =
      bodies.createParticles(Method::cpdi, own.decomposition(), comm->getRank(), mats, true);
  const auto table = gatherParticles(ps, comm, 20);
  if (comm->getRank() != 0)
    return;
  const auto& id = table.column("id");
  const auto& X = table.column("X");
  ASSERT_EQ(id.size(), 20u);
  for (std::size_t p = 0; p < 20; ++p) {
    EXPECT_EQ(id[p], double(p));
    EXPECT_NEAR(X[p], (p + 0.5) / 20.0, 1e-15);
  }
}

}  // namespace
}  // namespace impm

// app: integration points from bodies (material points and FEM Gauss points, cut cells
// included), ids independent of the rank count, output gathered by id, and the grid
// output's fields.

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultComm.hpp>

#include "app/Bodies.hpp"
#include "app/GridFields.hpp"
#include "app/Output.hpp"
#include "app/shapes/Mesh.hpp"
#include "core/Errors.hpp"
#include "core/NodeOwnership.hpp"
#include "core/Parameters.hpp"
#include "io/MeshFile.hpp"
#include "material/MaterialFactory.hpp"
#include "material/MaterialState.hpp"
#include "solver/GridSystem.hpp"

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

// 2-D shapes: a rectangle on grid lines is filled exactly; a disk and a triangle get the
// sub-cells whose centres they contain, counted here independently of the code.
Teuchos::ParameterList shapeDeck(const std::string& shape, int perCell) {
  Teuchos::ParameterList deck;
  auto& mat = deck.sublist("Materials").sublist("rubber");
  mat.set("Model", std::string("neo-hookean")), mat.set("E", 1.0), mat.set("nu", 0.0);
  mat.set("Density", 2.0);
  validateParameters(mat, materialValidParameters());
  auto& b = deck.sublist("Bodies").sublist("body");
  b.set("Material", std::string("rubber"));
  b.set("Shape", shape);
  b.set("Particles Per Cell", perCell);
  const auto A = [](std::vector<double> v) { return Teuchos::Array<double>(v); };
  if (shape == "rectangle")
    b.set("Lower Corner", A({0.25, 0.5})), b.set("Upper Corner", A({0.75, 1.0}));
  else if (shape == "disk")
    b.set("Center", A({0.5, 0.5})), b.set("Radius", 0.3);
  else
    b.set("Vertices", A({0.1, 0.1, 0.9, 0.1, 0.1, 0.9}));  // a right triangle
  validateParameters(b, bodyValidParameters());
  return deck;
}

TEST(Bodies, ShapesFill2DCellsOnSubCells) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  NodeOwnership<2> own(makeGridGeometry<2>({0.0, 0.0}, {1.0, 1.0}, {8, 8}), comm);
  const double sub = 1.0 / 24;  // 3 x 3 particles per cell of 1/8
  for (const std::string shape : {"rectangle", "disk", "polygon"}) {
    const auto deck = shapeDeck(shape, 3);
    Bodies<2> bodies(deck, {"rubber"}, own.grid());
    std::vector<std::shared_ptr<Material<2>>> mats = {
        createMaterial<2>("rubber", deck.sublist("Materials").sublist("rubber"))};
    const auto ps =
        bodies.createParticles(Method::cpdi, own.decomposition(), comm->getRank(), mats, true);
    GlobalId expected = 0;
    for (int j = 0; j < 24; ++j)
      for (int i = 0; i < 24; ++i) {
        const double x = (i + 0.5) * sub, y = (j + 0.5) * sub;
        if (shape == "rectangle")
          expected += x >= 0.25 && x <= 0.75 && y >= 0.5 && y <= 1.0;
        else if (shape == "disk")
          expected += (x - 0.5) * (x - 0.5) + (y - 0.5) * (y - 0.5) <= 0.09;
        else
          expected += x >= 0.1 && y >= 0.1 && x + y <= 1.0;
      }
    GlobalId count = 0;
    Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, GlobalId(ps.size()), Teuchos::outArg(count));
    EXPECT_EQ(count, expected) << shape;
    auto V = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), ps.volume);
    auto r = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), ps.domain);
    for (std::size_t p = 0; p < ps.size(); ++p) {
      EXPECT_NEAR(V(p), sub * sub, 1e-15);
      EXPECT_NEAR(r(p, 0, 0), sub / 2, 1e-15);
      EXPECT_NEAR(r(p, 1, 1), sub / 2, 1e-15);
    }
  }
}

// The 20 cpdi particles of a bar over [0, 1] on 10 cells, as this rank holds them.
struct BarOfTwentyParticles {
  Teuchos::RCP<const Teuchos::Comm<int>> comm = Teuchos::DefaultComm<int>::getComm();
  NodeOwnership<1> own{makeGridGeometry<1>({0.0}, {1.0}, {10}), comm};
  Teuchos::ParameterList deck = deckWithBar(0.0, 1.0, 2);
  Bodies<1> bodies{deck, {"steel"}, own.grid()};
  std::vector<std::shared_ptr<Material<1>>> mats = {
      createMaterial<1>("steel", deck.sublist("Materials").sublist("steel"))};
  ParticleSet<1> ps =
      bodies.createParticles(Method::cpdi, own.decomposition(), comm->getRank(), mats, true);
};

TEST(Output, ParticlesAreGatheredSortedById) {
  BarOfTwentyParticles bar;
  auto& [comm, own, deck, bodies, mats, ps] = bar;
  // Stored out of id order (reversed): the table sorts them, on one rank as on several.
  for (std::size_t p = 0, q = ps.size(); p + 1 < q; ++p, --q) {
    std::swap(ps.id(p), ps.id(q - 1));
    std::swap(ps.X(p, 0), ps.X(q - 1, 0));
  }
  const auto table = gatherParticles(ps, comm, 20);
  // In blocks: consecutive ids on every rank, the blocks in rank order and covering 0..19.
  const auto block = gatherParticles(ps, comm, 20, TableRows::inBlocks);
  const auto& blockId = block.column("id");
  double rowsThrough = 0.0;  // inclusive scan: the rows up to and including this rank's
  const double rows = static_cast<double>(blockId.size());
  Teuchos::scan(*comm, Teuchos::REDUCE_SUM, rows, Teuchos::outArg(rowsThrough));
  for (std::size_t k = 0; k < blockId.size(); ++k) {
    EXPECT_EQ(blockId[k], rowsThrough - rows + k);
    EXPECT_NEAR(block.column("X")[k], (blockId[k] + 0.5) / 20.0, 1e-15);
  }
  double total = 0.0;
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, rows, Teuchos::outArg(total));
  EXPECT_EQ(total, 20.0);
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

// The initial state is written from the table the constructor gathered for the Exodus
// meshes (the particles as it read them: one gather for both), a later state from the
// particles at its write; the initial state is written once.
TEST(Output, InitialStateIsTheConstructorsTable) {
  BarOfTwentyParticles bar;
  auto& [comm, own, deck, bodies, mats, ps] = bar;
  const auto params = outputValidParameters();  // CSV and Exodus
  const std::string directory = "output_test_initial";
  Output<1> output(params, directory, "bar", own, ps, 20, {"step"}, {"mass"}, {"F0"});
  const MultiVector grid(own.nodeMap(), 1);
  const auto uColumn = [&] {  // the particle CSV's u, read on rank 0
    std::ifstream in(directory + "/bar_particles.csv");
    std::string line, cell;
    std::getline(in, line);
    std::istringstream header(line);
    std::size_t column = 0;
    while (std::getline(header, cell, ',') && cell != "u")
      ++column;
    std::vector<double> u;
    while (std::getline(in, line)) {
      std::istringstream row(line);
      for (std::size_t c = 0; c <= column; ++c)
        std::getline(row, cell, ',');
      u.push_back(std::stod(cell));
    }
    return u;
  };
  Kokkos::deep_copy(ps.u, 0.25);  // after the constructor read the particles
  output.writeInitialFields(0.0, grid, {0.0});
  comm->barrier();
  if (comm->getRank() == 0) {
    EXPECT_EQ(uColumn(), std::vector<double>(20, 0.0));
  }
  EXPECT_THROW(output.writeInitialFields(0.0, grid, {0.0}), std::logic_error);
  output.writeFields(1.0, ps, grid, {0.0});
  comm->barrier();
  if (comm->getRank() == 0) {
    EXPECT_EQ(uColumn(), std::vector<double>(20, 0.25));
    std::filesystem::remove_all(directory);
  }
}

// Output/Fields selects registry fields: id always, then the named fields' columns in the
// registry's order; a misspelt name is refused with a suggestion.
TEST(Output, FieldsAreSelectedFromTheRegistry) {
  ParticleSet<2> ps(1);
  FieldSpec eqps;
  eqps.name = "eqps", eqps.columns = defaultColumns<2>("eqps", FieldShape::scalar);
  ps.declare(eqps);
  std::vector<std::string> names;
  for (const auto& c : outputColumns(ps, {"eqps", "v", "stress"}))
    names.push_back(c.csv + "/" + c.exodus);
  EXPECT_EQ(names, (std::vector<std::string>{"id/", "stress_xx/stress_xx", "stress_yy/stress_yy",
                                             "stress_xy/stress_xy", "v_x/velocityX",
                                             "v_y/velocityY", "eqps/eqps"}));
  EXPECT_EQ(outputColumns(ps).back().csv, "eqps");  // every output field, the declared last
  try {
    outputColumns(ps, {"stres"});
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.path(), "Output/Fields");
    EXPECT_NE(std::string(e.what()).find("'stres' is not an output field (did you mean 'stress'?)"),
              std::string::npos)
        << e.what();
  }
}

// The grid output's fields: the displacement sums the steps' increments; the velocity and
// mass are the last step's, copied in only when read (an output or a checkpoint), also when
// the unknowns changed since (a step on other nodes: the step before's values are copied on
// the unknowns they were made for, and the nodes without unknown read 0).
TEST(GridFields, DisplacementAccumulatesVelocityAndMassAreTheLastSteps) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  NodeOwnership<1> own(makeGridGeometry<1>({0.0}, {1.0}, {8}), comm);
  // The bar [0, upper] by fem, its particles and laws kept with the system that reads them.
  struct Bar {
    Materials<1> mats;
    ParticleSet<1> ps;
    std::unique_ptr<GridSystem<1>> system;
  };
  const auto bar = [&](double upper) {
    const auto deck = deckWithBar(0.0, upper, 2);
    Bodies<1> bodies(deck, {"steel"}, own.grid());
    auto b = std::make_unique<Bar>();
    b->mats = {createMaterial<1>("steel", deck.sublist("Materials").sublist("steel"))};
    b->ps =
        bodies.createParticles(Method::fem, own.decomposition(), comm->getRank(), b->mats, true);
    declareMaterialVariables(b->ps, b->mats), initializeMaterials(b->ps, b->mats, true);
    b->system =
        std::make_unique<GridSystem<1>>(own, Method::fem, Kinematics::totalLagrangian, b->ps,
                                        b->mats, GridSystem<1>::Contributions{}, 1.0, 1.0);
    return b;
  };
  // The values of a step, a function of the node and the step (no Robin end here: every
  // unknown is a node's).
  const auto stepVector = [](const GridSystem<1>& s, double step, double scale) {
    auto v = Teuchos::rcp(new Vector(s.unknownMap()));
    auto data = v->getDataNonConst();
    for (decltype(data.size()) k = 0; k < data.size(); ++k)
      data[k] = scale * (s.unknownMap()->getGlobalElement(k) + 10 * step);
    return v;
  };
  const auto wholeBar = bar(1.0), halfBar = bar(0.5);
  const auto &whole = wholeBar->system, &half = halfBar->system;  // nodes 0..8, then 0..4
  GridFields<1> fields(own, true, true);
  const auto read = [&](int column) {
    std::vector<double> at;
    const auto& output = fields;  // as the output files read it
    auto values = output.values().getData(column);
    for (decltype(values.size()) n = 0; n < values.size(); ++n)
      at.push_back(values[n]);
    return at;
  };
  const auto stepOn = [&](const GridSystem<1>& s, double step) {
    const auto du = stepVector(s, step, 1e-3);
    fields.update(StepGrid<1>{s, *du, stepVector(s, step, 1.0), stepVector(s, step, -2.0)});
  };
  const auto& nodes = *own.nodeMap();
  stepOn(*whole, 1), stepOn(*whole, 2);
  const auto u2 = read(0), v2 = read(1), m2 = read(2);
  for (std::size_t n = 0; n < u2.size(); ++n) {
    const double node = nodes.getGlobalElement(n);
    EXPECT_NEAR(u2[n], 1e-3 * (2 * node + 30), 1e-15) << node;
    EXPECT_EQ(v2[n], node + 20) << node;
    EXPECT_EQ(m2[n], -2 * (node + 20)) << node;
  }
  EXPECT_EQ(read(1), v2);  // reading again copies nothing new
  // Two steps on the half bar's nodes, the first not read: the last one's values count.
  stepOn(*half, 3), stepOn(*half, 4);
  const auto u4 = read(0), v4 = read(1), m4 = read(2);
  for (std::size_t n = 0; n < u4.size(); ++n) {
    const double node = nodes.getGlobalElement(n);
    const bool active = node <= 4;
    EXPECT_NEAR(u4[n], u2[n] + (active ? 1e-3 * (2 * node + 70) : 0.0), 1e-15) << node;
    EXPECT_EQ(v4[n], active ? node + 40 : 0.0) << node;
    EXPECT_EQ(m4[n], active ? -2 * (node + 40) : 0.0) << node;
  }
  // A step on other unknowns after one that was never read: back on the whole bar.
  stepOn(*half, 5), stepOn(*whole, 6);
  const auto v6 = read(1);
  for (std::size_t n = 0; n < v6.size(); ++n)
    EXPECT_EQ(v6[n], nodes.getGlobalElement(n) + 60.0);
  // A restart writes into the values: they hold the last step's before it does.
  stepOn(*whole, 7);
  auto restored = fields.values().getData(1);
  for (decltype(restored.size()) n = 0; n < restored.size(); ++n)
    EXPECT_EQ(restored[n], nodes.getGlobalElement(n) + 70.0);
}

}  // namespace
}  // namespace impm

namespace impm {
namespace {

// Mesh bodies: a mesh file written here (one per rank: the ranks run this test together),
// read back as a body, and the checks that refuse a bad element before anything runs.
class MeshBodies : public ::testing::Test {
 protected:
  void TearDown() override {
    for (const char* stem : {"squares", "clockwise", "folded", "bars", "empty_block"})
      std::remove(file(stem).c_str());
  }
  static std::string file(const std::string& stem) {
    return "unit_app_" + stem + "_" +
           std::to_string(Teuchos::DefaultComm<int>::getComm()->getRank()) + ".exo";
  }
  // Two unit squares side by side, blocks "left" and "right"; side set "left edge" on the
  // first square's left side, "right edge" on the second's right side.
  static BodyMesh twoSquares() {
    BodyMesh m;
    m.nodes = {{0, 0}, {1, 0}, {2, 0}, {0, 1}, {1, 1}, {2, 1}};
    BodyMesh::Block a, b;
    a.id = 1, a.name = "left", a.connectivity = {0, 1, 4, 3};
    b.id = 2, b.name = "right", b.connectivity = {1, 2, 5, 4};
    m.blocks = {a, b};
    BodyMesh::SideSet s, t;
    s.id = 1, s.name = "left edge", s.sides = {{0, 3}};
    t.id = 2, t.name = "right edge", t.sides = {{1, 1}};
    m.sideSets = {s, t};
    return m;
  }
  static Teuchos::ParameterList params(const std::string& path,
                                       std::vector<std::string> blocks = {}) {
    Teuchos::ParameterList p;
    p.set("Mesh File", path);
    p.set("Element Blocks", Teuchos::Array<std::string>(blocks));
    return p;
  }
  // The message of the InputError or FileError that making the body throws.
  static std::string refusal(const BodyMesh& m, const std::string& stem) {
    writeBodyMesh(file(stem), m, "test");
    try {
      Mesh body(params(file(stem)), "Bodies/b");
    } catch (const InputError& e) {
      return e.path() + ": " + e.what();
    } catch (const FileError& e) {
      return e.file() + ": " + e.what();
    }
    return "no error";
  }
};

TEST_F(MeshBodies, ElementsBecomeParticlesWithTheirAreasCornersAndSideSets) {
  writeBodyMesh(file("squares"), twoSquares(), "test");
  const Mesh right(params(file("squares"), {"right"}), "Bodies/b");
  const auto grid = makeGridGeometry<2>({0.0, 0.0}, {2.0, 1.0}, {4, 2});
  const auto seeds = right.fill(grid, 1, false);
  ASSERT_EQ(seeds.size(), 1u);
  EXPECT_DOUBLE_EQ(seeds[0].volume, 1.0);
  EXPECT_DOUBLE_EQ(seeds[0].x[0], 1.5);
  double corner[4][2], faces[4];
  right.seedCorners(0, corner, faces);
  EXPECT_DOUBLE_EQ(corner[2][0], 2.0);
  EXPECT_DOUBLE_EQ(faces[1], 2.0);  // bit 1: "right edge" on edge 1
  EXPECT_EQ(right.edgesOn(0), 0);   // "left edge" names no edge of this body
  EXPECT_EQ(right.edgesOn(1), 1);
  const double inside[2] = {1.5, 0.5}, outside[2] = {0.5, 0.5};
  EXPECT_TRUE(right.contains(inside));
  EXPECT_FALSE(right.contains(outside));
  const Mesh both(params(file("squares")), "Bodies/b");
  EXPECT_EQ(both.fill(grid, 1, false).size(), 2u);
}

TEST_F(MeshBodies, BadElementsAndFilesAreRefused) {
  auto clockwise = twoSquares();
  clockwise.blocks[1].connectivity = {1, 4, 5, 2};
  EXPECT_NE(refusal(clockwise, "clockwise").find("element 2 (block 'right') of unit_app_"),
            std::string::npos);
  EXPECT_NE(refusal(clockwise, "clockwise").find("has a non-positive area"), std::string::npos);
  auto folded = twoSquares();
  folded.nodes[4] = {0.2, 0.2};  // the shared corner pushed inside the first square
  EXPECT_NE(refusal(folded, "folded").find("is not a convex quadrilateral"), std::string::npos);
  auto bars = twoSquares();
  bars.blocks[0].type = "BAR2", bars.blocks[0].nodesPerElement = 2;
  bars.blocks[0].connectivity = {0, 1, 1, 2};
  bars.sideSets.clear();
  EXPECT_NE(refusal(bars, "bars").find("element block 'left' has BAR2 elements"),
            std::string::npos);
  try {
    Mesh m(params(file("squares_missing")), "Bodies/b");
    FAIL() << "no error";
  } catch (const FileError& e) {
    EXPECT_EQ(std::string(e.what()), "the mesh file does not exist");
  }
  writeBodyMesh(file("squares"), twoSquares(), "test");
  try {
    Mesh m(params(file("squares"), {"middle"}), "Bodies/b");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.path(), "Bodies/b/Element Blocks");
  }
}

// An empty element block (Exodus' NULL type) was refused even when the body did not use it.
TEST_F(MeshBodies, AnEmptyBlockIsSkippedUnlessNamed) {
  auto m = twoSquares();
  m.blocks.push_back(m.blocks[1]);
  m.blocks[2].id = 3, m.blocks[2].name = "empty", m.blocks[2].connectivity.clear();
  writeBodyMesh(file("empty_block"), m, "test");
  const BodyMesh read = readBodyMesh(file("empty_block"));
  ASSERT_EQ(read.blocks.size(), 3u);
  EXPECT_TRUE(read.blocks[2].connectivity.empty());
  const auto grid = makeGridGeometry<2>({0.0, 0.0}, {2.0, 1.0}, {4, 2});
  EXPECT_EQ(Mesh(params(file("empty_block")), "Bodies/b").fill(grid, 1, false).size(), 2u);
  EXPECT_EQ(Mesh(params(file("empty_block"), {"left"}), "Bodies/b").fill(grid, 1, false).size(),
            1u);
  try {
    Mesh named(params(file("empty_block"), {"left", "empty"}), "Bodies/b");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.path(), "Bodies/b/Element Blocks");
    EXPECT_NE(std::string(e.what()).find("element block 'empty' of unit_app_empty_block_"),
              std::string::npos);
    EXPECT_NE(std::string(e.what()).find(" has no elements"), std::string::npos);
  }
}

}  // namespace
}  // namespace impm

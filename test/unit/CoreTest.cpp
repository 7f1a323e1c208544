// core: formulas, parameter validation (one-line errors naming the path), the block
// decomposition, the DOF maps, and agreement on failures across ranks.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <set>

#include <Teuchos_DefaultComm.hpp>

#include "core/Collective.hpp"
#include "core/DofMap.hpp"
#include "core/Errors.hpp"
#include "core/Formula.hpp"
#include "core/Parameters.hpp"
#include "core/Tensor.hpp"

namespace impm {
namespace {

using Teuchos::ParameterList;

std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(Formula, NumbersExpressionsAndVariables) {
  EXPECT_TRUE(Formula("2.5", {"x"}).isConstant());
  EXPECT_DOUBLE_EQ(Formula("2.5", {"x"})(7.0), 2.5);
  const Formula f("1 + x*t + sin(pi*x)", {"x", "t"});
  EXPECT_NEAR(f(0.5, 2.0), 1 + 1.0 + 1.0, 1e-15);
  EXPECT_FALSE(f.independentOf("t"));
  EXPECT_TRUE(Formula("x^2", {"x", "t"}).independentOf("t"));
}

TEST(Formula, RejectsUnknownVariablesAndSyntax) {
  EXPECT_NE(errorOf([] { Formula("1 + y", {"x"}); }).find("'y', which is not a variable"),
            std::string::npos);
  EXPECT_NE(errorOf([] { Formula("1 + * x", {"x"}); }).find("cannot read formula"),
            std::string::npos);
}

ParameterList validList() {
  ParameterList valid;
  declareInt(valid, "Count", 3, "a count", Bounds::atLeast(1));
  declareDouble(valid, "Modulus", 1.0, "a modulus", Bounds::positive(), true);
  declareChoice(valid, "Kind", "a", {"a", "b"}, "a kind");
  declareFormula(valid, "Load", "0", {"x"}, "a load");
  declareIntArray(valid, "Cells", {4}, {1, 2}, "cells", Bounds::atLeast(1));
  declareDouble(valid.sublist("[Kind=b]"), "Extra", 2.0, "only for kind b");
  declareString(valid.sublist("Items").sublist("<name>"), "Tag", "", "a tag", true);
  return valid;
}

TEST(Parameters, FillsDefaultsAndConvertsIntsToDoubles) {
  ParameterList user;
  user.set("Modulus", 5);  // an int where a double is expected
  validateParameters(user, validList());
  EXPECT_EQ(user.get<int>("Count"), 3);
  EXPECT_DOUBLE_EQ(user.get<double>("Modulus"), 5.0);
  EXPECT_FALSE(user.isParameter("Extra"));  // only with Kind = b
}

TEST(Parameters, EveryKindOfMistakeNamesThePath) {
  auto check = [](const std::function<void(ParameterList&)>& edit, const std::string& expected) {
    ParameterList user;
    user.set("Modulus", 1.0);
    edit(user);
    const std::string error = errorOf([&] { validateParameters(user, validList()); });
    EXPECT_NE(error.find(expected), std::string::npos) << error;
  };
  check([](ParameterList& u) { u.set("Moduls", 2.0); },
        "Moduls: unknown parameter (did you mean 'Modulus'?)");
  check([](ParameterList& u) { u.set("Count", 2.5); }, "Count: expected type int, got double");
  check([](ParameterList& u) { u.set("Modulus", -1.0); }, "Modulus: must be > 0 (got -1)");
  check([](ParameterList& u) { u.remove("Modulus"); }, "Modulus: required parameter is missing");
  check([](ParameterList& u) { u.set("Kind", std::string("c")); }, "Kind: must be one of: a, b");
  check([](ParameterList& u) { u.set("Load", std::string("x + z")); },
        "Load: formula 'x + z' uses 'z'");
  check(
      [](ParameterList& u) {
        u.set("Cells", Teuchos::Array<int>(std::vector<int>{1, 2, 3}));
      },
      "Cells: expected 1 or 2 entries, got 3");
  check([](ParameterList& u) { u.set("Extra", 1.0); }, "Extra: unknown parameter");
  check([](ParameterList& u) { u.sublist("Items").sublist("first"); }, "Items/first/Tag: required");
  check([](ParameterList& u) { u.sublist("Count"); },
        "Count: must be a parameter, not a ParameterList");
}

TEST(Parameters, VariantsAndOverridesAreTypedLikeTheParameter) {
  ParameterList user;
  user.set("Modulus", 1.0);
  user.set("Kind", std::string("b"));
  validateParameters(user, validList());
  EXPECT_DOUBLE_EQ(user.get<double>("Extra"), 2.0);
  Teuchos::ParameterEntry proto;
  ASSERT_TRUE(findValidEntry(validList(), user, "Extra", proto));
  EXPECT_TRUE(parseLike(proto, "4.5", "Extra").isType<double>());
  ASSERT_TRUE(findValidEntry(validList(), user, "Cells", proto));
  EXPECT_EQ(Teuchos::getValue<Teuchos::Array<int>>(parseLike(proto, "{8}", "Cells"))[0], 8);
  ASSERT_TRUE(findValidEntry(validList(), user, "Load", proto));
  EXPECT_TRUE(parseLike(proto, "3", "Load").isType<double>());
  EXPECT_TRUE(parseLike(proto, "3*x", "Load").isType<std::string>());
  EXPECT_FALSE(findValidEntry(validList(), user, "Nothing", proto));
  // A formula parameter takes any text (checked where it is evaluated); an int does not.
  EXPECT_EQ(errorOf([&] { parseLike(proto, "x", "Load"); }), "no error");
  ASSERT_TRUE(findValidEntry(validList(), user, "Count", proto));
  EXPECT_NE(errorOf([&] { parseLike(proto, "x", "Count"); }).find("Count: cannot read 'x' as int"),
            std::string::npos);
  EXPECT_NE(errorOf([&] { parseLike(proto, "two", "Count"); }).find("cannot read 'two' as int"),
            std::string::npos);
}

TEST(Decomposition, EveryCellAndNodeHasExactlyOneOwner) {
  for (int ranks : {1, 2, 3, 4, 6}) {
    const auto g1 = makeGridGeometry<1>({0.0}, {1.0}, {10});
    const auto g2 = makeGridGeometry<2>({0.0, 0.0}, {2.0, 1.0}, {8, 5});
    Decomposition<1> d1(g1, ranks);
    Decomposition<2> d2(g2, ranks);
    std::vector<int> cells1(g1.numCells(), 0), nodes1(g1.numNodes(), 0);
    std::vector<int> cells2(g2.numCells(), 0), nodes2(g2.numNodes(), 0);
    for (int r = 0; r < ranks; ++r) {
      for (auto c : d1.ownedCells(r))
        ++cells1[c];
      for (auto n : d1.ownedNodes(r))
        ++nodes1[n];
      for (auto c : d2.ownedCells(r))
        ++cells2[c];
      for (auto n : d2.ownedNodes(r))
        ++nodes2[n];
    }
    for (int c : cells1)
      EXPECT_EQ(c, 1);
    for (int c : nodes1)
      EXPECT_EQ(c, 1);
    for (int c : cells2)
      EXPECT_EQ(c, 1);
    for (int c : nodes2)
      EXPECT_EQ(c, 1);
  }
}

TEST(DofMap, ActiveNodesOnlyWithExtrasNextToTheirAnchors) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  NodeOwnership<1> own(makeGridGeometry<1>({0.0}, {1.0}, {10}), comm);
  // Every rank touches nodes 2..7 (nodes 0, 1, 8, 9, 10 stay inactive).
  std::vector<GlobalId> touched = {2, 3, 4, 5, 6, 7};
  DofMap<1> dofs(own, touched, {ExtraDof{2}, ExtraDof{7}});
  EXPECT_EQ(dofs.numActiveNodes(), 6);
  EXPECT_EQ(dofs.ownedMap()->getGlobalNumElements(), 8u);
  const auto gids = dofs.ownedMap()->getNodeElementList();
  for (decltype(gids.size()) k = 0; k < gids.size(); ++k) {
    if (gids[k] == dofs.extraDof(0)) {
      ASSERT_GT(k, 0);
      EXPECT_EQ(gids[k - 1], dofs.nodeDof(2, 0));
    }
    if (gids[k] == dofs.extraDof(1)) {
      ASSERT_GT(k, 0);
      EXPECT_EQ(gids[k - 1], dofs.nodeDof(7, 0));
    }
  }
  // The overlap map starts with the owned map.
  const auto overlap = dofs.overlapMap()->getNodeElementList();
  for (decltype(gids.size()) k = 0; k < gids.size(); ++k)
    EXPECT_EQ(overlap[k], gids[k]);
}

// The touched list holds a node once per particle-node pair, in any order: each distinct
// node is one unknown, whether the nodes lie close together (marked in one pass) or far
// apart (sorted).
TEST(DofMap, RepeatedTouchedNodesInAnyOrderAreOneUnknownEach) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  NodeOwnership<1> own(makeGridGeometry<1>({0.0}, {1.0}, {1000}), comm);
  std::vector<GlobalId> close;
  for (int repeat = 0; repeat < 3; ++repeat)
    for (GlobalId node = 600; node >= 400; node -= 2)  // on both halves of the grid
      close.push_back(node);
  const std::vector<GlobalId> apart = {999, 5, 500, 5, 999, 500, 5};
  for (const auto& [touched, distinct] :
       {std::make_pair(close, std::set<GlobalId>(close.begin(), close.end())),
        std::make_pair(apart, std::set<GlobalId>{5, 500, 999})}) {
    DofMap<1> dofs(own, touched, {});
    EXPECT_EQ(dofs.numActiveNodes(), static_cast<GlobalId>(distinct.size()));
    const auto overlap = dofs.overlapMap()->getNodeElementList();
    EXPECT_EQ(std::set<GlobalId>(overlap.begin(), overlap.end()), distinct);
    EXPECT_EQ(overlap.size(), distinct.size());  // each once
    const auto owned = dofs.ownedMap()->getNodeElementList();
    EXPECT_TRUE(std::is_sorted(owned.begin(), owned.end()));
  }
}

// With OverlapHalo::neighbours the overlap map adds the grid neighbours of a rank's nodes
// that another rank owns and holds as unknowns (and no others), and lists patches of
// overlap nodes around them for the graph; on one rank there is no halo.
TEST(DofMap, HaloAddsNeighboursOtherRanksHold) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  NodeOwnership<1> own(makeGridGeometry<1>({0.0}, {1.0}, {10}), comm);
  const int rank = comm->getRank();
  // Every rank touches the nodes 2..8 that it owns: those are the active ones.
  std::vector<GlobalId> touched;
  for (GlobalId node = 2; node <= 8; ++node)
    if (own.ownerOfNode(node) == rank)
      touched.push_back(node);
  std::set<GlobalId> expected(touched.begin(), touched.end()), halo;
  for (GlobalId node : touched)
    for (GlobalId next : {node - 1, node + 1})
      if (next >= 2 && next <= 8 && own.ownerOfNode(next) != rank)
        halo.insert(next);
  expected.insert(halo.begin(), halo.end());

  DofMap<1> plain(own, touched, {});
  const auto plainOverlap = plain.overlapMap()->getNodeElementList();
  EXPECT_EQ(std::set<GlobalId>(plainOverlap.begin(), plainOverlap.end()),
            std::set<GlobalId>(touched.begin(), touched.end()));
  EXPECT_EQ(plain.haloPatchStart().size(), 1u);

  DofMap<1> dofs(own, touched, {}, OverlapHalo::neighbours);
  EXPECT_EQ(dofs.numActiveNodes(), 7);
  const auto overlap = dofs.overlapMap()->getNodeElementList();
  EXPECT_EQ(std::set<GlobalId>(overlap.begin(), overlap.end()), expected);
  EXPECT_EQ(overlap.size(), expected.size());
  if (comm->getSize() > 1) {
    EXPECT_FALSE(halo.empty());
  }
  // Each patch holds overlap nodes within two cells, one of them a halo node; together they
  // pair every halo node with every overlap node within two cells of it.
  const auto& start = dofs.haloPatchStart();
  const auto& nodes = dofs.haloPatchNodes();
  std::set<std::pair<GlobalId, GlobalId>> paired;
  for (std::size_t k = 0; k + 1 < start.size(); ++k) {
    const std::vector<GlobalId> patch(nodes.begin() + start[k], nodes.begin() + start[k + 1]);
    ASSERT_FALSE(patch.empty());
    EXPECT_LE(*std::max_element(patch.begin(), patch.end()) -
                  *std::min_element(patch.begin(), patch.end()),
              2);
    EXPECT_TRUE(std::any_of(patch.begin(), patch.end(), [&](GlobalId n) { return halo.count(n); }));
    for (GlobalId a : patch) {
      EXPECT_TRUE(expected.count(a));
      for (GlobalId b : patch)
        paired.emplace(a, b);
    }
  }
  for (GlobalId h : halo)
    for (GlobalId n : expected)
      if (std::abs(n - h) <= 2) {
        EXPECT_TRUE(paired.count({h, n})) << "halo node " << h << " and node " << n;
      }
}

TEST(Collective, AFailureOnOneRankStopsEveryRank) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  const int last = comm->getSize() - 1;
  try {
    collectively(*comm, [&] {
      if (comm->getRank() == last)
        throw InputError("Some/Path", "broken on rank " + std::to_string(last));
    });
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.path(), "Some/Path");
    EXPECT_EQ(std::string(e.what()), "Some/Path: broken on rank " + std::to_string(last));
  }
  EXPECT_NO_THROW(collectively(*comm, [] {}));
}

}  // namespace
}  // namespace impm

#include <random>

#include "core/Migration.hpp"

namespace impm {
namespace {

// Every field of particle id k holds values derived from k, so any mix-up shows.
template <class View>
void fillFrom(View& view, const Kokkos::View<GlobalId*>::HostMirror& id) {
  auto h = Kokkos::create_mirror_view(view);
  using Value = typename View::non_const_value_type;
  Value* data = h.data();
  const std::size_t width = id.extent(0) ? h.span() / id.extent(0) : 0;
  for (std::size_t p = 0; p < id.extent(0); ++p)
    for (std::size_t w = 0; w < width; ++w)
      data[p * width + w] =
          static_cast<Value>(id(p) * 1000 + w + (std::is_floating_point<Value>::value ? 0.25 : 0));
  Kokkos::deep_copy(view, h);
}

TEST(Migration, RandomOwnersAndBackKeepEveryFieldBitForBit) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  const int size = comm->getSize(), rank = comm->getRank();
  const std::size_t n = 7 + rank;  // ranks hold different counts
  ParticleSet<2> ps(n);
  FieldSpec state;  // a declared field travels like the framework's
  state.name = "b_e", state.shape = FieldShape::symmetric3x3;
  ps.declare(state);
  auto id = Kokkos::create_mirror_view(ps.id);
  for (std::size_t p = 0; p < n; ++p)
    id(p) = static_cast<GlobalId>(p * size + rank);
  Kokkos::deep_copy(ps.id, id);
  ps.forEachField([&](const FieldSpec& spec, auto& view) {
    if (spec.migrate && static_cast<const void*>(view.data()) != ps.id.data())
      fillFrom(view, id);
  });
  std::mt19937 rng(17 + rank);
  std::vector<int> random(n);
  for (auto& r : random)
    r = static_cast<int>(rng() % size);
  migrateParticles(ps, random, *comm);
  // Back home: the origin of id k is k % size.
  auto moved = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), ps.id);
  std::vector<int> home(ps.size());
  for (std::size_t p = 0; p < ps.size(); ++p)
    home[p] = static_cast<int>(moved(p) % size);
  migrateParticles(ps, home, *comm);
  ASSERT_EQ(ps.size(), n);
  auto back = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), ps.id);
  std::vector<std::size_t> order(n);
  for (std::size_t p = 0; p < n; ++p)
    order[p] = p;
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return back(a) < back(b); });
  for (std::size_t p = 1; p < n; ++p)  // every rank keeps its particles in id order
    EXPECT_LT(back(p - 1), back(p));
  ParticleSet<2> expected(n);
  expected.declare(state);
  Kokkos::deep_copy(expected.id, id);
  expected.forEachField([&](const FieldSpec& spec, auto& view) {
    if (spec.migrate && static_cast<const void*>(view.data()) != expected.id.data())
      fillFrom(view, id);
  });
  // Compare field by field through raw bytes, after sorting by id.
  std::vector<std::vector<char>> got, want;
  auto bytes = [&](auto& view, const std::vector<std::size_t>* perm) {
    auto h = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), view);
    const std::size_t row =
        n ? h.span() / n * sizeof(typename std::decay_t<decltype(h)>::value_type) : 0;
    std::vector<char> out(n * row);
    const char* data = reinterpret_cast<const char*>(h.data());
    for (std::size_t p = 0; p < n; ++p)
      std::copy(data + (perm ? (*perm)[p] : p) * row, data + ((perm ? (*perm)[p] : p) + 1) * row,
                out.begin() + p * row);
    return out;
  };
  ps.forEachField([&](const FieldSpec& spec, auto& view) {
    if (spec.migrate)
      got.push_back(bytes(view, &order));
  });
  expected.forEachField([&](const FieldSpec& spec, auto& view) {
    if (spec.migrate)
      want.push_back(bytes(view, nullptr));
  });
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t f = 0; f < got.size(); ++f)
    EXPECT_TRUE(got[f] == want[f]) << "field " << f;
}

}  // namespace
}  // namespace impm

namespace impm {
namespace {

// The particle registry: fields declared once, then resized, mirrored and migrated with the
// framework's; declaring a name twice is refused.
TEST(ParticleRegistry, DeclareResizeMirrorAndRefuseDuplicates) {
  ParticleSet<2> ps(3);
  FieldSpec eqps;
  eqps.name = "eqps", eqps.shape = FieldShape::scalar, eqps.twoLevels = true;
  eqps.columns = defaultColumns<2>("eqps", FieldShape::scalar);
  ps.declare(eqps, {0.5});
  FieldSpec be;
  be.name = "b_e", be.shape = FieldShape::symmetric3x3;
  ps.declare(be, {1, 1, 1, 0, 0, 0});
  EXPECT_TRUE(ps.has("eqps"));
  EXPECT_TRUE(ps.has("stress"));  // a framework field
  EXPECT_FALSE(ps.has("damage"));
  EXPECT_EQ(ps.values("b_e").extent(1), 6u);
  EXPECT_THROW(ps.declare(eqps), std::invalid_argument);
  FieldSpec clash = eqps;
  clash.name = "stress";
  EXPECT_THROW(ps.declare(clash), std::invalid_argument);
  clash.name = "2bad";
  EXPECT_THROW(ps.declare(clash), std::invalid_argument);
  // Growing keeps the old rows and gives the new ones the initial values.
  {
    auto host = Kokkos::create_mirror_view(ps.values("eqps"));
    host(1, 0) = 7.0;
    Kokkos::deep_copy(ps.values("eqps"), host);
  }
  ps.resize(5);
  const auto mirror = ps.mirror(Kokkos::DefaultHostExecutionSpace());
  ASSERT_EQ(mirror.size(), 5u);
  EXPECT_EQ(mirror.values("eqps")(1, 0), 7.0);
  EXPECT_EQ(mirror.values("eqps")(4, 0), 0.5);
  EXPECT_EQ(mirror.values("b_e")(4, 0), 1.0);
  EXPECT_EQ(mirror.values("b_e")(4, 3), 0.0);
  // The registry lists the declared fields after the framework's, with their columns.
  const auto specs = ps.specs();
  EXPECT_EQ(specs.back().name, "b_e");
  EXPECT_EQ(specs[specs.size() - 2].columns.front().csv, "eqps");
  EXPECT_EQ(defaultColumns<2>("b_e", FieldShape::symmetric3x3)[3].csv, "b_e_xy");
  EXPECT_EQ(defaultColumns<2>("v", FieldShape::vector)[1].exodus, "vY");
  // A copy back from the host keeps every value.
  ParticleSet<2> back;
  back.declare(eqps), back.declare(be);
  back.copyFrom(mirror);
  EXPECT_EQ(back.size(), 5u);
  auto check = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), back.values("eqps"));
  EXPECT_EQ(check(1, 0), 7.0);
}

// Per-material index lists follow the material field, also after a migration.
TEST(ParticleRegistry, MaterialMembersAreRebuiltAfterMigration) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  const int size = comm->getSize(), rank = comm->getRank();
  ParticleSet<1> ps(6);
  auto id = Kokkos::create_mirror_view(ps.id);
  auto material = Kokkos::create_mirror_view(ps.material);
  for (int p = 0; p < 6; ++p)
    id(p) = 6 * rank + p, material(p) = p % 2;
  Kokkos::deep_copy(ps.id, id), Kokkos::deep_copy(ps.material, material);
  ps.indexMaterials(2);
  EXPECT_EQ(ps.membersOf(0).extent(0), 3u);
  std::vector<int> destination(6);
  for (int p = 0; p < 6; ++p)  // the odd-material particles go to the next rank
    destination[p] = p % 2 ? (rank + 1) % size : rank;
  migrateParticles(ps, destination, *comm);
  auto m = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), ps.material);
  for (int k = 0; k < 2; ++k) {
    auto members = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), ps.membersOf(k));
    EXPECT_EQ(members.extent(0), 3u);
    for (std::size_t i = 0; i < members.extent(0); ++i)
      EXPECT_EQ(m(members(i)), k);
  }
}

}  // namespace
}  // namespace impm

#include <Teuchos_CommHelpers.hpp>

#include <array>

#include "core/NodeOwnership.hpp"
#include "core/Repartition.hpp"

namespace impm {
namespace {

TEST(Decomposition, ATableGivesEveryCellItsRankAndItsNodesFollow) {
  const auto g = makeGridGeometry<2>({0.0, 0.0}, {4.0, 2.0}, {4, 2});
  // Ranks 0..2 in a pattern no block decomposition has.
  const std::vector<int> owners = {2, 0, 0, 1, 2, 2, 1, 1};
  const Decomposition<2> d(g, 3, owners);
  std::vector<int> nodes(g.numNodes(), 0);
  for (int r = 0; r < 3; ++r) {
    for (auto c : d.ownedCells(r))
      EXPECT_EQ(owners[c], r);
    for (auto n : d.ownedNodes(r)) {
      ++nodes[n];
      EXPECT_EQ(d.ownerOfNode(n), r);
    }
  }
  for (int count : nodes)
    EXPECT_EQ(count, 1);
  // A node goes with the cell it is the lower-left corner of; the top and right edges with
  // the cells below and to the left of them.
  EXPECT_EQ(d.ownerOfNode(0), 2);   // node (0,0), cell 0
  EXPECT_EQ(d.ownerOfNode(4), 1);   // node (4,0), cell 3
  EXPECT_EQ(d.ownerOfNode(14), 1);  // node (4,2), cell 7
  const double inCell5[2] = {1.5, 1.5};
  EXPECT_EQ(d.ownerOfPoint(inCell5), 2);
  EXPECT_THROW(Decomposition<2>(g, 3, std::vector<int>(7, 0)), std::invalid_argument);
  EXPECT_THROW(Decomposition<2>(g, 3, std::vector<int>(8, 3)), std::invalid_argument);
}

// All the particles start in the cells of rank 0 (the lower rows of a column); a repartition
// must spread them over the ranks in about equal counts, with one table on every rank.
// 3-D blocks: every cell and node has one owner, and 8 ranks on a cube of cells take 2 x 2 x 2
// blocks (the least surface per volume), 4 ranks on a grid long in z split z only.
TEST(Decomposition, ThreeDimensionalBlocksAreAsCubicAsTheRankCountAllows) {
  const auto cube = makeGridGeometry<3>({0.0, 0.0, 0.0}, {1.0, 1.0, 1.0}, {6, 6, 6});
  EXPECT_EQ(Decomposition<3>(cube, 8).blocks(), (std::array<int, 3>{2, 2, 2}));
  const auto tall = makeGridGeometry<3>({0.0, 0.0, 0.0}, {1.0, 1.0, 8.0}, {2, 2, 16});
  EXPECT_EQ(Decomposition<3>(tall, 4).blocks(), (std::array<int, 3>{1, 1, 4}));
  for (int ranks : {1, 2, 3, 4, 6, 8}) {
    const auto g = makeGridGeometry<3>({0.0, 0.0, 0.0}, {2.0, 1.0, 1.5}, {5, 3, 4});
    Decomposition<3> d(g, ranks);
    std::vector<int> cells(g.numCells(), 0), nodes(g.numNodes(), 0);
    for (int r = 0; r < ranks; ++r) {
      for (auto c : d.ownedCells(r)) {
        ++cells[c];
        EXPECT_EQ(d.ownerOfCell(c), r);
      }
      for (auto n : d.ownedNodes(r)) {
        ++nodes[n];
        EXPECT_EQ(d.ownerOfNode(n), r);
      }
    }
    for (int c : cells)
      EXPECT_EQ(c, 1) << ranks << " ranks";
    for (int c : nodes)
      EXPECT_EQ(c, 1) << ranks << " ranks";
  }
}

// The 3-D determinant and inverse: a^-1 a = I, det(a b) = det a det b, on matrices with
// every entry non-zero.
TEST(Tensor, ThreeDimensionalDeterminantAndInverse) {
  const double a[3][3] = {{2.0, -0.3, 0.7}, {0.4, 1.5, -0.2}, {-0.6, 0.9, 3.1}};
  const double b[3][3] = {{1.1, 0.2, -0.5}, {-0.8, 0.6, 0.3}, {0.25, -0.4, 2.2}};
  double ab[3][3] = {}, inv[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        ab[i][j] += a[i][k] * b[k][j];
  const double det = determinant<3>(a);
  // By the rule of Sarrus, written out independently of the code's cofactor form.
  const double sarrus = a[0][0] * a[1][1] * a[2][2] + a[0][1] * a[1][2] * a[2][0] +
                        a[0][2] * a[1][0] * a[2][1] - a[0][2] * a[1][1] * a[2][0] -
                        a[0][0] * a[1][2] * a[2][1] - a[0][1] * a[1][0] * a[2][2];
  EXPECT_NEAR(det, sarrus, 1e-14);
  EXPECT_NEAR(determinant<3>(ab), det * determinant<3>(b), 1e-13);
  inverse<3>(a, det, inv);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      double e = 0.0;
      for (int k = 0; k < 3; ++k)
        e += inv[i][k] * a[k][j];
      EXPECT_NEAR(e, i == j ? 1.0 : 0.0, 1e-14) << i << j;
    }
}

// Cells crowded in the lowest layers of a column of cells along z: only cuts along z can
// spread them, so a partition that ignored z (the cells' x and y centres are all the same)
// could not.
TEST(Repartition, CutsAlongZInThreeDimensions) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  const int size = comm->getSize(), rank = comm->getRank();
  NodeOwnership<3> own(makeGridGeometry<3>({0.0, 0.0, 0.0}, {1.0, 1.0, 16.0}, {1, 1, 16}), comm);
  std::vector<std::array<double, 3>> points;
  for (int k = 0; k < 4; ++k)  // four particles in each of the lowest four layers
    for (int q = 0; q < 4; ++q) {
      const double x[3] = {0.2 + 0.2 * q, 0.5, k + 0.5};
      if (own.decomposition().ownerOfPoint(x) == rank)
        points.push_back({x[0], x[1], x[2]});
    }
  ParticleSet<3> ps(points.size());
  auto x = Kokkos::create_mirror_view(ps.x);
  for (std::size_t p = 0; p < points.size(); ++p)
    for (int d = 0; d < 3; ++d)
      x(p, d) = points[p][d];
  Kokkos::deep_copy(ps.x, x);
  auto partition = repartitionCells(own.decomposition(), ps, comm);
  own.repartition(std::move(partition.decomposition));
  migrateToOwners(ps, own.decomposition(), *comm);
  // 4 layers of 4 particles: 1, 2 and 4 ranks balance exactly, 3 ranks to 8 against 16/3.
  EXPECT_LE(particleImbalance(ps.size(), *comm), size == 3 ? 1.5 + 1e-12 : 1.0 + 1e-12);
}

TEST(Repartition, SpreadsParticlesCrowdedOnOneRank) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  const int size = comm->getSize(), rank = comm->getRank();
  NodeOwnership<2> own(makeGridGeometry<2>({0.0, 0.0}, {2.0, 16.0}, {2, 16}), comm);
  const auto& grid = own.grid();
  // Four particles per cell in the lowest rows that rank 0 owns, at most two rows.
  std::vector<std::array<double, 2>> points;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i)
      for (int k = 0; k < 4; ++k) {
        const double x[2] = {i + 0.2 + 0.2 * k, j + 0.5};
        if (own.decomposition().ownerOfPoint(x) == rank)
          points.push_back({x[0], x[1]});
      }
  ParticleSet<2> ps(points.size());
  auto x = Kokkos::create_mirror_view(ps.x);
  for (std::size_t p = 0; p < points.size(); ++p)
    x(p, 0) = points[p][0], x(p, 1) = points[p][1];
  Kokkos::deep_copy(ps.x, x);
  const double before = particleImbalance(ps.size(), *comm);
  EXPECT_DOUBLE_EQ(before, size == 1 ? 1.0 : static_cast<double>(size));
  auto partition = repartitionCells(own.decomposition(), ps, comm);
  const double predicted = partition.imbalance;
  own.repartition(std::move(partition.decomposition));
  migrateToOwners(ps, own.decomposition(), *comm);
  GlobalId total = 0;
  const GlobalId mine = static_cast<GlobalId>(ps.size());
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, mine, Teuchos::outArg(total));
  EXPECT_EQ(total, 16);
  // 16 particles in 4 cells of 4: ranks get whole cells, so 1, 2 and 4 ranks balance exactly,
  // 3 ranks to 8 against a mean of 16/3.
  const double after = particleImbalance(ps.size(), *comm);
  EXPECT_LE(after, size == 3 ? 1.5 + 1e-12 : 1.0 + 1e-12);
  EXPECT_DOUBLE_EQ(predicted, after);
  // Every rank holds the same table.
  const auto& owners = own.decomposition().cellOwners();
  ASSERT_EQ(static_cast<GlobalId>(owners.size()), grid.numCells());
  std::vector<double> local(owners.begin(), owners.end());
  const auto all = gatherToAll(*comm, local);
  for (int r = 0; r < size; ++r)
    for (std::size_t c = 0; c < owners.size(); ++c)
      EXPECT_EQ(all[r * owners.size() + c], owners[c]);
}

}  // namespace
}  // namespace impm

#include <cfloat>
#include <limits>

#include "core/Diagnostics.hpp"

namespace impm {
namespace {

// The failure messages name the first particle whose stress, tangent or state is not finite:
// every non-finite kind is found in every position of a row, in the first and the last row,
// extreme finite values are not, and rows past `rows` (a view's spare capacity) do not count.
TEST(Diagnostics, FirstNonFiniteRowFindsEveryKindAndPositionAndOnlyThose) {
  const double kinds[] = {
      std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
      -std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::signaling_NaN()};
  const double finite[] = {DBL_MAX, -DBL_MAX, DBL_MIN, DBL_TRUE_MIN, -0.0, 0.0};
  const std::size_t rows = 7, capacity = 9;
  Kokkos::View<double* [2][2][2][2], Kokkos::HostSpace> A("A", capacity);
  Kokkos::View<double*, Kokkos::HostSpace> values("values", capacity);
  for (std::size_t k = 0; k < A.span(); ++k)
    A.data()[k] = finite[k % 6];
  EXPECT_EQ(firstNonFiniteRow(A, rows), -1);
  for (const double bad : kinds)
    for (const std::size_t row : {std::size_t(0), std::size_t(3), rows - 1})
      for (std::size_t entry = 0; entry < 16; ++entry) {
        double& x = A.data()[row * 16 + entry];
        const double kept = x;
        x = bad;
        EXPECT_EQ(firstNonFiniteRow(A, rows), static_cast<long>(row)) << bad << " " << entry;
        x = kept;
      }
  A(rows, 1, 1, 1, 1) = kinds[0];  // spare capacity
  EXPECT_EQ(firstNonFiniteRow(A, rows), -1);
  EXPECT_EQ(firstNonFiniteRow(A, rows + 1), static_cast<long>(rows));
  values(rows - 1) = kinds[1];
  values(2) = kinds[2];
  EXPECT_EQ(firstNonFiniteRow(values, rows), 2);
  EXPECT_EQ(firstNonFiniteRow(values, 2), -1);
}

}  // namespace
}  // namespace impm

#include <cstdint>
#include <fstream>
#include <sstream>

#include <Kokkos_Core.hpp>

#include "core/MemoryPolicy.hpp"

namespace impm {
namespace {

// The kernel's flags of the mapping that holds address, from /proc/self/smaps ("hg": the
// mapping asked for transparent huge pages).
std::string mappingFlags(const void* address) {
  const auto at = reinterpret_cast<std::uintptr_t>(address);
  std::ifstream smaps("/proc/self/smaps");
  bool inside = false;
  for (std::string line; std::getline(smaps, line);) {
    std::uintptr_t begin = 0, end = 0;
    char dash = 0;
    if (std::istringstream(line) >> std::hex >> begin >> dash >> end && dash == '-')
      inside = begin <= at && at < end;
    else if (inside && line.rfind("VmFlags:", 0) == 0)
      return line.substr(8) + " ";
  }
  return "";
}

TEST(MemoryPolicy, ViewsMadeAfterTheAdviceAskForHugePages) {
  keepFreedMemory();  // as impm does: large blocks from the heap
  if (!adviseHugePages())
    GTEST_SKIP() << "no heap advice here (not glibc on Linux, huge pages off, or a sanitizer)";
  // 32 MB, then 128 MB: more than the heap holds free, so it grows for each.  A view may
  // begin in the free top of the heap as it was; its middle is in what the heap grew by.
  for (const std::size_t n : {std::size_t(4) << 20, std::size_t(16) << 20}) {
    Kokkos::View<double*, Kokkos::HostSpace> big("big", n);
    const std::string flags = mappingFlags(big.data() + n / 2);
    EXPECT_NE(flags.find(" hg "), std::string::npos) << n << " doubles, flags:" << flags;
  }
}

}  // namespace
}  // namespace impm

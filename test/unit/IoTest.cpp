// io: files read back exactly as written (CSV in the shortest exact form, Exodus through the
// exodusII reading API, time steps appended one by one) and decks with typed overrides.

#include <gtest/gtest.h>

#include <exodusII.h>
#include <Teuchos_DefaultComm.hpp>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <sstream>

#include "core/Errors.hpp"
#include "core/Parameters.hpp"
#include "io/CsvFile.hpp"
#include "io/ExodusFile.hpp"
#include "io/InputDeck.hpp"

namespace impm {
namespace {

// A file in the test's working directory, one per rank (every rank runs every test).
std::string scratch(const std::string& name) {
  return "io_test_rank" + std::to_string(Teuchos::DefaultComm<int>::getComm()->getRank()) + "_" +
         name;
}

TEST(Csv, HistoryAndTableReadBackExactly) {
  const std::string path = scratch("history.csv");
  CsvHistory h(path, {"step", "value"});
  // The shortest text that reads back to the same double: 0.1 stays "0.1", 0.1 + 0.2 needs 17
  // digits, and the extremes of the range survive.
  const std::vector<double> values = {1.0 / 3.0, 0.1 + 0.2, 4.9e-324, -1.7976931348623157e308};
  h.append({1, 0.1});
  for (double v : values)
    h.append({2, v});
  std::ifstream in(path);
  std::string header, row;
  std::getline(in, header), std::getline(in, row);
  EXPECT_EQ(header, "step,value");
  EXPECT_EQ(row, "1,0.1");
  for (double v : values) {
    std::getline(in, row);
    EXPECT_EQ(std::strtod(row.c_str() + 2, nullptr), v) << row;  // stod refuses subnormals
  }
  in.close();
  // A row of the longest forms (24 characters) is written whole.
  h.append({-2.2250738585072014e-308, -1.7976931348623157e308});
  in.open(path);
  for (std::size_t line = 0; line < values.size() + 3; ++line)
    std::getline(in, row);
  EXPECT_EQ(row, "-2.2250738585072014e-308,-1.7976931348623157e+308");
  EXPECT_THROW(h.append({1.0}), std::logic_error);
  std::remove(path.c_str());
}

// Rank r holds rows [start_r, start_r + rowsOf(r)) of the table; the collective file must
// equal the serial file of the whole.  By default rank r holds (r + 1) m rows.
void expectCollectiveTableEqualsTheSerialOne(int m, const std::function<int(int)>& rowsOf = {}) {
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const int rank = comm->getRank(), size = comm->getSize();
  const auto value = [](int row, int c) { return c == 0 ? row : 1.0 / (row + 3.0) - c; };
  std::vector<std::vector<double>> local(3), whole(3);
  int row = 0;
  for (int r = 0; r < size; ++r)
    for (int k = 0; k < (rowsOf ? rowsOf(r) : (r + 1) * m); ++k, ++row)
      for (int c = 0; c < 3; ++c) {
        whole[c].push_back(value(row, c));
        if (r == rank)
          local[c].push_back(value(row, c));
      }
  const std::string collective = "io_test_collective.csv";  // one file for all ranks
  const std::string serial = scratch("serial.csv");
  std::ofstream(collective) << std::string(100000, 'x');  // a longer old file is replaced
  comm->barrier();
  writeCsvTableCollectively(collective, *comm, {"row", "a", "b"}, local);
  writeCsvTable(serial, {"row", "a", "b"}, whole);
  const auto read = [](const std::string& path) {
    std::ifstream in(path);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  const std::string text = read(collective);
  EXPECT_EQ(text, read(serial));
  if (m > 1) {  // each rank's text spans several of the blocks it is written in (8 MB)
    EXPECT_GT(text.size(), std::size_t(size) * (16u << 20));
  }
  comm->barrier();
  if (rank == 0)
    std::remove(collective.c_str());
  std::remove(serial.c_str());
}

TEST(Csv, CollectiveTableEqualsTheSerialOne) {
  expectCollectiveTableEqualsTheSerialOne(1);
}

TEST(Csv, CollectiveTableWrittenInBlocksEqualsTheSerialOne) {
  expectCollectiveTableEqualsTheSerialOne(400000);
}

// Ranks without rows anywhere: the whole table on rank 0 (as the particle output writes it
// beside the Exodus files), on the last rank, or on every rank but the first.
TEST(Csv, CollectiveTableWithRanksWithoutRowsEqualsTheSerialOne) {
  const int last = Teuchos::DefaultComm<int>::getComm()->getSize() - 1;
  expectCollectiveTableEqualsTheSerialOne(0, [](int r) { return r == 0 ? 7 : 0; });
  expectCollectiveTableEqualsTheSerialOne(0, [last](int r) { return r == last ? 7 : 0; });
  expectCollectiveTableEqualsTheSerialOne(0, [](int r) { return r == 0 ? 0 : 3 + r; });
}

TEST(Exodus, MeshVariablesAndTimeStepsReadBack) {
  const std::string path = scratch("bar.exo");
  ExodusMesh mesh;
  mesh.dimension = 1;
  mesh.coords = {{0.0, 0.5, 1.0}};
  mesh.elementType = "BAR2";
  mesh.nodesPerElement = 2;
  mesh.connectivity = {1, 2, 2, 3};
  {
    ExodusFile file(path, "test", mesh, {"displacementX"}, {"stress"}, {"F0"});
    file.append(0.0, {{0, 0, 0}}, {{0, 0}}, {0.0});
    file.append(0.5, {{0, 0.1, 0.2}}, {{1.5, 2.5}}, {-3.0});
    EXPECT_EQ(file.stepsWritten(), 2);
  }
  int cpu = sizeof(double), io = 0;
  float version = 0;
  const int id = ex_open(path.c_str(), EX_READ, &cpu, &io, &version);
  ASSERT_GE(id, 0);
  EXPECT_EQ(ex_inquire_int(id, EX_INQ_TIME), 2);
  double t = -1;
  ex_get_time(id, 2, &t);
  EXPECT_DOUBLE_EQ(t, 0.5);
  std::vector<double> u(3), s(2), g(1), x(3);
  ex_get_var(id, 2, EX_NODAL, 1, 1, 3, u.data());
  ex_get_var(id, 2, EX_ELEM_BLOCK, 1, 1, 2, s.data());
  ex_get_var(id, 2, EX_GLOBAL, 1, 0, 1, g.data());
  ex_get_coord(id, x.data(), nullptr, nullptr);
  EXPECT_DOUBLE_EQ(u[2], 0.2);
  EXPECT_DOUBLE_EQ(s[1], 2.5);
  EXPECT_DOUBLE_EQ(g[0], -3.0);
  EXPECT_DOUBLE_EQ(x[1], 0.5);
  char name[MAX_STR_LENGTH + 1];
  char* names[1] = {name};
  ex_get_variable_names(id, EX_NODAL, 1, names);
  EXPECT_STREQ(name, "displacementX");
  ex_close(id);
  std::remove(path.c_str());
}

// A netCDF-3 file whose header grows after data is written moves all of it (in 8 kB blocks):
// the file is fully defined when it is made, so that a step adds its record and nothing else.
TEST(Exodus, AStepAddsItsRecordOnly) {
  const std::string path = scratch("record.exo");
  ExodusMesh mesh;
  mesh.dimension = 2;
  mesh.coords = {{0.0, 1.0, 1.0, 0.0}, {0.0, 0.0, 1.0, 1.0}};
  mesh.elementType = "QUAD4";
  mesh.nodesPerElement = 4;
  mesh.connectivity = {1, 2, 3, 4};
  mesh.elementIds = {7};
  ExodusFile file(path, "test", mesh, {"displacementX", "displacementY"}, {"a", "b", "c"}, {"F0"});
  const auto size = [&] { return std::filesystem::file_size(path); };
  const auto made = size();
  file.append(0.0, {{0, 0, 0, 0}, {0, 0, 0, 0}}, {{1}, {2}, {3}}, {0.0});
  // time, 2 x 4 nodal values, 3 element values, 1 global value
  const std::uintmax_t record = (1 + 2 * 4 + 3 + 1) * sizeof(double);
  EXPECT_EQ(size() - made, record);
  file.append(1.0, {{0, 0, 0, 0}, {0, 0, 0, 0}}, {{1}, {2}, {3}}, {0.5});
  EXPECT_EQ(size() - made, 2 * record);
  std::remove(path.c_str());
}

TEST(InputDeck, OverridesAreTypedAndValidated) {
  const std::string path = scratch("deck.xml");
  std::ofstream(path) << "<ParameterList name=\"impm\"><Parameter name=\"Count\" type=\"int\" "
                         "value=\"2\"/></ParameterList>";
  Teuchos::ParameterList valid;
  declareInt(valid, "Count", 1, "a count", Bounds::atLeast(1));
  declareIntArray(valid.sublist("Grid"), "Cells", {4}, {1, 2}, "cells", Bounds::atLeast(1));
  auto deck = loadDeck(path, {parseOverride("Grid/Cells={64}"), parseOverride("Count=5")}, valid);
  EXPECT_EQ(deck.get<int>("Count"), 5);
  EXPECT_EQ(deck.sublist("Grid").get<Teuchos::Array<int>>("Cells")[0], 64);
  EXPECT_THROW(loadDeck(path, {parseOverride("Count=0")}, valid), InputError);
  EXPECT_THROW(loadDeck(path, {parseOverride("Nope=1")}, valid), InputError);
  EXPECT_THROW(parseOverride("Count"), InputError);
  EXPECT_EQ(deckStem("input/bar_static_s1.xml"), "bar_static_s1");
  std::remove(path.c_str());
}

}  // namespace
}  // namespace impm

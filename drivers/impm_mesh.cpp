// impm_mesh: writes the body-fitted meshes of impm's decks, tests and benchmarks into Exodus
// II files (QUAD4 or TRI3, one element block, side sets on the boundary).
//
//   impm_mesh annulus OUT.exo --radii a b --cells nr nt [--triangles] [--block NAME]
//       a quarter of the annulus a <= r <= b, 0 <= theta <= pi/2: nr elements along r, nt
//       along theta; side sets inner, outer, x0 (on the y axis), y0 (on the x axis)
//   impm_mesh rectangle OUT.exo --box x0 x1 y0 y1 --cells nx ny [--triangles]
//       [--distort f] [--seed s] [--block NAME]
//       the box in nx x ny elements, interior nodes moved at random by up to f times the
//       element size along each axis; side sets left, right, bottom, top
//
//   impm_mesh text IN.txt OUT.exo
//       converts a mesh listed as text (what drivers/gmsh_to_exodus.py writes):
//         nodes N, then N lines "x y";
//         per block: block NAME QUAD4|TRI3 COUNT, then COUNT lines of 1-based node numbers;
//         per side set: sideset NAME COUNT, then COUNT lines "element side" (1-based, the
//         element numbered over all blocks in order, Exodus side numbering)
//
// --triangles splits every quadrilateral along its diagonal from its first corner.
// Exit status 0, or 2 with a message for a bad command line, a malformed text mesh or an
// unwritable file.

#include <cmath>
#include <fstream>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include "core/Errors.hpp"
#include "io/MeshFile.hpp"

namespace {

struct Options {
  std::string kind, out, in, block = "body";
  double range[4] = {1, 2, 0, 0};
  int cells[2] = {0, 0};
  bool triangles = false;
  double distort = 0.0;
  unsigned seed = 1;
};

[[noreturn]] void usage(const std::string& why) {
  std::cerr << "impm_mesh: " << why
            << "\nusage: impm_mesh annulus OUT.exo --radii a b --cells nr nt [--triangles]\n"
               "       impm_mesh rectangle OUT.exo --box x0 x1 y0 y1 --cells nx ny "
               "[--triangles] [--distort f] [--seed s]\n"
               "       impm_mesh text IN.txt OUT.exo\n";
  std::exit(2);
}

Options parse(int argc, char** argv) {
  if (argc < 3)
    usage("needs a kind and a file");
  Options o;
  o.kind = argv[1], o.out = argv[2];
  if (o.kind == "text") {
    if (argc != 4)
      usage("text needs an input and an output file");
    o.in = argv[2], o.out = argv[3];
    return o;
  }
  if (o.kind != "annulus" && o.kind != "rectangle")
    usage("unknown kind '" + o.kind + "'");
  const auto number = [&](int& k) {
    if (++k >= argc)
      usage(std::string("a value is missing after ") + argv[k - 1]);
    try {
      return std::stod(argv[k]);
    } catch (const std::exception&) {
      usage(std::string("'") + argv[k] + "' is not a number");
    }
  };
  for (int k = 3; k < argc; ++k) {
    const std::string a = argv[k];
    if (a == "--radii" || a == "--box") {
      for (int j = 0; j < (a == "--box" ? 4 : 2); ++j)
        o.range[j] = number(k);
    } else if (a == "--cells") {
      for (int j = 0; j < 2; ++j)
        o.cells[j] = static_cast<int>(number(k));
    } else if (a == "--triangles") {
      o.triangles = true;
    } else if (a == "--distort") {
      o.distort = number(k);
    } else if (a == "--seed") {
      o.seed = static_cast<unsigned>(number(k));
    } else if (a == "--block") {
      if (++k >= argc)
        usage("a name is missing after --block");
      o.block = argv[k];
    } else {
      usage("unknown option '" + a + "'");
    }
  }
  if (o.cells[0] < 1 || o.cells[1] < 1)
    usage("--cells needs two counts >= 1");
  return o;
}

// Node (i, j) of the (n0 + 1) x (n1 + 1) lattice, i fastest.
int node(const Options& o, int i, int j) {
  return j * (o.cells[0] + 1) + i;
}

std::vector<std::array<double, 2>> nodes(const Options& o) {
  std::vector<std::array<double, 2>> out;
  std::mt19937 random(o.seed);
  std::uniform_real_distribution<double> shift(-o.distort, o.distort);
  const int n0 = o.cells[0], n1 = o.cells[1];
  for (int j = 0; j <= n1; ++j)
    for (int i = 0; i <= n0; ++i) {
      const double s = static_cast<double>(i) / n0, t = static_cast<double>(j) / n1;
      if (o.kind == "annulus") {
        const double r = o.range[0] + (o.range[1] - o.range[0]) * s, theta = 0.5 * M_PI * t;
        out.push_back({r * std::cos(theta), r * std::sin(theta)});
        if (j == n1)
          out.back()[0] = 0.0;  // exactly on the axis
        continue;
      }
      double x = o.range[0] + (o.range[1] - o.range[0]) * s;
      double y = o.range[2] + (o.range[3] - o.range[2]) * t;
      if (i > 0 && i < n0 && j > 0 && j < n1) {
        x += shift(random) * (o.range[1] - o.range[0]) / n0;
        y += shift(random) * (o.range[3] - o.range[2]) / n1;
      }
      out.push_back({x, y});
    }
  return out;
}

// Elements and side sets.  Sides of quadrilateral (i, j): 0 along j (low edge of the second
// direction), 1 at i + 1, 2 at j + 1, 3 at i.
void elements(const Options& o, impm::BodyMesh& mesh) {
  const bool annulus = o.kind == "annulus";
  const std::vector<std::string> names =
      annulus ? std::vector<std::string>{"y0", "outer", "x0", "inner"}
              : std::vector<std::string>{"bottom", "right", "top", "left"};
  impm::BodyMesh::Block block;
  block.id = 1, block.name = o.block, block.nodesPerElement = o.triangles ? 3 : 4;
  mesh.sideSets.resize(4);
  for (int s = 0; s < 4; ++s)
    mesh.sideSets[s].id = s + 1, mesh.sideSets[s].name = names[s];
  const int n0 = o.cells[0], n1 = o.cells[1];
  int element = 0;
  for (int j = 0; j < n1; ++j)
    for (int i = 0; i < n0; ++i) {
      const int c[4] = {node(o, i, j), node(o, i + 1, j), node(o, i + 1, j + 1), node(o, i, j + 1)};
      const bool on[4] = {j == 0, i == n0 - 1, j == n1 - 1, i == 0};
      if (!o.triangles) {
        block.connectivity.insert(block.connectivity.end(), c, c + 4);
        for (int s = 0; s < 4; ++s)
          if (on[s])
            mesh.sideSets[s].sides.push_back({element, s});
        ++element;
        continue;
      }
      // (c0, c1, c2): sides 0, 1 of the quadrilateral; (c0, c2, c3): its sides 2, 3.
      block.connectivity.insert(block.connectivity.end(), {c[0], c[1], c[2], c[0], c[2], c[3]});
      for (int s = 0; s < 2; ++s)
        if (on[s])
          mesh.sideSets[s].sides.push_back({element, s});
      for (int s = 2; s < 4; ++s)
        if (on[s])
          mesh.sideSets[s].sides.push_back({element + 1, s - 1});
      element += 2;
    }
  mesh.blocks.push_back(std::move(block));
}

// The text listing of the header comment; exits with status 2 when it is malformed.
impm::BodyMesh readText(const std::string& path) {
  std::ifstream in(path);
  if (!in)
    usage("cannot read " + path);
  const auto bad = [&](const std::string& what) { usage(path + ": " + what); };
  impm::BodyMesh mesh;
  std::string word;
  std::size_t count = 0;
  if (!(in >> word >> count) || word != "nodes")
    bad("expected 'nodes N'");
  mesh.nodes.resize(count);
  for (auto& n : mesh.nodes)
    if (!(in >> n[0] >> n[1]))
      bad("expected node coordinates");
  int id = 0;
  while (in >> word) {
    std::string name, type;
    if (word == "block") {
      impm::BodyMesh::Block b;
      if (!(in >> name >> type >> count) || (type != "QUAD4" && type != "TRI3"))
        bad("expected 'block NAME QUAD4|TRI3 COUNT'");
      b.id = ++id, b.name = name, b.nodesPerElement = type == "QUAD4" ? 4 : 3;
      b.connectivity.resize(count * b.nodesPerElement);
      for (int& n : b.connectivity)
        if (!(in >> n) || n < 1 || n > static_cast<int>(mesh.nodes.size()))
          bad("block " + name + ": expected node numbers 1 to " +
              std::to_string(mesh.nodes.size()));
        else
          --n;
      mesh.blocks.push_back(std::move(b));
    } else if (word == "sideset") {
      impm::BodyMesh::SideSet s;
      if (!(in >> name >> count))
        bad("expected 'sideset NAME COUNT'");
      s.id = static_cast<int>(mesh.sideSets.size()) + 1, s.name = name;
      s.sides.resize(count);
      for (auto& side : s.sides) {
        if (!(in >> side[0] >> side[1]))
          bad("sideset " + name + ": expected 'element side'");
        --side[0], --side[1];
      }
      mesh.sideSets.push_back(std::move(s));
    } else {
      bad("unexpected '" + word + "'");
    }
  }
  return mesh;
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  impm::BodyMesh mesh;
  if (o.kind == "text") {
    mesh = readText(o.in);
  } else {
    mesh.nodes = nodes(o);
    elements(o, mesh);
  }
  try {
    impm::writeBodyMesh(o.out, mesh, "impm_mesh " + o.kind);
  } catch (const impm::FileError& e) {
    std::cerr << "impm_mesh: " << e.file() << ": " << e.what() << "\n";
    return 2;
  }
  std::cout << "impm_mesh: " << o.out << ": " << mesh.numElements() << " elements, "
            << mesh.nodes.size() << " nodes\n";
  return 0;
}

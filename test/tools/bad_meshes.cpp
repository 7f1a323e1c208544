// Writes the broken body meshes of the bad-input tests into the directory given: each is a
// small mesh inside [0, 2]^2 with a side set "inner", wrong in one way.
//   clockwise.exo   an element numbered clockwise (non-positive area)
//   folded.exo      a non-convex quadrilateral
//   bars.exo        a block of BAR2 elements
//   two_blocks.exo  blocks "ring" and "other"; side set "inner" lists edges of "other" only

#include <iostream>
#include <string>

#include "core/Errors.hpp"
#include "io/MeshFile.hpp"

namespace {

// Two unit squares side by side in [0, 2] x [0, 1], in two blocks when `split`.
impm::BodyMesh squares(bool split) {
  impm::BodyMesh m;
  m.nodes = {{0, 0}, {1, 0}, {2, 0}, {0, 1}, {1, 1}, {2, 1}};
  impm::BodyMesh::Block a;
  a.id = 1, a.name = split ? "ring" : "body", a.connectivity = {0, 1, 4, 3};
  impm::BodyMesh::Block b = a;
  b.id = 2, b.name = "other", b.connectivity = {1, 2, 5, 4};
  if (split) {
    m.blocks = {a, b};
  } else {
    a.connectivity.insert(a.connectivity.end(), b.connectivity.begin(), b.connectivity.end());
    m.blocks = {a};
  }
  impm::BodyMesh::SideSet s;
  s.id = 1, s.name = "inner", s.sides = {{1, 1}};  // the second square's right side
  m.sideSets = {s};
  return m;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: bad_meshes DIRECTORY\n";
    return 2;
  }
  const std::string dir = argv[1];
  try {
    auto clockwise = squares(false);
    clockwise.blocks[0].connectivity = {0, 1, 4, 3, 1, 4, 5, 2};
    impm::writeBodyMesh(dir + "/clockwise.exo", clockwise, "clockwise");
    auto folded = squares(false);
    folded.nodes[4] = {0.2, 0.2};
    impm::writeBodyMesh(dir + "/folded.exo", folded, "folded");
    auto bars = squares(false);
    bars.blocks[0].type = "BAR2", bars.blocks[0].nodesPerElement = 2;
    bars.blocks[0].connectivity = {0, 1, 1, 2};
    bars.sideSets.clear();
    impm::writeBodyMesh(dir + "/bars.exo", bars, "bars");
    impm::writeBodyMesh(dir + "/two_blocks.exo", squares(true), "two blocks");
  } catch (const impm::FileError& e) {
    std::cerr << "bad_meshes: " << e.file() << ": " << e.what() << "\n";
    return 1;
  }
  return 0;
}

#pragma once
// A 2-D body-fitted mesh in an Exodus II file (exodusII library): nodes, element blocks of
// QUAD4 or TRI3 elements and side sets, as they are in the file.  The reader checks the file's
// structure only (element types, sizes, side numbers); the geometry (positive areas, convex
// quadrilaterals) is checked by the body made from it (app/shapes/Mesh).  The writer makes
// the meshes of the tests and benchmarks (drivers/impm_mesh).

#include <array>
#include <string>
#include <vector>

namespace impm {

struct BodyMesh {
  struct Block {
    int id = 0;
    std::string name;               // the file's name, or the id in decimal when unnamed
    std::string type;               // as in the file; the writer: "" for QUAD4 or TRI3
    int nodesPerElement = 4;        // 4: QUAD4, 3: TRI3
    std::vector<int> connectivity;  // 0-based node indices, counter-clockwise
  };
  struct SideSet {
    int id = 0;
    std::string name;  // as for blocks
    // (element, side): the element's 0-based index over all blocks in file order and the
    // 0-based local side (Exodus side k + 1 joins local nodes k and k + 1, cyclically).
    std::vector<std::array<int, 2>> sides;
  };
  std::vector<std::array<double, 2>> nodes;
  std::vector<Block> blocks;
  std::vector<SideSet> sideSets;

  std::size_t numElements() const;
};

// Throws FileError(path, reason) for a missing or unreadable file, a mesh that is not 2-D,
// an element type other than QUAD4/TRI3 in a block that has elements (an empty block is kept,
// with no connectivity), or a side naming an element or side that does not exist.
BodyMesh readBodyMesh(const std::string& path);

// Writes the mesh (overwriting); throws FileError when the file cannot be written.
void writeBodyMesh(const std::string& path, const BodyMesh& mesh, const std::string& title);

}  // namespace impm

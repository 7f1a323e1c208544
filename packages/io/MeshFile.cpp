#include "io/MeshFile.hpp"

#include <exodusII.h>

#include <algorithm>
#include <cctype>

#include "core/Errors.hpp"
#include "io/InputFile.hpp"

namespace impm {

std::size_t BodyMesh::numElements() const {
  std::size_t n = 0;
  for (const auto& b : blocks)
    n += b.connectivity.size() / b.nodesPerElement;
  return n;
}

namespace {

// Closes the file however the reader leaves.
class ExodusHandle {
 public:
  ExodusHandle(int id) : id_(id) {}
  ~ExodusHandle() {
    if (id_ >= 0)
      ex_close(id_);
  }
  ExodusHandle(const ExodusHandle&) = delete;
  ExodusHandle& operator=(const ExodusHandle&) = delete;
  int id() const { return id_; }

 private:
  int id_;
};

void check(int status, const std::string& path, const std::string& what) {
  if (status < 0)
    throw FileError(path, "cannot read the Exodus mesh (" + what + ")");
}

// The names of the blocks or side sets, or their ids where the file has none.
std::vector<std::string> names(int file, ex_entity_type type, const std::vector<int>& ids,
                               const std::string& path) {
  const std::size_t width = 1024;
  std::vector<std::vector<char>> buffers(ids.size(), std::vector<char>(width + 1, '\0'));
  std::vector<char*> pointers;
  for (auto& b : buffers)
    pointers.push_back(b.data());
  if (!ids.empty())
    check(ex_get_names(file, type, pointers.data()), path, "names");
  std::vector<std::string> out;
  for (std::size_t k = 0; k < ids.size(); ++k) {
    std::string n(buffers[k].data());
    while (!n.empty() && std::isspace(static_cast<unsigned char>(n.back())))
      n.pop_back();
    out.push_back(n.empty() ? std::to_string(ids[k]) : n);
  }
  return out;
}

// QUAD4 (QUAD, QUAD4, SHELL4) or TRI3 (TRI, TRI3, TRIANGLE); 0 for anything else.
int supportedNodes(std::string type, int nodes) {
  std::transform(type.begin(), type.end(), type.begin(),
                 [](unsigned char c) { return std::toupper(c); });
  if (nodes == 4 && (type == "QUAD" || type == "QUAD4" || type == "SHELL4"))
    return 4;
  if (nodes == 3 && (type == "TRI" || type == "TRI3" || type == "TRIANGLE"))
    return 3;
  return 0;
}

void readBlocks(int file, int numBlocks, int numNodes, const std::string& path, BodyMesh& mesh) {
  std::vector<int> ids(numBlocks);
  if (numBlocks > 0)
    check(ex_get_elem_blk_ids(file, ids.data()), path, "block ids");
  const auto blockNames = names(file, EX_ELEM_BLOCK, ids, path);
  for (int b = 0; b < numBlocks; ++b) {
    char type[MAX_STR_LENGTH + 1] = {};
    int count = 0, nodes = 0, attributes = 0;
    check(ex_get_elem_block(file, ids[b], type, &count, &nodes, &attributes), path, "block");
    BodyMesh::Block block;
    block.id = ids[b], block.name = blockNames[b], block.type = type;
    block.nodesPerElement = supportedNodes(type, nodes);
    if (count == 0) {  // an empty block (Exodus' "NULL" type): a body made of it is refused
      block.nodesPerElement = std::max(block.nodesPerElement, 4);
      mesh.blocks.push_back(std::move(block));
      continue;
    }
    if (block.nodesPerElement == 0)
      throw FileError(path, "element block '" + block.name + "' has " + type + " elements (" +
                                std::to_string(nodes) + " nodes); a body mesh takes QUAD4 or TRI3");
    block.connectivity.resize(static_cast<std::size_t>(count) * nodes);
    if (count > 0)
      check(ex_get_elem_conn(file, ids[b], block.connectivity.data()), path, "connectivity");
    for (int& n : block.connectivity) {
      if (n < 1 || n > numNodes)
        throw FileError(path, "element block '" + block.name + "' names node " + std::to_string(n) +
                                  " of " + std::to_string(numNodes));
      --n;
    }
    mesh.blocks.push_back(std::move(block));
  }
}

void readSideSets(int file, int numSets, const std::string& path, BodyMesh& mesh) {
  std::vector<int> ids(numSets);
  if (numSets > 0)
    check(ex_get_side_set_ids(file, ids.data()), path, "side set ids");
  const auto setNames = names(file, EX_SIDE_SET, ids, path);
  // The first element of each block, and its side count, to check the sides.
  std::vector<int> sidesOf;
  for (const auto& b : mesh.blocks)
    sidesOf.insert(sidesOf.end(), b.connectivity.size() / b.nodesPerElement, b.nodesPerElement);
  for (int s = 0; s < numSets; ++s) {
    int count = 0, factors = 0;
    check(ex_get_side_set_param(file, ids[s], &count, &factors), path, "side set");
    std::vector<int> elements(count), sides(count);
    if (count > 0)
      check(ex_get_side_set(file, ids[s], elements.data(), sides.data()), path, "side set");
    BodyMesh::SideSet set;
    set.id = ids[s], set.name = setNames[s];
    for (int k = 0; k < count; ++k) {
      const int e = elements[k] - 1, side = sides[k] - 1;
      if (e < 0 || e >= static_cast<int>(sidesOf.size()) || side < 0 || side >= sidesOf[e])
        throw FileError(path, "side set '" + set.name + "' names side " + std::to_string(sides[k]) +
                                  " of element " + std::to_string(elements[k]) +
                                  ", which the mesh does not have");
      set.sides.push_back({e, side});
    }
    mesh.sideSets.push_back(std::move(set));
  }
}

}  // namespace

BodyMesh readBodyMesh(const std::string& path) {
  if (const std::string why = notAnInputFile(path, "the mesh file does not exist"); !why.empty())
    throw FileError(path, why);
  int cpuWordSize = sizeof(double), ioWordSize = 0;
  float version = 0;
  const int saved = ex_opts(0);  // the library's own messages would repeat ours
  ExodusHandle file(ex_open(path.c_str(), EX_READ, &cpuWordSize, &ioWordSize, &version));
  ex_opts(saved);
  if (file.id() < 0)
    throw FileError(path, "is not an Exodus II file (or cannot be read)");
  char title[MAX_LINE_LENGTH + 1] = {};
  int dim = 0, numNodes = 0, numElements = 0, numBlocks = 0, numNodeSets = 0, numSideSets = 0;
  check(ex_get_init(file.id(), title, &dim, &numNodes, &numElements, &numBlocks, &numNodeSets,
                    &numSideSets),
        path, "sizes");
  if (dim != 2)
    throw FileError(path, "the mesh is " + std::to_string(dim) + "-D; a body mesh is 2-D");
  if (numElements == 0)
    throw FileError(path, "the mesh has no element");
  BodyMesh mesh;
  std::vector<double> x(numNodes), y(numNodes);
  check(ex_get_coord(file.id(), x.data(), y.data(), nullptr), path, "coordinates");
  for (int n = 0; n < numNodes; ++n)
    mesh.nodes.push_back({x[n], y[n]});
  readBlocks(file.id(), numBlocks, numNodes, path, mesh);
  readSideSets(file.id(), numSideSets, path, mesh);
  return mesh;
}

void writeBodyMesh(const std::string& path, const BodyMesh& mesh, const std::string& title) {
  int cpuWordSize = sizeof(double), ioWordSize = sizeof(double);
  ExodusHandle file(ex_create(path.c_str(), EX_CLOBBER, &cpuWordSize, &ioWordSize));
  const auto fail = [&](int status, const char* what) {
    if (status < 0)
      throw FileError(path, std::string("cannot write the Exodus mesh (") + what + ")");
  };
  fail(file.id(), "create");
  const int numNodes = static_cast<int>(mesh.nodes.size());
  fail(ex_put_init(file.id(), title.c_str(), 2, numNodes, static_cast<int>(mesh.numElements()),
                   static_cast<int>(mesh.blocks.size()), 0, static_cast<int>(mesh.sideSets.size())),
       "sizes");
  std::vector<double> x, y;
  for (const auto& n : mesh.nodes)
    x.push_back(n[0]), y.push_back(n[1]);
  fail(ex_put_coord(file.id(), x.data(), y.data(), nullptr), "coordinates");
  std::vector<std::string> blockNames, setNames;
  for (const auto& b : mesh.blocks) {
    const int count = static_cast<int>(b.connectivity.size() / b.nodesPerElement);
    const std::string type = !b.type.empty() ? b.type : b.nodesPerElement == 4 ? "QUAD4" : "TRI3";
    fail(ex_put_elem_block(file.id(), b.id, type.c_str(), count, b.nodesPerElement, 0), "block");
    std::vector<int> connectivity(b.connectivity);
    for (int& n : connectivity)
      ++n;
    if (count > 0)  // an empty block has no connectivity variable
      fail(ex_put_elem_conn(file.id(), b.id, connectivity.data()), "connectivity");
    blockNames.push_back(b.name);
  }
  for (const auto& s : mesh.sideSets) {
    fail(ex_put_side_set_param(file.id(), s.id, static_cast<int>(s.sides.size()), 0), "side set");
    std::vector<int> elements, sides;
    for (const auto& side : s.sides)
      elements.push_back(side[0] + 1), sides.push_back(side[1] + 1);
    fail(ex_put_side_set(file.id(), s.id, elements.data(), sides.data()), "side set");
    setNames.push_back(s.name);
  }
  const auto put = [&](ex_entity_type type, const std::vector<std::string>& n) {
    std::vector<char*> c;
    for (const auto& s : n)
      c.push_back(const_cast<char*>(s.c_str()));
    if (!c.empty())
      fail(ex_put_names(file.id(), type, c.data()), "names");
  };
  put(EX_ELEM_BLOCK, blockNames);
  put(EX_SIDE_SET, setNames);
}

}  // namespace impm

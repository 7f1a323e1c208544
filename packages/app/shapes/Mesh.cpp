#include "app/shapes/Mesh.hpp"

#include <algorithm>
#include <cmath>

#include "core/Errors.hpp"
#include "core/Parameters.hpp"
#include "io/MeshFile.hpp"

namespace impm {

namespace {

using Point = std::array<double, 2>;

double cross(const Point& o, const Point& a, const Point& b) {
  return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

// Shoelace area and centroid of the polygon of corners (a repeated corner adds nothing).
double areaAndCentroid(const std::array<Point, 4>& c, double centroid[2]) {
  double area = 0.0;
  centroid[0] = centroid[1] = 0.0;
  for (int k = 0; k < 4; ++k) {
    const Point &a = c[k], &b = c[(k + 1) % 4];
    const double w = a[0] * b[1] - b[0] * a[1];
    area += w;
    for (int d = 0; d < 2; ++d)
      centroid[d] += (a[d] + b[d]) * w;
  }
  for (int d = 0; d < 2; ++d)
    centroid[d] /= 3.0 * area;
  return area / 2.0;
}

// Exodus local side -> edge of the corner polygon (a triangle's third side closes it).
int edgeOfSide(int nodesPerElement, int side) {
  return nodesPerElement == 3 && side == 2 ? 3 : side;
}

// The names listed in Element Blocks (all blocks when it is empty), checked.
std::vector<bool> chosenBlocks(const BodyMesh& mesh, const Teuchos::ParameterList& params,
                               const std::string& path, const std::string& file) {
  const auto& wanted = params.get<Teuchos::Array<std::string>>("Element Blocks");
  std::vector<bool> chosen(mesh.blocks.size(), wanted.empty());
  for (const auto& name : wanted) {
    bool found = false;
    for (std::size_t b = 0; b < mesh.blocks.size(); ++b)
      if (mesh.blocks[b].name == name) {
        if (mesh.blocks[b].connectivity.empty())
          throw InputError(path + "/Element Blocks",
                           "element block '" + name + "' of " + file + " has no elements");
        chosen[b] = found = true;
      }
    if (!found)
      throw InputError(path + "/Element Blocks", file + " has no element block '" + name + "'");
  }
  return chosen;
}

}  // namespace

void Mesh::declareParameters(Teuchos::ParameterList& valid) {
  declareString(valid, "Mesh File", "body.exo",
                "2-D: the Exodus II mesh (QUAD4 and TRI3 element blocks), relative to the deck's "
                "directory",
                true);
  declareStringArray(valid, "Element Blocks", {},
                     "2-D: the element blocks (names, or ids where the file names none) that "
                     "make the body; empty: all of them");
}

Mesh::Mesh(const Teuchos::ParameterList& params, const std::string& path) {
  const std::string file = file_ = params.get<std::string>("Mesh File");
  const BodyMesh mesh = readBodyMesh(file);
  if (mesh.sideSets.size() > 52)
    throw FileError(file, "has more than 52 side sets");
  for (const auto& s : mesh.sideSets)
    sideSets_.push_back(s.name);
  const auto chosen = chosenBlocks(mesh, params, path, file);
  std::vector<int> index;  // file element -> element of this body, or -1
  int fileElement = 0;
  for (std::size_t b = 0; b < mesh.blocks.size(); ++b) {
    const auto& block = mesh.blocks[b];
    const int n = block.nodesPerElement;
    for (std::size_t e = 0; e < block.connectivity.size() / n; ++e, ++fileElement) {
      if (!chosen[b]) {
        index.push_back(-1);
        continue;
      }
      Corners c;
      for (int k = 0; k < 4; ++k)
        c[k] = mesh.nodes[block.connectivity[e * n + std::min(k, n - 1)]];
      const std::string which =
          "element " + std::to_string(fileElement + 1) + " (block '" + block.name + "') of " + file;
      double centre[2];
      if (!(areaAndCentroid(c, centre) > 0))
        throw InputError(path + "/Mesh File",
                         which + " has a non-positive area (corners not counter-clockwise?)");
      for (int k = 0; n == 4 && k < 4; ++k)
        if (!(cross(c[k], c[(k + 1) % 4], c[(k + 2) % 4]) > 0))
          throw InputError(path + "/Mesh File", which + " is not a convex quadrilateral");
      index.push_back(static_cast<int>(elements_.size()));
      elements_.push_back(c);
      faces_.push_back({0, 0, 0, 0});
    }
  }
  if (elements_.empty())
    throw InputError(path + "/Element Blocks", file + " has no element in the chosen blocks");
  edgesOn_.assign(mesh.sideSets.size(), 0);
  for (std::size_t s = 0; s < mesh.sideSets.size(); ++s)
    for (const auto& side : mesh.sideSets[s].sides) {
      const int e = index[side[0]];
      if (e < 0)
        continue;
      ++edgesOn_[s];
      const int n = elements_[e][3] == elements_[e][2] ? 3 : 4;
      faces_[e][edgeOfSide(n, side[1])] += std::ldexp(1.0, static_cast<int>(s));
    }
  lower_ = upper_ = elements_[0][0];
  for (const auto& c : elements_)
    for (const auto& p : c)
      for (int d = 0; d < 2; ++d)
        lower_[d] = std::min(lower_[d], p[d]), upper_[d] = std::max(upper_[d], p[d]);
  // About one element per bucket.
  const double side = std::sqrt((upper_[0] - lower_[0]) * (upper_[1] - lower_[1]) /
                                static_cast<double>(elements_.size()));
  for (int d = 0; d < 2; ++d) {
    buckets_[d] = std::max(1, std::min(4096, static_cast<int>((upper_[d] - lower_[d]) / side)));
    bucketSize_[d] = (upper_[d] - lower_[d]) / buckets_[d];
  }
  bucket_.resize(static_cast<std::size_t>(buckets_[0]) * buckets_[1]);
  const auto cellOf = [&](int d, double x) {
    return std::clamp(static_cast<int>((x - lower_[d]) / bucketSize_[d]), 0, buckets_[d] - 1);
  };
  for (std::size_t e = 0; e < elements_.size(); ++e) {
    Point lo = elements_[e][0], hi = lo;
    for (const auto& p : elements_[e])
      for (int d = 0; d < 2; ++d)
        lo[d] = std::min(lo[d], p[d]), hi[d] = std::max(hi[d], p[d]);
    for (int j = cellOf(1, lo[1]); j <= cellOf(1, hi[1]); ++j)
      for (int i = cellOf(0, lo[0]); i <= cellOf(0, hi[0]); ++i)
        bucket_[static_cast<std::size_t>(j) * buckets_[0] + i].push_back(static_cast<int>(e));
  }
}

bool Mesh::inElement(std::size_t e, const double* x) const {
  const auto& c = elements_[e];
  const Point p = {x[0], x[1]};
  for (int k = 0; k < 4; ++k) {
    const Point &a = c[k], &b = c[(k + 1) % 4];
    if (a == b)
      continue;
    const double length2 = (b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]);
    if (cross(a, b, p) < -1e-12 * length2)  // closed: a point on an edge is inside
      return false;
  }
  return true;
}

bool Mesh::contains(const double* x) const {
  for (int d = 0; d < 2; ++d)
    if (x[d] < lower_[d] || x[d] > upper_[d])
      return false;
  int cell[2];
  for (int d = 0; d < 2; ++d)
    cell[d] = std::clamp(static_cast<int>((x[d] - lower_[d]) / bucketSize_[d]), 0, buckets_[d] - 1);
  for (int e : bucket_[static_cast<std::size_t>(cell[1]) * buckets_[0] + cell[0]])
    if (inElement(e, x))
      return true;
  return false;
}

std::vector<Seed<2>> Mesh::fill(const GridGeometry<2>& grid, int perCell, bool gauss) const {
  if (gauss)
    return subCellFill<2>(*this, grid, perCell, gauss);
  std::vector<Seed<2>> seeds(elements_.size());
  for (std::size_t e = 0; e < elements_.size(); ++e) {
    Seed<2>& s = seeds[e];
    s.volume = areaAndCentroid(elements_[e], s.x);
    s.half[0][0] = s.half[1][1] = 0.5 * std::sqrt(s.volume);  // the square of equal area
    s.half[0][1] = s.half[1][0] = 0.0;
  }
  return seeds;
}

void Mesh::seedCorners(std::size_t k, double corner[4][2], double faces[4]) const {
  for (int c = 0; c < 4; ++c) {
    for (int d = 0; d < 2; ++d)
      corner[c][d] = elements_[k][c][d];
    faces[c] = faces_[k][c];
  }
}

}  // namespace impm

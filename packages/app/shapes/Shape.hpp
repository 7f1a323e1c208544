#pragma once
// The region a body occupies in the reference configuration, and the integration points that
// fill it.  One file per shape (Interval, Box, Ball, Cylinder, Polygon, ...); ShapeFactory turns
// Bodies/<name>/Shape into one.  A shape answers two questions: is a point material
// (contains), and which particles, with their domains and volumes, fill the body (fill).
// The 2-D and 3-D shapes given by numbers are filled on the grid (SubCellShape): a particle at
// the centre of every n x n (x n) sub-cell whose centre the shape contains, the sub-cell being its
// domain, and fem's Gauss points in the cells whose centre it contains.  A shape that knows better
// (the 1-D interval's equal particles, a mesh's elements, an image's pixels) fills itself. Shapes
// that carry boundary names (a mesh's side sets) list them: the bit k of a seed's face mask is
// sideSets()[k].

#include <array>
#include <string>
#include <vector>

#include "core/Grid.hpp"

namespace impm {

// An integration point before it becomes a particle: position, domain half-vectors r_k
// (columns: half[a][k] is component a of r_k) and volume (1-D: length).  Kept small: an
// image of 16 million pixels makes as many.
template <int Dim>
struct Seed {
  double x[Dim];
  double half[Dim][Dim];
  double volume;
};

template <int Dim>
class Shape {
 public:
  virtual ~Shape() = default;

  // True when x lies in the shape (closed: a point on the boundary is inside).
  virtual bool contains(const double* x) const = 0;
  // Bounding box: lower()[d] <= x[d] <= upper()[d].
  const std::array<double, Dim>& lower() const { return lower_; }
  const std::array<double, Dim>& upper() const { return upper_; }
  // Distance from x to the bounding box (0 inside it).
  double boxDistance(const double* x) const;
  // The deck parameter that places the shape (named when the body leaves the grid).
  virtual std::string placement() const = 0;

  // Material points (perCell per cell and direction) or, with gauss, fem's Gauss points (2
  // per cell and direction), in a rank-independent order.
  virtual std::vector<Seed<Dim>> fill(const GridGeometry<Dim>& grid, int perCell,
                                      bool gauss) const = 0;
  // True when the seeds have corners of their own (mesh elements): seedCorners gives those
  // of seed k of fill, counter-clockwise (a triangle repeats its last corner), and for each
  // face f (corner f to corner f + 1) the bit mask of the side sets that hold it.
  virtual bool hasCorners() const { return false; }
  virtual void seedCorners(std::size_t /*k*/, double /*corner*/[1 << Dim][Dim],
                           double /*faces*/[2 * Dim]) const {}
  // The named parts of the boundary the seeds' face masks refer to.
  virtual const std::vector<std::string>& sideSets() const {
    static const std::vector<std::string> none;
    return none;
  }
  // How many of the body's faces side set k holds.
  virtual int edgesOn(int /*sideSet*/) const { return 0; }
  // The file the shape was read from ("" for shapes given by numbers).
  virtual std::string source() const { return ""; }

 protected:
  std::array<double, Dim> lower_{}, upper_{};
};

// The sub-cell filling (above) of any shape of 2 or 3 dimensions: n^Dim sub-cells per cell.
template <int Dim>
std::vector<Seed<Dim>> subCellFill(const Shape<Dim>& shape, const GridGeometry<Dim>& grid,
                                   int perCell, bool gauss);

// A shape filled on the grid's sub-cells (above).
template <int Dim>
class SubCellShape : public Shape<Dim> {
 public:
  std::vector<Seed<Dim>> fill(const GridGeometry<Dim>& grid, int perCell,
                              bool gauss) const override {
    return subCellFill<Dim>(*this, grid, perCell, gauss);
  }
};

}  // namespace impm

#pragma once
// A 2-D body from a body-fitted mesh (an Exodus II file of QUAD4 and TRI3 elements): the
// primer's "conforming" particle domains of section 1.6.2.  Every element of the chosen
// element blocks becomes one particle at the element's centroid with the element's exact
// area; with cpdi its domain is the element itself (four tracked corners, CPDI2; a triangle
// is the quadrilateral whose last two corners coincide, CPTI), with gimp the axis-aligned
// square of the same area.  Several bodies may read one file with different blocks: element
// blocks map to materials.  The mesh's side sets name boundary edges for tractions.  fem
// fills the grid's cells whose centre lies in an element.
//
// The elements are checked before anything runs: counter-clockwise with positive area, and
// quadrilaterals convex (the bilinear map of a non-convex one folds over).

#include <Teuchos_ParameterList.hpp>

#include <array>

#include "app/shapes/Shape.hpp"

namespace impm {

class Mesh : public Shape<2> {
 public:
  static void declareParameters(Teuchos::ParameterList& valid);
  // Reads and checks the mesh; throws FileError for an unreadable file and InputError
  // naming <path>/Mesh File (or Element Blocks) for a bad element or an unknown block.
  Mesh(const Teuchos::ParameterList& params, const std::string& path);

  bool contains(const double* x) const override;
  std::string placement() const override { return "Mesh File"; }
  std::vector<Seed<2>> fill(const GridGeometry<2>& grid, int perCell, bool gauss) const override;
  bool hasCorners() const override { return true; }
  void seedCorners(std::size_t k, double corner[4][2], double faces[4]) const override;
  const std::vector<std::string>& sideSets() const override { return sideSets_; }
  int edgesOn(int sideSet) const override { return edgesOn_.at(sideSet); }
  std::string source() const override { return file_; }

 private:
  using Corners = std::array<std::array<double, 2>, 4>;
  bool inElement(std::size_t e, const double* x) const;

  std::vector<Corners> elements_;
  std::vector<std::array<double, 4>> faces_;  // per element and edge: side-set bit mask
  std::vector<std::string> sideSets_;
  std::vector<int> edgesOn_;  // per side set: the faces of this body it holds
  std::string file_;
  // Elements by the cells of a bucket grid over the bounding box, for contains().
  std::array<int, 2> buckets_{};
  std::array<double, 2> bucketSize_{};
  std::vector<std::vector<int>> bucket_;
};

}  // namespace impm

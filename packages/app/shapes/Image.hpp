#pragma once
// A 2-D body read from a grayscale image (a CT slice, the primer's "Lego model" of section
// 1.6.2): the pixels whose gray level lies in Gray Range.  Pixel (row, column) of the file,
// row 0 at the top as image viewers show it, is the square
//   [x0 + column h, x0 + (column + 1) h] x [y0 + (rows - 1 - row) h, y0 + (rows - row) h]
// with h = Pixel Size and (x0, y0) = Image Origin, the image's lower-left corner.  Each
// selected pixel becomes n x n particles (Particles Per Pixel) at the centres of its n x n
// sub-squares, each sub-square the particle's domain, so the domains tile the pixels exactly
// and the boundary is the pixels' staircase.  Several bodies may read the same image with
// different ranges: one image holds several materials.  fem fills the grid's cells whose
// centre lies in a selected pixel.

#include <Teuchos_ParameterList.hpp>

#include "app/shapes/Shape.hpp"
#include "io/ImageFile.hpp"

namespace impm {

class Image : public SubCellShape<2> {
 public:
  static void declareParameters(Teuchos::ParameterList& valid);
  // Reads the image; throws FileError for an unreadable file and InputError naming
  // <path>/Gray Range when no pixel lies in the range.
  Image(const Teuchos::ParameterList& params, const std::string& path);

  bool contains(const double* x) const override;
  std::string placement() const override { return "Image Origin"; }
  std::vector<Seed<2>> fill(const GridGeometry<2>& grid, int perCell, bool gauss) const override;

 private:
  bool selected(int row, int column) const;

  GrayImage image_;
  std::array<double, 2> origin_{};
  double pixel_ = 1.0;
  int lowest_ = 0, highest_ = 0, perPixel_ = 1;
};

}  // namespace impm

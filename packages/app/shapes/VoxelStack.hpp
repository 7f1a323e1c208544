#pragma once
// A 3-D body read from a stack of grayscale slices (a CT scan): Shape = image in a 3-D deck.
// Image File names either a multi-page TIFF (page k is slice k) or a printf-style pattern of
// PNG or TIFF files with the slice index (slice_%03d.png), over Slices = {first, last}.  The
// slices are read one at a time and only which voxels lie in Gray Range is kept (a bit a
// voxel): never the whole stack.  Voxel (slice k, row, column) is the box
//   [x0 + column h, x0 + (column + 1) h] x [y0 + (rows - 1 - row) h, y0 + (rows - row) h]
//   x [z0 + l t, z0 + (l + 1) t]
// with h = Pixel Size, t = Slice Thickness (h when 0), (x0, y0, z0) = Image Origin and
// l = k - first (Slice Order = bottom to top) or last - k (top to bottom): each slice as an
// image viewer shows it, seen from above (+z towards the viewer).  Each selected voxel becomes
// n x n x n particles (Particles Per Pixel) at the centres of its sub-boxes, their domains.

#include <Teuchos_ParameterList.hpp>

#include <cstdint>
#include <vector>

#include "app/shapes/Shape.hpp"

namespace impm {

class VoxelStack : public Shape<3> {
 public:
  // The 3-D parameters of [Shape=image] (the 2-D image declares the shared ones).
  static void declareParameters(Teuchos::ParameterList& valid);
  // Reads the slices; throws FileError for an unreadable slice or slices of other sizes, and
  // InputError naming <path>/Gray Range when no voxel lies in the range.
  VoxelStack(const Teuchos::ParameterList& params, const std::string& path);

  bool contains(const double* x) const override;
  std::string placement() const override { return "Image Origin"; }
  std::string source() const override { return file_; }
  std::vector<Seed<3>> fill(const GridGeometry<3>& grid, int perCell, bool gauss) const override;

 private:
  // Voxel (column, fromBottom, layer): x, y, z indices from the lower corner.
  bool selected(int column, int fromBottom, int layer) const {
    const std::size_t k =
        (static_cast<std::size_t>(layer) * rows_ + fromBottom) * columns_ + column;
    return (bits_[k / 64] >> (k % 64)) & 1u;
  }

  std::string file_;
  std::vector<std::uint64_t> bits_;
  int columns_ = 0, rows_ = 0, layers_ = 0, perVoxel_ = 1;
  double size_[3] = {};
  std::size_t count_ = 0;  // selected voxels
};

}  // namespace impm

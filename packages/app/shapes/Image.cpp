#include "app/shapes/Image.hpp"

#include <cmath>

#include "core/Errors.hpp"
#include "core/Parameters.hpp"

namespace impm {

void Image::declareParameters(Teuchos::ParameterList& valid) {
  declareString(valid, "Image File", "body.png",
                "The grayscale PNG or TIFF image (8 or 16 bits), relative to the deck's "
                "directory; 3-D: a multi-page TIFF (a page a slice) or a printf-style pattern "
                "of slice files (slice_%03d.png, see Slices)",
                true);
  declareDouble(valid, "Pixel Size", 1.0, "The side of a (square) pixel", Bounds::positive(), true);
  declareDoubleArray(valid, "Image Origin", {0.0, 0.0}, {2, 3},
                     "Position of the image's lower-left corner: (x, y); 3-D: (x, y, z), the "
                     "lower corner of the stack's lowest layer",
                     Bounds::any(), true);
  declareIntArray(valid, "Gray Range", {1, 255}, {2},
                  "The body's pixels (voxels): those with lowest <= gray level <= highest",
                  Bounds::atLeast(0), true);
  declareInt(valid, "Particles Per Pixel", 1,
             "Particles per pixel (voxel) and direction (n x n, 3-D n x n x n, domains tiling it)",
             Bounds::atLeast(1));
}

Image::Image(const Teuchos::ParameterList& params, const std::string& path)
    : image_(readGrayImage(params.get<std::string>("Image File"))) {
  pixel_ = params.get<double>("Pixel Size");
  perPixel_ = params.get<int>("Particles Per Pixel");
  const auto& o = params.get<Teuchos::Array<double>>("Image Origin");
  const auto& range = params.get<Teuchos::Array<int>>("Gray Range");
  lowest_ = range[0], highest_ = range[1];
  if (o.size() != 2)
    throw InputError(path + "/Image Origin",
                     "expected 2 entries (x, y) for a 2-D image, got " + std::to_string(o.size()));
  if (lowest_ > highest_)
    throw InputError(path + "/Gray Range", "the lowest level " + std::to_string(lowest_) +
                                               " is above the highest " + std::to_string(highest_));
  bool any = false;
  for (int r = 0; r < image_.height && !any; ++r)
    for (int c = 0; c < image_.width && !any; ++c)
      any = selected(r, c);
  if (!any)
    throw InputError(path + "/Gray Range", "no pixel of " + params.get<std::string>("Image File") +
                                               " has a gray level in [" + std::to_string(lowest_) +
                                               ", " + std::to_string(highest_) + "]");
  for (int d = 0; d < 2; ++d)
    origin_[d] = o[d];
  lower_ = origin_;
  upper_ = {origin_[0] + pixel_ * image_.width, origin_[1] + pixel_ * image_.height};
}

bool Image::selected(int row, int column) const {
  const int level = image_.at(row, column);
  return lowest_ <= level && level <= highest_;
}

bool Image::contains(const double* x) const {
  const int column = static_cast<int>(std::floor((x[0] - origin_[0]) / pixel_));
  const int fromBottom = static_cast<int>(std::floor((x[1] - origin_[1]) / pixel_));
  if (column < 0 || column >= image_.width || fromBottom < 0 || fromBottom >= image_.height)
    return false;
  return selected(image_.height - 1 - fromBottom, column);
}

std::vector<Seed<2>> Image::fill(const GridGeometry<2>& grid, int perCell, bool gauss) const {
  if (gauss)
    return SubCellShape<2>::fill(grid, perCell, gauss);
  const int n = perPixel_;
  const double h = pixel_ / n;
  std::size_t selectedPixels = 0;
  for (int row = 0; row < image_.height; ++row)
    for (int column = 0; column < image_.width; ++column)
      selectedPixels += selected(row, column);
  std::vector<Seed<2>> seeds;
  seeds.reserve(selectedPixels * n * n);
  // Bottom row first, as the lattice shapes order theirs: the order does not depend on ranks.
  for (int fromBottom = 0; fromBottom < image_.height; ++fromBottom)
    for (int column = 0; column < image_.width; ++column) {
      if (!selected(image_.height - 1 - fromBottom, column))
        continue;
      for (int s = 0; s < n; ++s)
        for (int r = 0; r < n; ++r) {
          Seed<2> seed{};
          seed.x[0] = origin_[0] + column * pixel_ + (r + 0.5) * h;
          seed.x[1] = origin_[1] + fromBottom * pixel_ + (s + 0.5) * h;
          seed.half[0][0] = seed.half[1][1] = h / 2;
          seed.volume = h * h;
          seeds.push_back(seed);
        }
    }
  return seeds;
}

}  // namespace impm

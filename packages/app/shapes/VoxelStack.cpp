#include "app/shapes/VoxelStack.hpp"

#include <cmath>
#include <cstdio>

#include "core/Errors.hpp"
#include "core/Parameters.hpp"
#include "io/ImageFile.hpp"

namespace impm {

void VoxelStack::declareParameters(Teuchos::ParameterList& valid) {
  declareIntArray(valid, "Slices", {0, 0}, {2},
                  "3-D: the first and last slice, the indices put into Image File's pattern "
                  "(a multi-page TIFF: its pages counted from 0; all of them when unset)",
                  Bounds::atLeast(0));
  declareDouble(valid, "Slice Thickness", 0.0,
                "3-D: the voxels' extent along z (0: Pixel Size, cubic voxels)",
                Bounds::atLeast(0.0));
  declareChoice(valid, "Slice Order", "bottom to top", {"bottom to top", "top to bottom"},
                "3-D: whether the first slice is the lowest layer of voxels (z0 to z0 + "
                "thickness) or the highest");
}

namespace {

// Whether a pattern holds one integer conversion (%d, %03d, ...) and no other '%': it goes
// to snprintf.
bool onePlainConversion(const std::string& pattern) {
  const auto at = pattern.find('%');
  auto end = pattern.find_first_not_of("0123456789", at + 1);
  return end != std::string::npos && pattern[end] == 'd' &&
         pattern.find('%', end) == std::string::npos;
}

// The file of slice k: Image File's pattern with k, or the multi-page file itself.
std::string sliceFile(const std::string& file, bool pattern, int k) {
  if (!pattern)
    return file;
  char name[4096];
  std::snprintf(name, sizeof name, file.c_str(), k);
  return name;
}

}  // namespace

VoxelStack::VoxelStack(const Teuchos::ParameterList& params, const std::string& path)
    : file_(params.get<std::string>("Image File")) {
  const bool pattern = file_.find('%') != std::string::npos;
  if (pattern && !onePlainConversion(file_))
    throw InputError(path + "/Image File",
                     "a slice pattern holds one integer conversion "
                     "such as %03d and no other '%', got '" +
                         file_ + "'");
  int first = 0, last = 0;
  if (setInDeck(params, "Slices")) {
    const auto& s = params.get<Teuchos::Array<int>>("Slices");
    first = s[0], last = s[1];
    if (first > last)
      throw InputError(path + "/Slices", "the first slice " + std::to_string(first) +
                                             " is after the last " + std::to_string(last));
  } else if (pattern) {
    throw InputError(path + "/Slices", "Image File is a pattern (" + file_ +
                                           "): give the first and last slice index");
  } else {
    last = grayImagePages(file_) - 1;
  }
  const auto& o = params.get<Teuchos::Array<double>>("Image Origin");
  if (o.size() != 3)
    throw InputError(
        path + "/Image Origin",
        "expected 3 entries (x, y, z) for a voxel stack, got " + std::to_string(o.size()));
  const auto& range = params.get<Teuchos::Array<int>>("Gray Range");
  const bool upward = params.get<std::string>("Slice Order") == "bottom to top";
  layers_ = last - first + 1;
  for (int k = first; k <= last; ++k) {  // one slice in memory at a time
    const std::string name = sliceFile(file_, pattern, k);
    const GrayImage slice = readGrayImage(name, pattern ? 0 : k);
    if (k == first) {
      columns_ = slice.width, rows_ = slice.height;
      bits_.assign((static_cast<std::size_t>(columns_) * rows_ * layers_ + 63) / 64, 0);
    } else if (slice.width != columns_ || slice.height != rows_) {
      throw FileError(name, "is " + std::to_string(slice.width) + " x " +
                                std::to_string(slice.height) + " pixels; the first slice is " +
                                std::to_string(columns_) + " x " + std::to_string(rows_));
    }
    const int layer = upward ? k - first : last - k;
    for (int row = 0; row < rows_; ++row)
      for (int column = 0; column < columns_; ++column) {
        const int level = slice.at(row, column);
        if (level < range[0] || level > range[1])
          continue;
        const std::size_t v =
            (static_cast<std::size_t>(layer) * rows_ + (rows_ - 1 - row)) * columns_ + column;
        bits_[v / 64] |= std::uint64_t(1) << (v % 64);
        ++count_;
      }
  }
  if (count_ == 0)
    throw InputError(path + "/Gray Range", "no voxel of " + file_ + " has a gray level in [" +
                                               std::to_string(range[0]) + ", " +
                                               std::to_string(range[1]) + "]");
  perVoxel_ = params.get<int>("Particles Per Pixel");
  const double h = params.get<double>("Pixel Size"), t = params.get<double>("Slice Thickness");
  size_[0] = size_[1] = h, size_[2] = t > 0 ? t : h;
  const int counts[3] = {columns_, rows_, layers_};
  for (int d = 0; d < 3; ++d)
    lower_[d] = o[d], upper_[d] = o[d] + size_[d] * counts[d];
}

bool VoxelStack::contains(const double* x) const {
  int index[3];
  const int counts[3] = {columns_, rows_, layers_};
  for (int d = 0; d < 3; ++d) {
    index[d] = static_cast<int>(std::floor((x[d] - lower_[d]) / size_[d]));
    if (index[d] < 0 || index[d] >= counts[d])
      return false;
  }
  return selected(index[0], index[1], index[2]);
}

std::vector<Seed<3>> VoxelStack::fill(const GridGeometry<3>& grid, int perCell, bool gauss) const {
  if (gauss)
    return subCellFill<3>(*this, grid, perCell, gauss);
  const int n = perVoxel_;
  double h[3];
  for (int d = 0; d < 3; ++d)
    h[d] = size_[d] / n;
  std::vector<Seed<3>> seeds;
  seeds.reserve(count_ * n * n * n);
  // Lowest layer, then row, then column first, as the lattice shapes order theirs.
  int voxel[3];
  for (voxel[2] = 0; voxel[2] < layers_; ++voxel[2])
    for (voxel[1] = 0; voxel[1] < rows_; ++voxel[1])
      for (voxel[0] = 0; voxel[0] < columns_; ++voxel[0]) {
        if (!selected(voxel[0], voxel[1], voxel[2]))
          continue;
        for (int s = 0; s < n * n * n; ++s) {
          const int sub[3] = {s % n, (s / n) % n, s / (n * n)};
          Seed<3> seed{};
          for (int d = 0; d < 3; ++d) {
            seed.x[d] = lower_[d] + voxel[d] * size_[d] + (sub[d] + 0.5) * h[d];
            seed.half[d][d] = h[d] / 2;
          }
          seed.volume = h[0] * h[1] * h[2];
          seeds.push_back(seed);
        }
      }
  return seeds;
}

}  // namespace impm

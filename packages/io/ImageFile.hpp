#pragma once
// A grayscale image read from a PNG or a TIFF file (libpng, libtiff): the gray level of
// every pixel, row 0 at the top as image viewers show it.  8- and 16-bit (and 1-, 2-, 4-bit
// PNG, expanded to 8); colour images and images with several samples per pixel are refused,
// not converted, so that a gray-level table means what it says.

#include <cstdint>
#include <string>
#include <vector>

namespace impm {

struct GrayImage {
  int width = 0, height = 0;
  int bits = 8;                 // bits per sample of the file (8 or 16 after expansion)
  std::vector<uint16_t> level;  // row-major, row 0 at the top

  int at(int row, int column) const {
    return level[static_cast<std::size_t>(row) * width + column];
  }
};

// Reads the file by its signature (not its name); throws FileError(path, reason) when it is
// missing, unreadable, truncated, not a PNG or TIFF, or not grayscale.  page: the page of a
// multi-page TIFF (counted from 0; a PNG has page 0 only).
GrayImage readGrayImage(const std::string& path, int page = 0);

// The number of pages of a TIFF (1 for a PNG); throws FileError as readGrayImage does.
int grayImagePages(const std::string& path);

}  // namespace impm

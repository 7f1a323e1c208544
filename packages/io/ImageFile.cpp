#include "io/ImageFile.hpp"

#include <png.h>
#include <tiffio.h>

#include <csetjmp>
#include <cstdio>
#include <fstream>
#include <memory>

#include "core/Errors.hpp"
#include "io/InputFile.hpp"

namespace impm {

namespace {

// libpng reports errors through a callback that must not return: it keeps the message and
// jumps back to readPng.
struct PngErrors {
  std::jmp_buf jump;
  std::string message;
};

void pngError(png_structp png, png_const_charp message) {
  auto* errors = static_cast<PngErrors*>(png_get_error_ptr(png));
  errors->message = message;
  std::longjmp(errors->jump, 1);
}

void pngWarning(png_structp, png_const_charp) {}

GrayImage readPng(const std::string& path) {
  std::unique_ptr<FILE, int (*)(FILE*)> file(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!file)
    throw FileError(path, "cannot be opened");
  PngErrors errors;
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &errors, pngError, pngWarning);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!info) {
    png_destroy_read_struct(&png, nullptr, nullptr);
    throw FileError(path, "cannot be read: out of memory");
  }
  GrayImage image;
  std::vector<png_bytep> rows;
  std::vector<unsigned char> bytes;
  bool colour = false;
  // Nothing with a destructor is created between setjmp and the last libpng call.
  if (setjmp(errors.jump)) {
    png_destroy_read_struct(&png, &info, nullptr);
    throw FileError(path, "is not a readable PNG: " + errors.message);
  }
  png_init_io(png, file.get());
  png_read_info(png, info);
  const int type = png_get_color_type(png, info);
  colour = (type & PNG_COLOR_MASK_COLOR) != 0;
  if (!colour) {
    if (type & PNG_COLOR_MASK_ALPHA)
      png_set_strip_alpha(png);
    if (png_get_bit_depth(png, info) < 8)
      png_set_expand_gray_1_2_4_to_8(png);
    png_read_update_info(png, info);
    image.width = static_cast<int>(png_get_image_width(png, info));
    image.height = static_cast<int>(png_get_image_height(png, info));
    image.bits = png_get_bit_depth(png, info);
    const std::size_t stride = png_get_rowbytes(png, info);
    bytes.resize(stride * image.height);
    rows.resize(image.height);
    for (int r = 0; r < image.height; ++r)
      rows[r] = bytes.data() + stride * r;
    png_read_image(png, rows.data());
  }
  png_destroy_read_struct(&png, &info, nullptr);
  if (colour)
    throw FileError(path, "is a colour PNG; impm reads grayscale images (convert it first)");
  image.level.resize(static_cast<std::size_t>(image.width) * image.height);
  const std::size_t stride = bytes.size() / image.height;
  for (int r = 0; r < image.height; ++r)
    for (int c = 0; c < image.width; ++c) {
      const unsigned char* p = bytes.data() + stride * r;
      image.level[static_cast<std::size_t>(r) * image.width + c] =
          image.bits == 16 ? static_cast<uint16_t>(p[2 * c] << 8 | p[2 * c + 1]) : p[c];
    }
  return image;
}

// libtiff prints to stderr unless told otherwise: keep the last message for the error.
std::string& tiffMessage() {
  static std::string message;
  return message;
}

void tiffError(const char* module, const char* format, va_list args) {
  char text[512];
  std::vsnprintf(text, sizeof text, format, args);
  tiffMessage() = (module ? std::string(module) + ": " : std::string()) + text;
}

void tiffWarning(const char*, const char*, va_list) {}

using TiffFile = std::unique_ptr<TIFF, void (*)(TIFF*)>;

// The TIFF at path, libtiff's messages kept for the errors; FileError when it cannot be read.
TiffFile openTiff(const std::string& path) {
  TIFFSetErrorHandler(tiffError);
  TIFFSetWarningHandler(tiffWarning);
  tiffMessage().clear();
  TiffFile tiff(TIFFOpen(path.c_str(), "r"), &TIFFClose);
  if (!tiff)
    throw FileError(path, "is not a readable TIFF: " + tiffMessage());
  return tiff;
}

GrayImage readTiff(const std::string& path, int page) {
  const TiffFile tiff = openTiff(path);
  if (page > 0 && !TIFFSetDirectory(tiff.get(), static_cast<tdir_t>(page)))
    throw FileError(path, "has no page " + std::to_string(page) + " (it has " +
                              std::to_string(TIFFNumberOfDirectories(tiff.get())) +
                              ", counted from 0)");
  uint32_t width = 0, height = 0;
  uint16_t bits = 1, samples = 1, photometric = PHOTOMETRIC_MINISBLACK;
  TIFFGetField(tiff.get(), TIFFTAG_IMAGEWIDTH, &width);
  TIFFGetField(tiff.get(), TIFFTAG_IMAGELENGTH, &height);
  TIFFGetFieldDefaulted(tiff.get(), TIFFTAG_BITSPERSAMPLE, &bits);
  TIFFGetFieldDefaulted(tiff.get(), TIFFTAG_SAMPLESPERPIXEL, &samples);
  TIFFGetFieldDefaulted(tiff.get(), TIFFTAG_PHOTOMETRIC, &photometric);
  if (samples != 1 ||
      (photometric != PHOTOMETRIC_MINISBLACK && photometric != PHOTOMETRIC_MINISWHITE))
    throw FileError(path, "is not a grayscale TIFF (" + std::to_string(samples) +
                              " samples per pixel); impm reads grayscale images");
  if (bits != 8 && bits != 16)
    throw FileError(path, "has " + std::to_string(bits) + " bits per sample; impm reads 8 and 16");
  uint16_t format = SAMPLEFORMAT_UINT;  // signed or float samples read as unsigned were wrong
  TIFFGetFieldDefaulted(tiff.get(), TIFFTAG_SAMPLEFORMAT, &format);
  if (format != SAMPLEFORMAT_UINT && format != SAMPLEFORMAT_VOID)
    throw FileError(path, std::string("has ") +
                              (format == SAMPLEFORMAT_IEEEFP ? "floating-point"
                               : format == SAMPLEFORMAT_INT  ? "signed integer"
                                                             : "complex") +
                              " samples; impm reads unsigned 8- and 16-bit gray levels");
  if (TIFFIsTiled(tiff.get()))
    throw FileError(path, "is a tiled TIFF; impm reads strip TIFFs");
  GrayImage image;
  image.width = static_cast<int>(width), image.height = static_cast<int>(height), image.bits = bits;
  image.level.resize(static_cast<std::size_t>(width) * height);
  std::vector<unsigned char> line(TIFFScanlineSize(tiff.get()));
  const int top = (1 << bits) - 1;
  for (uint32_t r = 0; r < height; ++r) {
    if (TIFFReadScanline(tiff.get(), line.data(), r, 0) < 0)
      throw FileError(path,
                      "is truncated or corrupt at row " + std::to_string(r) + ": " + tiffMessage());
    for (uint32_t c = 0; c < width; ++c) {
      int v = bits == 16 ? reinterpret_cast<const uint16_t*>(line.data())[c] : line[c];
      if (photometric == PHOTOMETRIC_MINISWHITE)
        v = top - v;
      image.level[static_cast<std::size_t>(r) * width + c] = static_cast<uint16_t>(v);
    }
  }
  return image;
}

}  // namespace

namespace {

enum class ImageKind { png, tiff };

// The kind of image file by its signature; FileError when it is none.
ImageKind imageKind(const std::string& path) {
  if (const std::string why = notAnInputFile(path, "the image file does not exist"); !why.empty())
    throw FileError(path, why);
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw FileError(path, "cannot be opened");
  unsigned char signature[8] = {};
  in.read(reinterpret_cast<char*>(signature), sizeof signature);
  in.close();
  if (png_sig_cmp(signature, 0, 8) == 0)
    return ImageKind::png;
  if ((signature[0] == 'I' && signature[1] == 'I') || (signature[0] == 'M' && signature[1] == 'M'))
    return ImageKind::tiff;
  throw FileError(path, "is neither a PNG nor a TIFF image");
}

}  // namespace

GrayImage readGrayImage(const std::string& path, int page) {
  if (imageKind(path) == ImageKind::tiff)
    return readTiff(path, page);
  if (page > 0)
    throw FileError(
        path, "is a PNG, which has one page (page " + std::to_string(page) + " was asked for)");
  return readPng(path);
}

int grayImagePages(const std::string& path) {
  if (imageKind(path) == ImageKind::png)
    return 1;
  return static_cast<int>(TIFFNumberOfDirectories(openTiff(path).get()));
}

}  // namespace impm

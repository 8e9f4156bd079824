// image_raster.cpp -- see image_raster.h.
#include "io/image_raster.h"

#include <gif_lib.h>
#include <png.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "io/mesh_io.h"

namespace grassfire {

namespace {

constexpr std::uint64_t kMaxPixels = std::uint64_t(1) << 28;

void check_size(const std::string& path, std::uint64_t width, std::uint64_t height) {
  if (width == 0 || height == 0) throw ImageFormatError(path + ": the image is empty (0 pixels)");
  if (width * height > kMaxPixels)
    throw ImageFormatError(path + ": the image has " + std::to_string(width * height) + " pixels, more than 2^28");
}

std::uint8_t luminance(const GifColorType& c) {
  return static_cast<std::uint8_t>(std::lround(0.299 * c.Red + 0.587 * c.Green + 0.114 * c.Blue));
}

std::string gif_error(int code) {
  const char* s = GifErrorString(code);
  return s ? s : "unknown GIF error " + std::to_string(code);
}

struct GifCloser {
  void operator()(GifFileType* f) const {
    int error = 0;
    DGifCloseFile(f, &error);
  }
};

}  // namespace

bool is_image_path(const std::string& path) {
  const std::string ext = file_extension(path);
  return ext == "png" || ext == "gif";
}

GrayAlphaImage read_image(const std::string& path) {
  const std::string ext = file_extension(path);
  if (ext == "png") return read_png(path);
  if (ext == "gif") return read_gif(path);
  throw ImageFormatError(path + ": not a .png or .gif file");
}

GrayAlphaImage read_png(const std::string& path) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&image, path.c_str()))
    throw ImageFormatError(path + ": cannot read as PNG (" + image.message + ")");
  image.format = PNG_FORMAT_GA;
  GrayAlphaImage out;
  try {
    check_size(path, image.width, image.height);
  } catch (...) {
    png_image_free(&image);
    throw;
  }
  out.width = image.width, out.height = image.height;
  std::vector<std::uint8_t> ga(PNG_IMAGE_SIZE(image));
  if (!png_image_finish_read(&image, nullptr, ga.data(), 0, nullptr))
    throw ImageFormatError(path + ": corrupt PNG data (" + image.message + ")");
  const std::size_t n = std::size_t(out.width) * out.height;
  out.gray.resize(n), out.alpha.resize(n);
  for (std::size_t i = 0; i < n; ++i) out.gray[i] = ga[2 * i], out.alpha[i] = ga[2 * i + 1];
  return out;
}

GrayAlphaImage read_gif(const std::string& path) {
  int error = 0;
  std::unique_ptr<GifFileType, GifCloser> gif(DGifOpenFileName(path.c_str(), &error));
  if (!gif) throw ImageFormatError(path + ": cannot read as GIF (" + gif_error(error) + ")");
  if (DGifSlurp(gif.get()) != GIF_OK) throw ImageFormatError(path + ": corrupt GIF data (" + gif_error(gif->Error) + ")");
  if (gif->ImageCount < 1) throw ImageFormatError(path + ": the GIF has no image");
  const SavedImage& frame = gif->SavedImages[0];
  const GifImageDesc& d = frame.ImageDesc;
  const ColorMapObject* map = d.ColorMap ? d.ColorMap : gif->SColorMap;
  if (!map) throw ImageFormatError(path + ": the GIF has no colour map");
  GraphicsControlBlock gcb{};
  gcb.TransparentColor = NO_TRANSPARENT_COLOR;
  DGifSavedExtensionToGCB(gif.get(), 0, &gcb);
  const std::uint64_t width = std::max<std::int64_t>(gif->SWidth, std::int64_t(d.Left) + d.Width);
  const std::uint64_t height = std::max<std::int64_t>(gif->SHeight, std::int64_t(d.Top) + d.Height);
  check_size(path, width, height);
  GrayAlphaImage out;
  out.width = static_cast<std::uint32_t>(width), out.height = static_cast<std::uint32_t>(height);
  out.gray.assign(width * height, 255);
  out.alpha.assign(width * height, 0);  // outside the frame: transparent
  for (int y = 0; y < d.Height; ++y)
    for (int x = 0; x < d.Width; ++x) {
      const int index = frame.RasterBits[std::size_t(y) * d.Width + x];
      if (index >= map->ColorCount) throw ImageFormatError(path + ": a pixel's colour index is outside the colour map");
      const std::size_t i = std::size_t(d.Top + y) * width + (d.Left + x);
      out.gray[i] = luminance(map->Colors[index]);
      out.alpha[i] = index == gcb.TransparentColor ? 0 : 255;
    }
  return out;
}

void write_png(const GrayAlphaImage& image, const std::string& path) {
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  png.width = image.width, png.height = image.height;
  png.format = PNG_FORMAT_GA;
  std::vector<std::uint8_t> ga(2 * std::size_t(image.width) * image.height);
  for (std::size_t i = 0; i < image.gray.size(); ++i) ga[2 * i] = image.gray[i], ga[2 * i + 1] = image.alpha[i];
  if (!png_image_write_to_file(&png, path.c_str(), 0, ga.data(), 0, nullptr))
    throw ImageFormatError(path + ": cannot write PNG (" + png.message + ")");
}

void write_gif(const GrayAlphaImage& image, const std::string& path) {
  // Levels 0..254 are grays; index 255 is the transparent colour when any pixel needs it.
  const bool transparent = std::any_of(image.alpha.begin(), image.alpha.end(), [](std::uint8_t a) { return a < 128; });
  int error = 0;
  GifFileType* gif = EGifOpenFileName(path.c_str(), false, &error);
  if (!gif) throw ImageFormatError(path + ": cannot write GIF (" + gif_error(error) + ")");
  EGifSetGifVersion(gif, true);  // GIF89a: the graphics control block of the transparent index
  std::vector<GifColorType> colors(256);
  for (int i = 0; i < 256; ++i) colors[i] = {GifByteType(i), GifByteType(i), GifByteType(i)};
  ColorMapObject* map = GifMakeMapObject(256, colors.data());
  std::vector<GifByteType> row(image.width);
  bool ok = EGifPutScreenDesc(gif, int(image.width), int(image.height), 8, 0, map) == GIF_OK;
  if (ok && transparent) {
    GraphicsControlBlock gcb{};
    gcb.DisposalMode = DISPOSAL_UNSPECIFIED;
    gcb.DelayTime = 0;
    gcb.TransparentColor = 255;
    GifByteType ext[4];
    const std::size_t len = EGifGCBToExtension(&gcb, ext);
    ok = EGifPutExtension(gif, GRAPHICS_EXT_FUNC_CODE, int(len), ext) == GIF_OK;
  }
  ok = ok && EGifPutImageDesc(gif, 0, 0, int(image.width), int(image.height), false, nullptr) == GIF_OK;
  for (std::uint32_t y = 0; ok && y < image.height; ++y) {
    for (std::uint32_t x = 0; x < image.width; ++x) {
      const std::uint8_t g = image.gray_at(x, y);
      row[x] = transparent && image.alpha_at(x, y) < 128 ? 255 : std::min<std::uint8_t>(g, transparent ? 254 : 255);
    }
    ok = EGifPutLine(gif, row.data(), int(image.width)) == GIF_OK;
  }
  const int write_error = gif->Error;
  GifFreeMapObject(map);
  if (EGifCloseFile(gif, &error) != GIF_OK) ok = false;
  if (!ok) throw ImageFormatError(path + ": cannot write GIF (" + gif_error(write_error ? write_error : error) + ")");
}

}  // namespace grassfire

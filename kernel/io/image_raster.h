// image_raster.h -- PNG and GIF images as 8-bit gray + alpha rasters (libpng, giflib).
//
// Computes: the pixels of an image file as luminance (0 black .. 255 white) and alpha
// (0 transparent .. 255 opaque), row 0 at the top. PNG: any colour type and bit depth,
// through libpng's simplified API (palette, 16-bit and colour images are converted; the
// luminance is libpng's sRGB-to-gray conversion). GIF: the first frame, through its colour
// map (luminance 0.299 R + 0.587 G + 0.114 B, rounded), with the graphics control block's
// transparent index as alpha 0; a frame smaller than the logical screen is placed at its
// offset on a transparent screen.
// Writing (for tests and figures): 8-bit gray + alpha PNG, and a GIF with a 256-level gray
// colour map (alpha 0 pixels written as a transparent index when the raster has any).
// Errors: ImageFormatError naming the file: unreadable, not an image of the type its
// extension says, corrupt data, an empty image, or more than 2^28 pixels.
// Complexity: O(pixels).
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "shapes/gray_alpha_image.h"
#include "support/format_error.h"

namespace grassfire {

class ImageFormatError : public FormatError {  // support/format_error.h: the contract of what()
 public:
  using FormatError::FormatError;
};

// By extension: .png or .gif (case-insensitive).
bool is_image_path(const std::string& path);
GrayAlphaImage read_image(const std::string& path);
GrayAlphaImage read_png(const std::string& path);
GrayAlphaImage read_gif(const std::string& path);

void write_png(const GrayAlphaImage& image, const std::string& path);
void write_gif(const GrayAlphaImage& image, const std::string& path);

}  // namespace grassfire

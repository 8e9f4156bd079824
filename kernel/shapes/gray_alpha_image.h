// gray_alpha_image.h -- an 8-bit gray + alpha raster, as a value: what image_shape.h
// turns into a planar shape and io/image_raster.h reads from PNG and GIF files.
//
// Pixels row-major, row 0 at the top; gray 0 black .. 255 white, alpha 0 transparent ..
// 255 opaque. Contract: gray.size() == alpha.size() == width * height.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace grassfire {

struct GrayAlphaImage {
  std::uint32_t width = 0, height = 0;
  std::vector<std::uint8_t> gray, alpha;  // row-major, row 0 at the top
  std::uint8_t gray_at(std::uint32_t x, std::uint32_t y) const { return gray[std::size_t(y) * width + x]; }
  std::uint8_t alpha_at(std::uint32_t x, std::uint32_t y) const { return alpha[std::size_t(y) * width + x]; }
};

}  // namespace grassfire

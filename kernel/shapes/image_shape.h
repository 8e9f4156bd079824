// image_shape.h -- the planar shape of a binary image's foreground (PNG, GIF).
//
// Computes: from an image (io/image_raster.h) the polygon with holes bounding its
// foreground, in pixel units with y up: pixel (x, y) of a W x H image (row y from the top)
// is the unit square [x, x + 1] x [H - y - 1, H - y].
//   - Foreground: Opaque = alpha >= 128; Dark = opaque and gray < threshold; Light = opaque
//     and gray >= threshold; Auto (the default) = Opaque when some pixel has alpha < 128,
//     else the class (dark or light) that is NOT the majority of the border pixels, i.e.
//     a shape on a plain background either way round (MPEG-7 CE-Shape-1: white on black;
//     drawings: black on white); a tie makes dark the foreground.
//   - Connectivity of the foreground: 8 (default; pixels touching at a corner are joined,
//     holes are 4-connected) or 4. The shape must be one component: several are an error
//     that lists their sizes, unless `largest` keeps the component with most pixels.
//   - Contour PixelBoundary (default): the exact boundary of the union of foreground
//     pixels, integer coordinates, except at a saddle (a 2 x 2 block whose foreground
//     pixels touch only at the centre), where the two boundaries through the centre
//     would meet: there the corner is cut by half a pixel on the side that the
//     connectivity separates (8: the background corners, so the pixels are joined by a
//     bridge; 4: the foreground corners), so the rings stay simple and disjoint. Vertices
//     are integers or halves, decimals that the exact Boost path of the polygon axis takes.
//   - Contour MarchingSquares: the iso-line at 1/2 of the foreground indicator sampled at
//     pixel centres (marching squares with the same saddle rule): the polygon through the
//     midpoints of the pixel-boundary edges, every corner cut.
//   Collinear vertices are merged. The outer ring is counter-clockwise, holes (background
//   components enclosed by the foreground) clockwise; the result satisfies geometry2/shape2.h.
// Invariant (tests check it exactly): a pixel centre lies inside the shape iff the pixel
// is foreground (of the kept component), in both contour modes.
// Errors: ImageShapeError naming the source: no foreground pixel, several components
// (without `largest`). Option parsing: std::invalid_argument naming the option.
// Complexity: O(W H).
// Section: input of the 2D pipeline (the binary shape images of 3.5, MPEG-7 CE-Shape-1).
#pragma once

#include <map>
#include <stdexcept>
#include <string>

#include "geometry2/shape2.h"
#include "shapes/gray_alpha_image.h"

namespace grassfire {

class ImageShapeError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

enum class PixelConnectivity { Four, Eight };
enum class ImageContour { PixelBoundary, MarchingSquares };
enum class ImageForeground { Auto, Dark, Light, Opaque };

struct ImageShapeOptions {
  PixelConnectivity connectivity = PixelConnectivity::Eight;
  ImageContour contour = ImageContour::PixelBoundary;
  ImageForeground foreground = ImageForeground::Auto;
  int threshold = 128;   // gray levels 0..255: dark < threshold <= light
  bool largest = false;  // several components: keep the largest instead of failing
};

// From the options' names and values as the program takes them: "connectivity" (4, 8),
// "contour" (pixel, marching-squares), "foreground" (auto, dark, light, opaque),
// "threshold" (1..255), "largest" (true, false). Unknown names are an error.
ImageShapeOptions parse_image_shape_options(const std::map<std::string, std::string>& named);

// The foreground mask (row-major, row 0 at the top) by the rule above.
std::vector<bool> foreground_mask(const GrayAlphaImage& image, const ImageShapeOptions& options);

// The shape (validated) of an image; `source` names it in messages and becomes its name.
Shape2 image_shape(const GrayAlphaImage& image, const ImageShapeOptions& options, const std::string& source);

}  // namespace grassfire

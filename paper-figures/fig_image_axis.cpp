// fig_image_axis.cpp -- a binary image as a shape (shapes/image_shape.h): its exact pixel-
// boundary polygon and marching-squares contour, with the exact medial axis coloured by
// EDF and the EMA, next to the polygon the image was drawn from.
//
// The image is made here: the built-in `hole` shape (a polygon with one hole) rasterised at
// 10 pixels per unit, white on black as in MPEG-7 CE-Shape-1 (pixel centres inside the
// polygon are white; exact location, geometry2/shape_locator.h). It is written as PNG and
// read back through load_shape, the path every command takes.
#include <cmath>
#include <cstdio>

#include "figure_registry.h"
#include "geometry2/shape_locator.h"
#include "io/image_raster.h"
#include "render/svg_medial2.h"
#include "pipeline/edf2d.h"
#include "shapes/builtin_shapes.h"
#include "io/load_shape.h"

namespace grassfire::figures {
namespace {

constexpr double kScale = 10;  // pixels per unit of the built-in shape

GrayAlphaImage rasterise(const Shape2& s, std::uint32_t width, std::uint32_t height) {
  const ShapeLocator locate(s, std::size_t(width) * height);
  GrayAlphaImage im;
  im.width = width, im.height = height;
  im.alpha.assign(std::size_t(width) * height, 255);
  for (std::uint32_t y = 0; y < height; ++y)
    for (std::uint32_t x = 0; x < width; ++x) {
      const Point2 centre{(x + 0.5) / kScale, (height - y - 0.5) / kScale};
      im.gray.push_back(locate.locate(LazyPoint::input(centre)) == BoundedSide::Inside ? 255 : 0);
    }
  return im;
}

struct Panel {
  std::string file, ema;
  std::size_t vertices = 0, nodes = 0;
};

// The EMA in a few words: a point, or the length of the cycle around the hole.
std::string describe_ema(const MedialGraph& g, const ExtendedMedialAxis& ema) {
  char b[128];
  if (ema.kind == ExtendedMedialAxis::Kind::Point) {
    const Point2 p = position_of(g, ema.point);
    std::snprintf(b, sizeof b, "the point (%.2f, %.2f)", p.x, p.y);
  } else {
    double length = 0;
    for (std::uint32_t e : ema.edges) length += g.edges()[e].length.mid();
    std::snprintf(b, sizeof b, "a cycle of length %.1f", length);
  }
  return b;
}

Panel draw(const FigureContext& ctx, const Shape2& shape, const std::string& file, const std::string& title) {
  Edf2dOptions o;
  o.axis = AxisMethod::ExactPolygon;
  const Edf2dResult r = compute_edf2d(shape, o);
  Medial2SvgOptions svg;
  svg.title = title;
  svg.width = 560;
  std::FILE* f = std::fopen((ctx.out_dir + "/" + file).c_str(), "w");
  if (!f) throw std::runtime_error(ctx.out_dir + "/" + file + ": cannot write");
  const std::string text = medial2_svg(shape, *r.graph, *r.burning, r.measures, svg);
  std::fwrite(text.data(), 1, text.size(), f);
  std::fclose(f);
  Panel p{file, describe_ema(*r.graph, r.burning->ema.at(0)), 0, r.graph->node_count()};
  for (const Ring& ring : shape.rings) p.vertices += ring.points.size();
  return p;
}

std::vector<FigureFile> fig_image_axis(const FigureContext& ctx) {
  const Shape2 polygon = builtin_shape("hole");
  const std::string png = ctx.out_dir + "/fig_image_input.png";
  write_png(rasterise(polygon, 100, 100), png);
  ImageShapeOptions ms;
  ms.contour = ImageContour::MarchingSquares;
  Shape2 scaled = polygon;  // the source polygon in pixel units, for comparison
  for (Ring& ring : scaled.rings)
    for (Point2& p : ring.points) p = {p.x * kScale, p.y * kScale};
  const Panel pixel = draw(ctx, load_shape(png), "fig_image_pixel.svg", "pixel boundary (exact, integer vertices)");
  const Panel squares = draw(ctx, load_shape(png, ms), "fig_image_ms.svg", "marching squares (half-integer vertices)");
  const Panel source = draw(ctx, scaled, "fig_image_source.svg", "the polygon the image was drawn from");
  char caption[900];
  std::snprintf(caption, sizeof caption,
                "A binary image read as a shape. Input: the built-in 'hole' polygon rasterised at 100 x 100 "
                "pixels, white on black (fig_image_input.png; the foreground is found automatically as the "
                "pixels unlike the border). Exact medial axis coloured by EDF, EMA cycle in black. Pixel "
                "boundary: %zu vertices, %zu axis nodes; marching squares: %zu vertices, %zu nodes; source "
                "polygon: %zu nodes. Look for the many short branches the pixel staircase adds to the axis "
                "(the instability of Fig. 1.2), while the EMA, the cycle around the hole where the EDF is "
                "infinite, stays where it was: EMA %s (pixels), %s (marching squares), %s (source).",
                pixel.vertices, pixel.nodes, squares.vertices, squares.nodes, source.nodes, pixel.ema.c_str(),
                squares.ema.c_str(), source.ema.c_str());
  return {{"fig_image_input.png", "The input image (100 x 100 pixels, white shape on black)."},
          {pixel.file, caption},
          {squares.file, "The same image with --contour marching-squares: every pixel corner cut."},
          {source.file, "The polygon the image was rasterised from, in pixel units, for comparison."}};
}

GF_REGISTER_FIGURE("fig_image", "Binary images as shapes: exact axis and EMA of an image", fig_image_axis);

}  // namespace
}  // namespace grassfire::figures

// svg_medial2.h -- pictures of 2D results: a shape, its medial axis coloured by EDF, ET,
// ST or R -- or by a scalar the burning does not carry, such as the potential residue PR
// (3.4.2) -- the EMA, optionally the distance function R as a grey background (Figs. 1.2,
// 3.3, 3.4, 3.5 of the dissertation).
//
// Computes: SVG text (render/render3d.h's SvgCanvas underneath). What a panel shows, bottom
// to top:
//  - the shape filled light grey (holes left open: one polygon per shape, each hole joined
//    to the outer ring by a zero-width bridge, so the non-zero fill rule leaves the
//    oppositely oriented holes empty); or, with `distance_background`, the distance to the
//    boundary R(p) = min over boundary segments of |p - segment| per raster cell, in grey
//    (dark at the boundary, white at the largest R), cut to the shape by painting white
//    over the outside and the holes;
//  - the boundary rings; the boundary samples as dots when given;
//  - the EMA's cycles as a thick grey line under the 2-core (3.4: "the gray loop");
//  - the medial axis, each edge cut into pieces no longer than `max_piece` pixels and at
//    its quench point (where the EDF along it has its kink), each piece coloured by the
//    field at its middle: heat colours from blue (low) to red (high) as the dissertation's
//    figures, and `kInfiniteColour` where the field is infinite;
//  - the EMA point: a grey dot with a white ring inside a black ring;
//  - a colour bar with the field's name, five ticks from the low to the high end of the
//    range, a swatch for infinity when there is any, and a grey bar for R (three ticks)
//    when shown.
// Field values along an edge at arc length s: EDF from GrassfireResult::edf_along (exact
// piecewise-linear form); R by linear interpolation of R between the two nodes (a display
// approximation: R is exactly linear only along straight edges between two boundary
// segments); ET = EDF - R; ST = 1 - R / EDF. On each piece between breakpoints (the ends
// and the quench point) EDF and R are linear, so ET is linear and ST monotone, and the
// range of every field over an edge is attained at its breakpoints.
// Other scalars (Medial2Scalar) bring their own breakpoints and values, and are drawn the
// same way. PR (potential_residue_scalar): the limits at the two ends of every edge (the
// generators' boundary distance), rising to L / 2 at a peak, linear in between -- the
// linear model of burn2/potential_residue.h (exact on straight edges of a polygon axis,
// where both feet move linearly; PR is constant on the edges of a sampled axis).
// Coordinates: y points up (flipped for SVG); the shape's bounding box is fitted into the
// panel with its aspect ratio kept.
// Contract: `burning` and `measures` were computed on `g`, which approximates the medial
// axis of `shape`; the shape is validated (geometry2/shape2.h). Values are drawn from the
// midpoints of certified enclosures (display only: no decision depends on them).
// Complexity: O(pieces + c * b) for b boundary segments and c background cells.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "burn2/extended_grassfire.h"
#include "burn2/measures.h"
#include "burn2/potential_residue.h"
#include "render/render3d.h"
#include "geometry2/shape2.h"

namespace grassfire {

enum class Medial2Field { Edf, Et, St, R };
const char* to_string(Medial2Field f);
// "edf", "et", "st" or "r" (any case); std::invalid_argument naming the value otherwise.
Medial2Field parse_medial2_field(const std::string& name);

// Blue (t = 0) through cyan, green, yellow to red (t = 1); t is clamped.
Rgb heat_color(double t);
constexpr Rgb kInfiniteColour{0.08, 0.08, 0.08};

struct Medial2SvgOptions {
  Medial2Field field = Medial2Field::Edf;
  double width = 800;  // px, for medial2_svg (the height follows the shape)
  std::string title;   // drawn above the shape when not empty
  bool colour_bar = true;
  bool show_ema = true;
  bool distance_background = false;                           // R as a grey raster inside the shape
  double raster_cell = 3;                                     // px, side of a background cell
  const std::vector<std::vector<Point2>>* samples = nullptr;  // boundary samples, drawn as dots
  double axis_width = 0;                                      // px; 0: width / 320 (scales with the picture)
  double max_piece = 4;                                       // px: the longest piece of an edge drawn in one colour
  // The colour scale; when lo < hi both are used (panels sharing one scale), otherwise
  // the finite range of the field on the graph.
  double range_lo = 0, range_hi = 0;
};

// The finite range of a field over the graph (nodes and both sides of every edge end and
// quench point), and whether the field is infinite anywhere. lo = hi = 0 when no value is
// finite.
struct Medial2FieldRange {
  double lo = 0, hi = 0;
  bool has_infinite = false;
};
Medial2FieldRange medial2_field_range(const MedialGraph& g, const GrassfireResult& burning,
                                      const NodeMeasures& measures, Medial2Field field);

// The arc lengths (from u, increasing) where the field's linear pieces on `edge` change:
// 0, the quench point when fire entered from both ends, and the length.
std::vector<double> field_breakpoints(const MedialGraph& g, const GrassfireResult& burning, std::uint32_t edge);

// The field at arc length s from `from` along `edge` (infinity where the EDF is).
double medial2_field_along(const MedialGraph& g, const GrassfireResult& burning, Medial2Field field, std::uint32_t edge,
                           std::uint32_t from, double s);

// A scalar on the medial axis, drawn like a field: its value at arc length s from the
// edge's end u, linear between the edge's breakpoints (0, ..., the edge's length,
// increasing), infinity allowed. The functions may refer to the graph and whatever the
// scalar was computed from: those must outlive the scalar.
struct Medial2Scalar {
  std::string name;  // the colour bar's label
  std::function<std::vector<double>(std::uint32_t edge)> breakpoints;
  std::function<double(std::uint32_t edge, double s)> along;
};
// The field as a scalar (breakpoints field_breakpoints, values medial2_field_along).
Medial2Scalar medial2_field_scalar(const MedialGraph& g, const GrassfireResult& burning, Medial2Field field);
// PR as a scalar (see the header comment); infinite on edges whose generators lie on two
// rings. Contract: pr = potential_residue(g, cp).
Medial2Scalar potential_residue_scalar(const MedialGraph& g, const ClosestPoints& cp, const PotentialResidue& pr);
// The finite range of the scalar over the breakpoints of every edge.
Medial2FieldRange medial2_scalar_range(const MedialGraph& g, const Medial2Scalar& scalar);

// World (y up) to canvas (y down) for a shape fitted into a box of the canvas.
class Medial2Frame {
 public:
  Medial2Frame(const Shape2& shape, double x, double y, double w, double h);
  Point2d operator()(const Point2& p) const { return {ox_ + scale_ * p.x, oy_ - scale_ * p.y}; }
  Point2 world(const Point2d& q) const { return {(q[0] - ox_) / scale_, (oy_ - q[1]) / scale_}; }
  double scale() const { return scale_; }  // px per world unit

 private:
  double ox_ = 0, oy_ = 0, scale_ = 1;
};

// The shape as one polygon (bridged holes, see the header comment) in canvas coordinates.
std::vector<Point2d> shape_polygon(const Medial2Frame& f, const Shape2& shape);
// Distance from p to the shape's boundary (display: double arithmetic).
double boundary_distance(const Shape2& shape, const Point2& p);
// The boundary rings as closed polylines.
void draw_boundary(SvgCanvas& c, const Medial2Frame& f, const Shape2& shape, const Rgb& colour, double width);
// The edge's points at the arc lengths `s` (from u), following curved edges.
std::vector<Point2d> edge_points(const Medial2Frame& f, const MedialGraph& g, std::uint32_t edge,
                                 const std::vector<double>& s);

// Draws one panel into the box (x, y, w, h) of the canvas; returns the number of axis
// pieces drawn.
std::size_t draw_medial2(SvgCanvas& c, double x, double y, double w, double h, const Shape2& shape,
                         const MedialGraph& g, const GrassfireResult& burning, const NodeMeasures& measures,
                         const Medial2SvgOptions& options);
// A panel as draw_medial2, coloured by the scalar (options.field unused, the colour bar
// labelled scalar.name, its range medial2_scalar_range unless options give one).
std::size_t draw_medial2_scalar(SvgCanvas& c, double x, double y, double w, double h, const Shape2& shape,
                                const MedialGraph& g, const GrassfireResult& burning, const Medial2Scalar& scalar,
                                const Medial2SvgOptions& options);
// The frame in which draw_medial2 and draw_medial2_scalar place the shape in the box
// (x, y, w, h): for drawing more on top of a panel.
Medial2Frame medial2_panel_frame(const Shape2& shape, const Medial2SvgOptions& options, double x, double y, double w,
                                 double h);
// The panel height that fits the shape at the given width (title and colour bar included).
double medial2_panel_height(const Shape2& shape, const Medial2SvgOptions& options, double width);

// A whole picture of one panel, options.width wide.
std::string medial2_svg(const Shape2& shape, const MedialGraph& g, const GrassfireResult& burning,
                        const NodeMeasures& measures, const Medial2SvgOptions& options);

}  // namespace grassfire

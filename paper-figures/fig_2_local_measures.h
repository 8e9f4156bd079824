// fig_2_local_measures.h -- what Figs. 2.4 and 2.6 share (2.2.1): the separation angle
// theta and the feature size r(x) of Chazal and Lieutier along medial edges, the part of
// the axis where one of them reaches a threshold (naive separation-angle pruning, the
// lambda-medial axis), the critical points of the distance function, and their drawing.
//
// Along an edge. At its nodes the measures are the kernel's certified ones
// (burn2/feature_size.h). An interior point x of an edge has exactly two closest boundary
// points, the feet of the edge's two generators, which burn2/closest_points.h gives at
// both ends: a generator whose two end feet coincide is a point (a boundary sample, a
// reflex vertex) and stays put; otherwise it is a segment and the foot at x is the
// projection of x on the line through the end feet. Then R = |x - y1|, theta =
// 2 asin(|y1 - y2| / 2R) and r = |y1 - y2| / 2 (the smallest circle around two points).
// These are evaluated in double precision at points given by MedialGeometry::point_along:
// display values, not certified ones.
// Threshold sets. On every kind of edge theta has at most one interior maximum and r at
// most one interior minimum (fixed generators: theta = 2 atan(h / d) for the distance d to
// the chord's midpoint, r constant; two segments: theta constant, r affine; a point and a
// segment: both extremal at the parabola's apex). The set {measure >= threshold} on an
// edge is therefore at most two intervals; it is found by testing kEdgeSteps + 1 points
// per edge and bisecting each change between neighbours (display precision; a crossing
// pair closer than 1 / kEdgeSteps of the edge could be missed). The ends are tested just
// inside the edge, for the limit along it (at a leaf, R = 0, the ratio is 0 / 0). A piece
// reaching an end contains that node: the node's closest points include the edge's.
// Critical points (x in the convex hull of its closest points: the generalized gradient
// of the distance vanishes, Lieutier 2004): a node with R > 0 certainly inside the hull
// of its distinct closest points (interval orientations of consecutive points, in their
// angular order around x), and an edge
// point on its own chord (fixed generators: the chord's midpoint strictly inside the
// edge; a point and a segment: the point's projection strictly inside the moving feet).
// Edges between two segments are critical all along when the segments are parallel; they
// and every test that the enclosures cannot decide are counted as undecided.
// Complexity: O(kEdgeSteps) per edge, plus O(k^2) per node with k closest points.
// Section: 2.2.1 (local significance measures).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "burn2/closest_points.h"
#include "burn2/feature_size.h"
#include "render/svg_medial2.h"
#include "pipeline/edf2d.h"

namespace grassfire::figures {

constexpr int kEdgeSteps = 64;
constexpr double kPi = 3.14159265358979323846;

// A shape, its medial axis (sampled or exact, as the options say), the closest boundary
// points and the measures at the nodes.
struct LocalMeasureShape {
  Shape2 shape;
  Edf2dResult result;
  ClosestPoints closest;
  LocalFeatureMeasures nodes;
  const MedialGraph& graph() const { return *result.graph; }
};
LocalMeasureShape local_measure_shape(Shape2 shape, const Edf2dOptions& options);
// A hand-made polygon with vertices in counter-clockwise order, validated.
Shape2 polygon_shape(const std::string& name, std::vector<Point2> outer);

enum class LocalMeasure { SeparationAngle, FeatureSize };

// A medial point with its two closest boundary points.
struct EdgePoint {
  Point2 x, y1, y2;
  double radius = 0, separation_angle = 0, feature_size = 0;
  double value(LocalMeasure m) const { return m == LocalMeasure::SeparationAngle ? separation_angle : feature_size; }
};
EdgePoint edge_point(const LocalMeasureShape& s, std::uint32_t edge, double s_from_u);
// Of the kEdgeSteps + 1 points tested per edge, the one nearest to `target` among those
// where the measure is at least `at_least`.
EdgePoint nearest_edge_point(const LocalMeasureShape& s, const Point2& target, LocalMeasure m, double at_least);
double node_value(const LocalMeasureShape& s, LocalMeasure m, std::uint32_t node);

// The closed part of the axis where the measure is >= threshold: kept nodes, pieces of
// edges (arc lengths from u) and its components (ids per kept node and per piece).
struct AxisPiece {
  std::uint32_t edge = 0;
  double s0 = 0, s1 = 0;
};
struct ThresholdAxis {
  std::vector<bool> node_kept;
  std::vector<AxisPiece> pieces;
  std::vector<std::uint32_t> node_component, piece_component;  // kNone for dropped nodes
  std::uint32_t components = 0;
  std::uint64_t cycles = 0;
  static constexpr std::uint32_t kNone = 0xffffffffu;
};
ThresholdAxis threshold_axis(const LocalMeasureShape& s, LocalMeasure m, double threshold);

struct CriticalPoint {
  Point2 at;
  double radius = 0;  // R = r(x) there
  bool at_node = false;
};
struct CriticalPoints {
  std::vector<CriticalPoint> points;
  std::uint32_t undecided = 0;
};
CriticalPoints critical_points(const LocalMeasureShape& s);

// ---- drawing ------------------------------------------------------------------------------

const Rgb kBlack{0, 0, 0}, kWhite{1, 1, 1}, kShapeFill{0.92, 0.92, 0.92}, kShapeBoundary{0.15, 0.15, 0.15};
const Rgb kDropped{0.72, 0.72, 0.72}, kRed{0.85, 0.1, 0.1}, kBlue{0.1, 0.3, 0.9};

// The shape filled and outlined in the box, its title above; the frame of the shape.
Medial2Frame shape_panel(SvgCanvas& c, double x, double y, double w, double h, const Shape2& shape,
                         const std::string& title);
// The whole axis in one colour (dashed when `dash` is given).
void draw_axis(SvgCanvas& c, const Medial2Frame& f, const MedialGraph& g, const Rgb& colour, double width,
               const std::string& dash = "");
// The axis coloured by the measure, heat colours from lo (blue) to hi (red).
void draw_measure_axis(SvgCanvas& c, const Medial2Frame& f, const LocalMeasureShape& s, LocalMeasure m, double lo,
                       double hi, double width);
// The kept pieces and isolated kept nodes, coloured per component from `palette`.
void draw_threshold_axis(SvgCanvas& c, const Medial2Frame& f, const LocalMeasureShape& s, const ThresholdAxis& t,
                         const std::vector<Rgb>& palette, double width);
// A horizontal heat-colour bar from lo to hi, ticks at `ticks` labelled `labels`.
void heat_bar(SvgCanvas& c, double x, double y, double w, double lo, double hi, const std::string& name,
              const std::vector<double>& ticks, const std::vector<std::string>& labels);
// A closed circle outline (no fill), in canvas units.
void circle_outline(SvgCanvas& c, const Point2d& centre, double radius, const Rgb& colour, double width,
                    const std::string& dash = "");
// Text centred at p (baseline) on a white box, readable over the axis.
void boxed_text(SvgCanvas& c, const Point2d& p, const std::string& text, double size, const Rgb& colour = kBlack);
// A dot with a white ring (a medial point) or a red dot (a closest point), with a label.
void labelled_dot(SvgCanvas& c, const Point2d& p, const Rgb& colour, const std::string& label,
                  const Point2d& label_offset, double size = 15);
// One legend row at baseline y: a sample mark (a line, a hollow critical point, a ring
// around a short component) in `colour`, then the text.
enum class Mark { Line, Hollow, Ring };
void legend_row(SvgCanvas& c, double x, double y, Mark mark, const Rgb& colour, const std::string& text);
// Ten colours told apart easily, for components.
const std::vector<Rgb>& component_palette();
std::string fixed(double v, int digits);
// printf into a string of any length (captions).
std::string printf_string(const char* format, ...) __attribute__((format(printf, 1, 2)));

}  // namespace grassfire::figures

// fig_3_5.cpp -- Figure 3.5: the EDF (top row) and the potential residue PR (bottom row)
// on the exact medial axis under boundary perturbation (3.4, 3.4.2): a unit square and a
// copy perturbed all round (a, b, e, f), key-1 and a copy perturbed on one side only
// (c, d, g, h). Every axis is coloured by its field over [0, the field's maximum on that
// axis] (the dissertation's normalisation); inserts under the squares zoom into the
// middle of the axis, where perturbation changes its connectivity.
#include <cmath>
#include <fstream>
#include <functional>
#include <stdexcept>

#include "apps2d/axis_correspondence.h"
#include "apps2d/perturbation.h"
#include "caption_printf.h"
#include "figure_registry.h"
#include "render/svg_medial2.h"
#include "pipeline/edf2d.h"
#include "io/load_shape.h"
#include "shapes/validate_shape.h"

namespace grassfire::figures {
namespace {

// The perturbations: largest displacement and spacing of the noise, over the diameter.
constexpr double kAmplitude = 0.005, kSpacing = 1.0 / 200;
constexpr std::uint64_t kSeed = 1;
constexpr double kSquareInsetHalf = 0.012;  // the inserts' window, around the square's middle

const Rgb kBlack{0, 0, 0}, kWhite{1, 1, 1}, kPrBlue{0.1, 0.3, 0.95}, kCross{0.55, 0, 0.55}, kFrame{0.35, 0.35, 0.35};

// A shape with its exact polygon axis, burning and PR (PR needs the moving generators of
// the exact axis: burn2/closest_points.h).
struct Analysed {
  Shape2 shape;
  Edf2dResult axis;
  ClosestPoints cp;
  PotentialResidue pr;
  Point2 ema;
  double edf_max = 0, pr_max = 0;
};

Analysed analyse(Shape2 shape) {
  Analysed a;
  a.shape = std::move(shape);
  Edf2dOptions o;
  o.axis = AxisMethod::ExactPolygon;
  a.axis = compute_edf2d(a.shape, o);
  const MedialGraph& g = *a.axis.graph;
  a.cp = closest_points(g, &a.shape);
  a.pr = potential_residue(g, a.cp);
  if (!ema_position(g, *a.axis.burning, &a.ema)) throw std::runtime_error("fig3_5: the EMA of a shape is a loop");
  a.edf_max = medial2_field_range(g, *a.axis.burning, a.axis.measures, Medial2Field::Edf).hi;
  a.pr_max = a.pr.maximum.value.value.mid();
  return a;
}

Shape2 perturbed(const Shape2& s, PerturbationKind kind, double amplitude, std::uint64_t seed) {
  const double d = shape_diameter(s);
  PerturbationOptions p;
  p.kind = kind;
  p.amplitude = amplitude * d;
  // Noise no denser than its amplitude, as in experiments/study_stability.cpp.
  p.spacing = d * std::max(kSpacing, amplitude);
  p.seed = seed;
  return perturb_boundary(s, p).shape;
}

double distance(const Point2& a, const Point2& b) { return std::hypot(a.x - b.x, a.y - b.y); }

// A marker: a disk of `fill` with a white ring inside a black ring (the EMA's style).
void marker(SvgCanvas& c, const Point2d& p, double r, const Rgb& fill) {
  c.circle(p, r * 1.25, kBlack, kBlack, 0);
  c.circle(p, r, fill, kWhite, 0.2 * r);
}

// Where the original shape had its marker: a black circle around it, open so that the
// perturbed shape's marker shows through when it has not moved.
void former_place(SvgCanvas& c, const Point2d& p, double r) {
  constexpr int kSides = 40;
  std::vector<Point2d> ring;
  for (int i = 0; i <= kSides; ++i) {
    const double t = 2 * M_PI * i / kSides;
    ring.push_back({p[0] + 2 * r * std::cos(t), p[1] + 2 * r * std::sin(t)});
  }
  c.polyline(ring, kBlack, 0.45 * r);
}

void cross(SvgCanvas& c, const Point2d& p, double r, double width) {
  c.polyline({{p[0] - r, p[1] - r}, {p[0] + r, p[1] + r}}, kCross, width);
  c.polyline({{p[0] - r, p[1] + r}, {p[0] + r, p[1] - r}}, kCross, width);
}

// A panel of one field with its markers, which scale with options.axis_width (the inserts
// draw it with thinner lines, then magnify it).
using PanelFn = std::function<void(SvgCanvas&, double x, double y, double w, double h, const Medial2SvgOptions&)>;

double line_width(const Medial2SvgOptions& o, double w) { return o.axis_width > 0 ? o.axis_width : w / 320; }

// EDF over [0, its maximum]; the EMA, and a circle where the original had it (`before`).
PanelFn edf_panel(const Analysed& a, const Point2* before) {
  return [&a, before](SvgCanvas& c, double x, double y, double w, double h, Medial2SvgOptions o) {
    o.range_lo = 0, o.range_hi = a.edf_max;
    draw_medial2(c, x, y, w, h, a.shape, *a.axis.graph, *a.axis.burning, a.axis.measures, o);
    if (before) former_place(c, medial2_panel_frame(a.shape, o, x, y, w, h)(*before), 3.4 * line_width(o, w));
  };
}

// PR over [0, its maximum]; its maximum (blue) with the maximum's two closest boundary
// points (crosses), and a circle where the original's maximum was (`before`).
PanelFn pr_panel(const Analysed& a, const Point2* before) {
  return [&a, before](SvgCanvas& c, double x, double y, double w, double h, Medial2SvgOptions o) {
    o.range_lo = 0, o.range_hi = a.pr_max;
    o.show_ema = false;
    const MedialGraph& g = *a.axis.graph;
    draw_medial2_scalar(c, x, y, w, h, a.shape, g, *a.axis.burning, potential_residue_scalar(g, a.cp, a.pr), o);
    const Medial2Frame f = medial2_panel_frame(a.shape, o, x, y, w, h);
    const double r = 3.4 * line_width(o, w);
    for (const Point2& p : a.pr.maximum.closest) cross(c, f(p), 1.6 * r, 0.6 * r);
    if (before) former_place(c, f(*before), r);
    marker(c, f(a.pr.maximum.position), r, kPrBlue);
  };
}

struct Inset {
  double x, y, size;  // the box in the figure
  Point2 centre;      // the window in world coordinates
  double half;
};

// Lines (and markers, which scale with them) in the inserts, relative to the panels'.
constexpr double kInsetLines = 1.0;

// A magnified window of a panel: the panel is drawn into a canvas of its own with lines
// `zoom` times thinner and nested into the figure as an <svg> element whose viewBox is the
// window, so that it shows `zoom` times larger with lines of the usual width (SVG clips a
// nested viewport to its box). Returns the nested element.
std::string inset_svg(const PanelFn& draw, const Shape2& shape, double panel_w, double panel_h, const Inset& in) {
  Medial2SvgOptions o;
  o.colour_bar = false;
  const Medial2Frame f0 = medial2_panel_frame(shape, o, 0, 0, panel_w, panel_h);
  const double window_px = 2 * in.half * f0.scale(), zoom = in.size / window_px;
  o.axis_width = kInsetLines * panel_w / 320 / zoom;
  o.max_piece = 4 / zoom;
  SvgCanvas inner(panel_w, panel_h);
  draw(inner, 0, 0, panel_w, panel_h, o);
  const Point2d corner = f0({in.centre.x - in.half, in.centre.y + in.half});
  const std::string doc = inner.str(), background = "fill=\"white\"/>\n";
  const std::size_t from = doc.find(background) + background.size(), to = doc.rfind("</svg>");
  const std::string head = caption_printf(
      "<svg x=\"%.2f\" y=\"%.2f\" width=\"%.2f\" height=\"%.2f\" viewBox=\"%.3f %.3f %.3f %.3f\">\n"
      "<rect x=\"%.3f\" y=\"%.3f\" width=\"%.3f\" height=\"%.3f\" fill=\"white\"/>\n",
      in.x, in.y, in.size, in.size, corner[0], corner[1], window_px, window_px, corner[0], corner[1], window_px,
      window_px);
  return head + doc.substr(from, to - from) + "</svg>\n";
}

void box(SvgCanvas& c, const Point2d& a, const Point2d& b, double width) {
  c.polyline({a, {b[0], a[1]}, b, {a[0], b[1]}, a}, kFrame, width);
}

void save_with_insets(const SvgCanvas& c, const std::vector<std::string>& nested, const std::string& path) {
  std::string svg = c.str();
  std::string all;
  for (const std::string& n : nested) all += n;
  svg.insert(svg.rfind("</svg>"), all);
  std::ofstream out(path);
  out << svg;
  if (!out) throw std::runtime_error(path + ": cannot write SVG");
}

struct Pair {
  const Analysed *original, *changed;
  std::string name, perturbation;  // for the titles
};

// One file: EDF of the pair on top, PR under it, with inserts under every panel when
// `half` > 0 (a window of that half side around the original's EMA).
void draw_pair(const Pair& p, const std::string& path, double panel_w, double half, const std::string (&tags)[4]) {
  Medial2SvgOptions o;
  o.title = "title";
  const double panel_h =
      std::max(medial2_panel_height(p.original->shape, o, panel_w), medial2_panel_height(p.changed->shape, o, panel_w));
  const double inset = half > 0 ? 0.5 * panel_w : 0, row_h = panel_h + (half > 0 ? inset + 34 : 0);
  SvgCanvas c(2 * panel_w, 2 * row_h);
  std::vector<std::string> nested;
  const Point2* before = &p.original->ema;
  const PanelFn panels[4] = {edf_panel(*p.original, nullptr), edf_panel(*p.changed, before),
                             pr_panel(*p.original, nullptr), pr_panel(*p.changed, &p.original->pr.maximum.position)};
  const std::string titles[4] = {tags[0] + " EDF: " + p.name, tags[1] + " EDF: " + p.perturbation,
                                 tags[2] + " PR: " + p.name, tags[3] + " PR: " + p.perturbation};
  for (int k = 0; k < 4; ++k) {
    const double x = panel_w * (k % 2), y = row_h * (k / 2);
    const Analysed& a = k % 2 == 0 ? *p.original : *p.changed;
    o.title = titles[k];
    panels[k](c, x, y, panel_w, panel_h, o);
    if (half <= 0) continue;
    const Inset in{x + 0.5 * (panel_w - inset), y + panel_h + 24, inset, p.original->ema, half};
    const Medial2Frame f = medial2_panel_frame(a.shape, o, x, y, panel_w, panel_h);
    const Point2& m = in.centre;
    box(c, f({m.x - half, m.y + half}), f({m.x + half, m.y - half}), 1.2);
    nested.push_back(inset_svg(panels[k], a.shape, panel_w, panel_h, in));
    box(c, {in.x, in.y}, {in.x + inset, in.y + inset}, 1.2);
    const double zoom = inset / (2 * half * f.scale());
    c.text({x + panel_w / 2, in.y - 6},
           caption_printf("insert: the %.2g x %.2g box around the middle, x%.0f", 2 * half, 2 * half, zoom), 14,
           "middle");
  }
  save_with_insets(c, nested, path);
}

Shape2 unit_square() {
  Shape2 s{"square", {Ring{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}}}};
  validate_shape(s, s.name);
  return s;
}

// The numbers both captions print: drifts over the original's diameter D.
std::string changes(const Analysed& a, const Analysed& b) {
  const double d = shape_diameter(a.shape);
  return caption_printf(
      "The axis grows from %u to %u edges; the maximum EDF goes from %.4g to %.4g and the EMA moves by %.2g D "
      "(D = %.3g, the diameter); the maximum PR goes from %.4g to %.4g (the perimeter from %.4g to %.4g) and the PR "
      "maximum moves by %.2g D (%u and %u local maximum regions of PR)",
      a.axis.graph->edge_count(), b.axis.graph->edge_count(), a.edf_max, b.edf_max, distance(a.ema, b.ema) / d, d,
      a.pr_max, b.pr_max, a.cp.ring_length[0].mid(), b.cp.ring_length[0].mid(),
      distance(a.pr.maximum.position, b.pr.maximum.position) / d, a.pr.local_maxima, b.pr.local_maxima);
}

std::string perturbation_text(const char* how) {
  return caption_printf(
      "a copy perturbed %s: the boundary densified to points at most %.2g D apart, each moved along the normal by up "
      "to "
      "%.2g D (uniform noise, seed %llu; Hausdorff distance at most %.2g D);",
      how, std::max(kSpacing, kAmplitude), kAmplitude, static_cast<unsigned long long>(kSeed), kAmplitude);
}

std::string closest_text(const Analysed& a) {
  const auto& c = a.pr.maximum.closest;
  return caption_printf("(%.3g, %.3g) and (%.3g, %.3g)", c[0].x, c[0].y, c[1].x, c[1].y);
}

// "n junctions of degrees d1, d2, ..." of the axis inside the inserts' window.
std::string junctions_in_window(const Analysed& a, const Point2& centre) {
  const MedialGraph& g = *a.axis.graph;
  std::string degrees;
  int n = 0;
  for (std::uint32_t v = 0; v < g.node_count(); ++v) {
    const Point2 q = g.node(v).position;
    if (g.degree(v) < 3 || std::fabs(q.x - centre.x) > kSquareInsetHalf || std::fabs(q.y - centre.y) > kSquareInsetHalf)
      continue;
    degrees += (n++ ? ", " : "") + std::to_string(g.degree(v));
  }
  return caption_printf("%d junction%s of degree %s", n, n == 1 ? "" : "s", degrees.c_str());
}

std::string square_caption(const Analysed& a, const Analysed& b) {
  return "Fig. 3.5 (a, b, e, f) redone: the unit square and " + perturbation_text("all round") +
         " their exact medial axes coloured by the EDF (top) and by the potential residue PR (bottom), each over "
         "[0, its maximum on that axis]; inserts: the " +
         caption_printf("%.3g", 2 * kSquareInsetHalf) +
         "-wide box around the middle. EMA: grey dot; PR maximum: blue dot, its two closest boundary points: "
         "crosses; black circles: where the original had them. " +
         changes(a, b) +
         ". Look for the EDF and the EMA staying put while the middle changes its connectivity (inserts: " +
         junctions_in_window(a, a.ema) + " in a, " + junctions_in_window(b, a.ema) +
         " in b), and for PR jumping there: the PR maximum's closest points are " + closest_text(a) +
         " in (e), on adjacent sides, and " + closest_text(b) +
         " in (f), on opposite sides, so the short edge between the new junctions takes the largest PR and the "
         "diagonals, red in (e), turn green in (f).";
}

// Leaves of the axis on the side the one-sided perturbation left alone, and how many of
// them sit at boundary points the original lacks (display tolerance: this is a count for
// the caption).
struct QuietSide {
  int leaves = 0, at_added_points = 0;
};

QuietSide quiet_side(const Analysed& a, const Shape2& original) {
  double lo = original.rings[0].points[0].x, hi = lo;
  for (const Point2& q : original.rings[0].points) lo = std::min(lo, q.x), hi = std::max(hi, q.x);
  const double centre = 0.5 * (lo + hi);
  auto is_vertex = [](const Shape2& s, const Point2& q) {
    for (const Point2& v : s.rings[0].points)
      if (distance(v, q) < 1e-9) return true;
    return false;
  };
  QuietSide out;
  const MedialGraph& g = *a.axis.graph;
  for (std::uint32_t v = 0; v < g.node_count(); ++v) {
    const Point2 q = g.node(v).position;
    if (g.degree(v) != 1 || q.x >= centre) continue;
    ++out.leaves;
    out.at_added_points += is_vertex(a.shape, q) && !is_vertex(original, q);
  }
  return out;
}

std::string key_caption(const Analysed& a, const Analysed& b) {
  const QuietSide before = quiet_side(a, a.shape), after = quiet_side(b, a.shape);
  const double shift = b.pr.maximum.position.x - a.pr.maximum.position.x;
  return "Fig. 3.5 (c, d, g, h) redone: key-1 (data/shapes2d) and " +
         perturbation_text("on its right half only (the points right of the bounding-box centre)") +
         " coloured as in (a, b, e, f), markers likewise. " + changes(a, b) +
         caption_printf(
             ", %s. Look for the EDF and the EMA unchanged despite the many new branches, and for the PR maximum "
             "(blue) moving along the main branch %s, where the noise lengthened the boundary. The unperturbed "
             "left half gains branches too (axis leaves there: %d in c, %d in d, %d of them at points the "
             "densification added: rounding to 6 decimals leaves some of those slightly convex corners, and the "
             "medial axis reaches every convex corner).",
             shift > 0 ? "to the right, towards the perturbed side" : "to the left",
             shift > 0 ? "towards the noisy side" : "(here not towards the noisy side)", before.leaves, after.leaves,
             after.at_added_points);
}

std::vector<FigureFile> fig_3_5(const FigureContext& ctx) {
  const Analysed square = analyse(unit_square());
  const Analysed square_p = analyse(perturbed(square.shape, PerturbationKind::Uniform, kAmplitude, kSeed));
  const Analysed key = analyse(load_shape(ctx.data_dir + "/shapes2d/key-1.json"));
  const Analysed key_p = analyse(perturbed(key.shape, PerturbationKind::OneSided, kAmplitude, kSeed));
  draw_pair({&square, &square_p, "the unit square", "perturbed all round"}, ctx.out_dir + "/fig3_5_square.svg", 480,
            kSquareInsetHalf, {"(a)", "(b)", "(e)", "(f)"});
  draw_pair({&key, &key_p, "key-1", "perturbed on the right"}, ctx.out_dir + "/fig3_5_key.svg", 700, 0,
            {"(c)", "(d)", "(g)", "(h)"});
  return {{"fig3_5_square.svg", square_caption(square, square_p)}, {"fig3_5_key.svg", key_caption(key, key_p)}};
}

GF_REGISTER_FIGURE("fig3_5", "Figure 3.5: EDF and potential residue under boundary perturbation", fig_3_5);

}  // namespace
}  // namespace grassfire::figures

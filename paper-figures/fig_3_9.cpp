// fig_3_9.cpp -- Figure 3.9 (3.5.3): boundary signatures of a shape with limbs: (a) the
// local curvature, (b) the local feature size over the medial axis, (c, d) boundary
// eccentricity BE on two poses of one figure with E(x), the distance to the EMA along the
// axis, over their medial axes, (e) the correspondence of the two boundaries found by
// matching BE (apps2d/boundary_matching.h, apps2d/match_svg.h), and the signatures as
// plots along the boundary.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "apps2d/boundary_matching.h"
#include "apps2d/match_svg.h"
#include "apps2d/perturbation.h"
#include "burn2/boundary_eccentricity.h"
#include "../experiments/plot_svg.h"
#include "figure_registry.h"
#include "support/atomic_file.h"
#include "render/svg_medial2.h"
#include "pipeline/edf2d.h"
#include "io/load_shape.h"

namespace grassfire::figures {
namespace {

constexpr std::size_t kSamples = 200;  // signature samples per boundary (match2d's default)
constexpr std::size_t kRefine = 5;     // BE's axis from kSamples * kRefine boundary samples
const Rgb kFill{0.93, 0.93, 0.93}, kInk{0, 0, 0}, kAxisGrey{0.3, 0.3, 0.3};

// One shape with its three signatures and the axes they were measured on.
struct SignedShape {
  std::string label;
  Shape2 shape;
  BoundarySignature curvature, lfs, be;
  Edf2dResult exact;    // exact polygon axis: the LFS is the distance to it
  Edf2dResult sampled;  // the axis BE is computed on (the same samples as eccentricity_signature)
  AxisEccentricity e;
};

SignedShape signed_shape(const Shape2& shape, const std::string& label) {
  SignedShape s;
  s.label = label;
  s.shape = shape;
  s.curvature = boundary_samples(s.shape, kSamples);
  s.curvature.values = curvature_signature(s.curvature.points);
  Edf2dOptions exact;
  exact.axis = AxisMethod::ExactPolygon;
  s.exact = compute_edf2d(s.shape, exact);
  s.lfs = boundary_samples(s.shape, kSamples);
  s.lfs.values = local_feature_size(s.lfs.points, *s.exact.graph);
  s.be = eccentricity_signature(s.shape, kSamples, kRefine);
  Edf2dOptions sampled;
  sampled.samples = kSamples * kRefine;
  s.sampled = compute_edf2d(s.shape, sampled);
  s.e = distance_to_ema(*s.sampled.graph, *s.sampled.burning);
  return s;
}

std::pair<double, double> range_of(const std::vector<double>& v) {
  const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
  return {*lo, *hi};
}

// E at arc length s from u along an edge: through the nearer end, or |s - offset| on the
// edge holding the EMA point (display: from the enclosures' midpoints).
double eccentricity_along(const SignedShape& s, std::uint32_t edge, double at) {
  const MedialGraph& g = *s.sampled.graph;
  const MedialEdge& me = g.edge(edge);
  const double w = me.length.mid();
  for (const ExtendedMedialAxis& ema : s.sampled.burning->ema)
    if (ema.kind == ExtendedMedialAxis::Kind::Point && !ema.point.at_node && ema.point.edge == edge) {
      const double o = ema.point.from == me.u ? ema.point.offset.mid() : w - ema.point.offset.mid();
      return std::abs(at - o);
    }
  return std::min(s.e.node[me.u].mid() + at, s.e.node[me.v].mid() + w - at);
}

void draw_eccentricity_axis(SvgCanvas& c, const Medial2Frame& f, const SignedShape& s, double hi, double width) {
  const MedialGraph& g = *s.sampled.graph;
  for (std::uint32_t e = 0; e < g.edge_count(); ++e) {
    const double w = g.edge(e).length.mid();
    const int n = std::max(1, static_cast<int>(std::ceil(w * f.scale() / 4)));
    for (int k = 0; k < n; ++k) {
      const double s0 = w * k / n, s1 = w * (k + 1) / n;
      const std::vector<Point2d> piece = edge_points(f, g, e, {s0, s1});
      c.polyline(piece, heat_color(eccentricity_along(s, e, 0.5 * (s0 + s1)) / hi), width);
    }
  }
  for (const ExtendedMedialAxis& ema : s.sampled.burning->ema) {
    const Point2d p = f(position_of(g, ema.point));
    c.circle(p, 6, {0, 0, 0}, {0, 0, 0}, 1);
    c.circle(p, 3.5, {1, 1, 1}, {1, 1, 1}, 0);
  }
}

void colour_bar(SvgCanvas& c, double x, double y, double w, double lo, double hi, const std::string& name) {
  c.text({x, y + 12}, name, 14);
  const double bx = x + 84, bw = w - 100, unit = std::max(std::abs(lo), std::abs(hi));
  constexpr int kSteps = 96;
  for (int i = 0; i < kSteps; ++i) c.rect(bx + bw * i / kSteps, y, bw / kSteps + 0.5, 14, heat_color((i + 0.5) / kSteps));
  for (int k = 0; k <= 4; ++k) {
    const double tx = bx + bw * k / 4, v = lo + (hi - lo) * k / 4;
    char buf[32];
    // A rounding residue such as an LFS of 6e-17 on the axis is printed as the 0 it stands for.
    std::snprintf(buf, sizeof buf, "%.3g", std::abs(v) < 1e-9 * unit ? 0.0 : v);
    c.polyline({{tx, y + 14}, {tx, y + 19}}, kInk, 1);
    c.text({tx, y + 33}, buf, 12, "middle");
  }
}

enum class Show { Curvature, Lfs, Eccentricity };

const BoundarySignature& signature_of(const SignedShape& s, Show what) {
  return what == Show::Curvature ? s.curvature : what == Show::Lfs ? s.lfs : s.be;
}

constexpr double kPanelW = 560, kTitleH = 36, kShapeH = 600, kPanelH = kTitleH + kShapeH + 56;

// One panel with its top-left corner at (x, y): the shape, its signature on the boundary,
// the axis it refers to (LFS: the exact axis; BE: the sampled axis coloured by E).
void panel(SvgCanvas& c, double x, double y, const SignedShape& s, Show what, const std::string& title) {
  const Medial2Frame f(s.shape, x + 14, y + kTitleH, kPanelW - 28, kShapeH);
  c.text({x + kPanelW / 2, y + 24}, title, 17, "middle");
  c.polygon(shape_polygon(f, s.shape), kFill);
  const BoundarySignature& sig = signature_of(s, what);
  auto [lo, hi] = range_of(sig.values);
  if (what == Show::Lfs) {
    const MedialGraph& g = *s.exact.graph;
    for (std::uint32_t e = 0; e < g.edge_count(); ++e) {
      std::vector<Point2d> pts;
      for (const Point2& p : g.geometry().polyline(g, e)) pts.push_back(f(p));
      c.polyline(pts, kAxisGrey, 1.2);
    }
  }
  if (what == Show::Eccentricity) {
    lo = 0;  // E and BE on one scale from 0 (E = 0 at the EMA) to the largest BE
    draw_eccentricity_axis(c, f, s, hi, 2.6);
  }
  draw_signature(c, f, sig, lo, hi, 7);
  const char* name = what == Show::Curvature ? "curvature" : what == Show::Lfs ? "LFS" : "BE, E";
  colour_bar(c, x + 14, y + kTitleH + kShapeH + 12, kPanelW - 28, lo, hi, name);
}

// The sum of |v_i - v_{i+1}| around the boundary over the signature's range: how many
// full swings the signature makes (a smooth signature with a few extremities: a few).
double swings(const std::vector<double>& v) {
  const auto [lo, hi] = range_of(v);
  double tv = 0;
  for (std::size_t i = 0; i < v.size(); ++i) tv += std::abs(v[i] - v[(i + 1) % v.size()]);
  return hi > lo ? tv / (hi - lo) : 0;
}

// The BE matching of a to b, its marked BE maxima on a and where their partners land.
struct MatchSummary {
  BoundaryMatch match;
  std::vector<std::uint32_t> marked;
  std::size_t near_maximum = 0;  // partners within kNear samples of a BE maximum of b
  std::size_t worst = 0;         // the largest such distance, in samples
};
constexpr std::size_t kWindow = kSamples / 20, kNear = 2;

std::size_t cyclic_distance(std::size_t i, std::size_t j, std::size_t n) {
  const std::size_t d = (i + n - j) % n;
  return std::min(d, n - d);
}

MatchSummary match_summary(const SignedShape& a, const SignedShape& b) {
  MatchSummary s;
  s.match = match_signatures(a.be.values, b.be.values);
  s.marked = signature_maxima(a.be.values, kWindow);
  const std::vector<std::uint32_t> to = correspondence_of(s.match, kSamples);
  const std::vector<std::uint32_t> maxima_b = signature_maxima(b.be.values, kWindow);
  for (std::uint32_t i : s.marked) {
    std::size_t d = kSamples;
    for (std::uint32_t j : maxima_b) d = std::min(d, cyclic_distance(to[i], j, kSamples));
    s.near_maximum += d <= kNear;
    s.worst = std::max(s.worst, d);
  }
  return s;
}

plot::Series series(const std::string& name, const std::vector<double>& y, const Rgb& colour,
                    const std::string& dash = "") {
  plot::Series s;
  s.name = name;
  s.colour = colour;
  s.dash = dash;
  s.markers = false;
  for (std::size_t i = 0; i < y.size(); ++i) s.x.push_back(static_cast<double>(i) / static_cast<double>(y.size()));
  s.y = y;
  return s;
}

const Rgb kClean{0.8, 0.1, 0.1}, kNoisy{0.62, 0.62, 0.62}, kOther{0.1, 0.3, 0.8};
constexpr double kPlotW = 1000, kPlotH = 270;

// Curvature, LFS and BE of a (and of its noisy copy) against the arc-length fraction from
// vertex 0; under BE, b's BE at the samples matched to a's, and a's marked maxima.
void signature_plots(SvgCanvas& c, const SignedShape& a, const SignedShape& noisy, const SignedShape& b,
                     const MatchSummary& ms, const std::string& noise_label) {
  const std::string x_label = "arc length from vertex 0 / perimeter";
  const char* titles[] = {"local curvature (as in a)", "local feature size (as in b)",
                          "boundary eccentricity BE (as in c), with the matching of (e)"};
  for (int row = 0; row < 3; ++row) {
    const Show what = row == 0 ? Show::Curvature : row == 1 ? Show::Lfs : Show::Eccentricity;
    const BoundarySignature &sa = signature_of(a, what), &sn = signature_of(noisy, what);
    plot::Plot p;
    p.title = a.label + ": " + titles[row];
    p.x_label = x_label;
    p.y_label = row == 0 ? "curvature" : row == 1 ? "LFS" : "BE";
    p.width = kPlotW;
    p.height = kPlotH;
    p.series.push_back(series(noise_label, sn.values, kNoisy));
    p.series.push_back(series(a.label, sa.values, kClean));
    if (what == Show::Eccentricity) {
      const std::vector<std::uint32_t> to = correspondence_of(ms.match, kSamples);
      std::vector<double> matched;
      for (std::uint32_t j : to) matched.push_back(b.be.values[j]);
      p.series.push_back(series(b.label + " at the matched samples", matched, kOther, "6,4"));
      plot::Series marks = series("BE maxima marked in (e) (dots)", {}, kInk);
      for (std::uint32_t i : ms.marked) marks.x.push_back(double(i) / kSamples), marks.y.push_back(sa.values[i]);
      marks.line = false;
      marks.markers = true;
      p.series.push_back(marks);
    }
    plot::draw(c, p, 0, row * kPlotH);
  }
}

std::string fmt(const char* format, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

std::string caption_abcd(const SignedShape& a, const SignedShape& b) {
  return "Fig. 3.9 (a-d) redone on rat-01 and rat-02 of the 2D Shape Structure dataset (MPEG-7 class 'rat': a "
         "standing cartoon mouse with ears, arms, a tail and feet, in two poses). Each boundary is resampled at " +
         std::to_string(kSamples) +
         " points by arc length and drawn as a thick curve coloured by a signature, blue low to red high, each panel "
         "on its own scale. (a) Discrete curvature of rat-01 (turning angle over the mean chord, from " +
         fmt("%.3g", range_of(a.curvature.values).first) + " to " + fmt("%.3g", range_of(a.curvature.values).second) +
         "): green, near 0, on most of the boundary, with a few spikes where the polygon bends strongly. (b) Local "
         "feature size, the distance to the exact medial axis (grey, " +
         std::to_string(a.exact.graph->node_count()) +
         " nodes): it drops to 0 wherever a branch reaches a convex vertex, and equally thick parts (arms, tail, "
         "feet) look alike. (c, d) Boundary eccentricity BE(p) = min over the medial points x closest to p of "
         "E(x) + R(x), on the sampled axis of " +
         std::to_string(kSamples * kRefine) +
         " boundary samples, with E(x), the distance along that axis to the EMA (black ring), colouring the axis on "
         "the same scale from 0: BE grows smoothly towards the extremities and is highest on the rim of the right ear "
         "and at the tail tip (largest BE " +
         fmt("%.3f", range_of(a.be.values).second) + " on rat-01, " + fmt("%.3f", range_of(b.be.values).second) +
         " on rat-02); the two poses get the same pattern. Total variation over range, the number of full "
         "swings of a signature around the boundary: curvature " +
         fmt("%.1f", swings(a.curvature.values)) + ", LFS " + fmt("%.1f", swings(a.lfs.values)) + ", BE " +
         fmt("%.1f", swings(a.be.values)) + " (rat-01).";
}

std::string caption_e(const SignedShape& a, const SignedShape& b, const MatchSummary& ms) {
  return "Fig. 3.9 (e) redone: rat-01 (left) and rat-02 (right) coloured by BE, matched by the dynamic program of "
         "apps2d/boundary_matching.h on BE divided by its maximum (every cyclic offset, stretch cost 0.05): offset " +
         std::to_string(ms.match.offset) + " (sample 0 of rat-01 goes to sample " + std::to_string(ms.match.offset) +
         " of rat-02), cost " + fmt("%.4f", ms.match.cost) + ", " + std::to_string(ms.match.stretch_steps) +
         " stretch steps, " + std::to_string(ms.match.path.size()) + " pairs. The " +
         std::to_string(ms.marked.size()) + " local maxima of rat-01's BE (largest within " +
         std::to_string(kWindow) +
         " samples on either side) are joined to their partners on rat-02 (same colour, dashed): " +
         std::to_string(ms.near_maximum) + " of the " + std::to_string(ms.marked.size()) +
         " partners lie within " + std::to_string(kNear) +
         " samples of a BE maximum of rat-02 (the farthest " + std::to_string(ms.worst) + " samples away). " +
         "Look for every dot landing on the same part of the other pose: left arm, both feet, tail tip, hand, the "
         "underside of the right ear, between the ears. " +
         (a.be.filled + b.be.filled == 0 ? std::string("Every BE sample had a medial point.")
                                         : std::to_string(a.be.filled + b.be.filled) +
                                               " BE samples had no medial point and took a neighbour's value.");
}

std::string caption_plots(const SignedShape& a, const SignedShape& noisy, double amplitude) {
  auto pair = [](double clean, double noise) { return fmt("%.1f", clean) + " -> " + fmt("%.1f", noise); };
  return "Fig. 3.9, the signatures of (a-c) as plots against the arc length from vertex 0 over the perimeter, on "
         "rat-01 (red) and on rat-01 with uniform boundary noise of amplitude " +
         fmt("%.3g", amplitude) +
         " (0.5% of its height, spacing 0.01, apps2d/perturbation.h, seed 7; grey), as the dissertation's noisy "
         "shape. Swings (total variation over range) without -> with noise: curvature " +
         pair(swings(a.curvature.values), swings(noisy.curvature.values)) + ", LFS " +
         pair(swings(a.lfs.values), swings(noisy.lfs.values)) + ", BE " +
         pair(swings(a.be.values), swings(noisy.be.values)) + "; the largest LFS falls from " +
         fmt("%.3g", range_of(a.lfs.values).second) + " to " + fmt("%.3g", range_of(noisy.lfs.values).second) +
         ", as every convex noise vertex adds an axis branch. Under BE, rat-02's BE at the samples matched to "
         "rat-01's (blue dashed) and the maxima marked in (e) (black dots). Look for BE unchanged by the noise and "
         "closely followed by the other pose, while the local signatures flicker.";
}

std::vector<FigureFile> fig_3_9(const FigureContext& ctx) {
  const Shape2 shape_a = load_shape(ctx.data_dir + "/shapes2d/rat-01.json");
  const SignedShape a = signed_shape(shape_a, "rat-01"),
                    b = signed_shape(load_shape(ctx.data_dir + "/shapes2d/rat-02.json"), "rat-02");
  PerturbationOptions noise;
  noise.amplitude = 0.005;  // 0.5% of the shape's height (1)
  noise.spacing = 0.01;
  noise.seed = 7;
  const SignedShape noisy = signed_shape(perturb_boundary(shape_a, noise).shape, "rat-01 + noise");
  const MatchSummary ms = match_summary(a, b);

  SvgCanvas c(2 * kPanelW, 2 * kPanelH);
  panel(c, 0, 0, a, Show::Curvature, "(a) local curvature: " + a.label);
  panel(c, kPanelW, 0, a, Show::Lfs, "(b) local feature size and the medial axis: " + a.label);
  panel(c, 0, kPanelH, a, Show::Eccentricity, "(c) BE, and E(x) on the medial axis: " + a.label);
  panel(c, kPanelW, kPanelH, b, Show::Eccentricity, "(d) BE, and E(x) on the medial axis: " + b.label);
  c.save(ctx.out_dir + "/fig3_9abcd.svg");

  const std::string title = "(e) " + a.label + " \u2192 " + b.label + ": BE matching, offset " +
                            std::to_string(ms.match.offset) + ", cost " + fmt("%.3f", ms.match.cost) + "; " +
                            std::to_string(ms.marked.size()) + " BE maxima of " + a.label + " and their partners";
  write_file_atomically(ctx.out_dir + "/fig3_9e.svg",
                        match_svg(a.shape, a.be, b.shape, b.be, ms.match, ms.marked, title, 1200));

  SvgCanvas plots(kPlotW, 3 * kPlotH);
  signature_plots(plots, a, noisy, b, ms, "rat-01 + noise " + fmt("%.3g", noise.amplitude));
  plots.save(ctx.out_dir + "/fig3_9plots.svg");
  return {{"fig3_9abcd.svg", caption_abcd(a, b)},
          {"fig3_9e.svg", caption_e(a, b, ms)},
          {"fig3_9plots.svg", caption_plots(a, noisy, noise.amplitude)}};
}

GF_REGISTER_FIGURE("fig3_9", "Figure 3.9: boundary signatures and BE matching", fig_3_9);

}  // namespace

}  // namespace grassfire::figures

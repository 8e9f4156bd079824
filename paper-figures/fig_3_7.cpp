// fig_3_7.cpp -- Figure 3.7: more examples of topology-preserving pruning by ET and ST
// together (the thresholds of Fig. 3.6 e) on real silhouettes: (a, b, c) the medial axis,
// the EDF over the distance function R, and the pruned axis; (d) pruned axes only (3.5.1).
#include <algorithm>
#include <cstdio>
#include <string>

#include "fig_3_pruning.h"
#include "figure_registry.h"

namespace grassfire::figures {
namespace {

constexpr std::size_t kSamples = 3000;
constexpr double kRelativeEt = 0.05;
const char* const kRows[] = {"elephant-1", "dog-2", "teddy-01"};
const char* const kMore[] = {"device2-1", "cattle-1", "children-1", "rat-01", "fork-1", "bird-1"};
const Rgb kAxisBlue{0.1, 0.25, 0.8}, kConnector{0.95, 0.45, 0.0};

struct Example {
  std::string name;
  Chapter3Shape shape;
  PrunedShape whole, pruned, plain;  // no thresholds; topology-preserving; the same without topology
};

Example example(const FigureContext& ctx, const std::string& name) {
  Example e{name, chapter3_shape(ctx.data_dir + "/shapes2d/" + name + ".json", kSamples), {}, {}, {}};
  e.whole = prune_shape(e.shape, relative_thresholds(e.shape.shape, 0, 0, false));
  e.pruned = prune_shape(e.shape, relative_thresholds(e.shape.shape, kRelativeEt, tubularity_threshold(), true));
  e.plain = prune_shape(e.shape, relative_thresholds(e.shape.shape, kRelativeEt, tubularity_threshold(), false));
  return e;
}

std::string percent(double fraction) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "%.0f%%", 100 * fraction);
  return buf;
}

std::string components(std::uint64_t n) {
  return std::to_string(n) + (n == 1 ? " component" : " components");
}

// The pruned panel's note: kept length, components before and after.
std::string pruned_note(const Example& e) {
  const PruningSummary& s = e.pruned.summary;
  return "kept " + percent(s.kept_fraction()) + " of the length; components " + std::to_string(s.axis_components) +
         " -> " + std::to_string(s.kept_components);
}

// The topology-preserving result in orange under the passing points (plain pruning) in black.
Pruned2SvgOptions pruned_options(const Example& e, const std::string& title) {
  Pruned2SvgOptions o;
  o.title = title;
  o.note = pruned_note(e);
  o.colour = kConnector;
  o.overlay = &e.plain.axis;
  return o;
}

// One row of (a, b, c): axis, EDF over R, pruned axis. The pruned panels get the plot
// area of the EDF panel (a note below instead of its taller colour bars) so the three
// shapes align.
double example_row(SvgCanvas& c, double y, double pw, const Example& e, const std::string& letter) {
  Medial2SvgOptions mo;
  mo.distance_background = true;
  mo.title = letter + " EDF over R: " + e.name;
  const double h = medial2_panel_height(e.shape.shape, mo, pw);
  Medial2SvgOptions no_bar = mo;
  no_bar.colour_bar = false;
  char note[80];
  std::snprintf(note, sizeof note, "length %.3g, %s", e.whole.summary.axis_length.mid(),
                components(e.whole.summary.axis_components).c_str());
  Pruned2SvgOptions axis;
  axis.title = letter + " medial axis: " + e.name;
  axis.show_axis = false, axis.mark_cuts = false, axis.colour = kAxisBlue, axis.axis_width = pw / 300;
  Pruned2SvgOptions no_note = axis;
  axis.note = note;
  const double note_strip = pruned2_panel_height(e.shape.shape, axis, pw) - pruned2_panel_height(e.shape.shape, no_note, pw);
  const double ph = medial2_panel_height(e.shape.shape, no_bar, pw) + note_strip;
  pruned_panel(c, 0, y, pw, ph, e.shape, e.whole, axis);
  draw_medial2(c, pw, y, pw, h, e.shape.shape, *e.shape.result.graph, *e.shape.result.burning,
               e.shape.result.measures, mo);
  pruned_panel(c, 2 * pw, y, pw, ph, e.shape, e.pruned, pruned_options(e, letter + " pruned: " + e.name));
  return h;
}

// "elephant-1 (T = 0.05): kept 34% of the axis length (2.8 of 8.27); components and cycles
// 1 and 0 before, 1 and 0 after; plain pruning: 1 component, 34%".
std::string example_numbers(const Example& e) {
  const PruningSummary& s = e.pruned.summary;
  char buf[320];
  std::snprintf(buf, sizeof buf,
                "%s (T = %.3g): kept %s of the axis length (%.3g of %.3g); components and cycles %llu and %llu "
                "before, %llu and %llu after; plain pruning: %s, %s",
                e.name.c_str(), e.pruned.thresholds.erosion.get_d(), percent(s.kept_fraction()).c_str(),
                s.kept_length.mid(), s.axis_length.mid(), static_cast<unsigned long long>(s.axis_components),
                static_cast<unsigned long long>(s.axis_cycles), static_cast<unsigned long long>(s.kept_components),
                static_cast<unsigned long long>(s.kept_cycles), components(e.plain.summary.kept_components).c_str(),
                percent(e.plain.summary.kept_fraction()).c_str());
  return buf;
}

std::string thresholds_text() {
  return "Thresholds as in Fig. 3.6 (e): ET >= T = 0.05 of the shape's dimension (the larger side of its bounding "
         "box) and ST >= 0.3 (just above 1 - 1/sqrt(2)), topology-preserving (failing leaves peeled, 3.3.2). Medial "
         "axes from " +
         std::to_string(kSamples) + " boundary samples. Pruned axes: black, the points passing both thresholds "
         "(plain pruning); orange, what topology preservation keeps besides to connect them; thin grey, the whole "
         "axis; white dots, cut points (a threshold crossed inside an edge). ";
}

FigureFile rows_figure(const FigureContext& ctx) {
  const double pw = 520;
  std::vector<Example> rows;
  for (const char* name : kRows) rows.push_back(example(ctx, name));
  Medial2SvgOptions mo;
  mo.distance_background = true;
  mo.title = "title";
  double total = 0;
  for (const Example& e : rows) total += medial2_panel_height(e.shape.shape, mo, pw);
  SvgCanvas c(3 * pw, total);
  double y = 0;
  const char* letters[] = {"(a)", "(b)", "(c)"};
  std::string numbers;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    y += example_row(c, y, pw, rows[i], letters[i]);
    numbers += std::string(letters[i]) + " " + example_numbers(rows[i]) + ". ";
  }
  c.save(ctx.out_dir + "/fig3_7abc.svg");
  return {"fig3_7abc.svg",
          "Fig. 3.7 (a, b, c) redone: three silhouettes of the 2D Shape Structure dataset, each with its medial axis "
          "(blue), the EDF over the distance function R (heat colours over grey, the EMA as a grey dot) and the "
          "pruned axis. " +
              thresholds_text() + numbers +
              "Look for the limbs (trunk, legs, tail, ears) kept nearly to their tips, where the EDF is far above R, "
              "while the branches into the polygon's small convex corners (EDF close to R) are removed; on " +
              rows[2].name + " the short orange pieces in the head reconnect the " +
              std::to_string(rows[2].plain.summary.kept_components - 1) + " pieces that plain pruning cuts off."};
}

FigureFile more_figure(const FigureContext& ctx) {
  const double pw = 300;
  std::vector<Example> more;
  for (const char* name : kMore) more.push_back(example(ctx, name));
  Pruned2SvgOptions po;
  po.title = "title";
  po.note = "note";
  double h = 0;
  for (const Example& e : more) h = std::max(h, pruned2_panel_height(e.shape.shape, po, pw));
  SvgCanvas c(pw * static_cast<double>(more.size()), h + 30);
  c.text({12, 22}, "(d) pruned medial axes only", 18, "start");
  std::string numbers, split;
  for (std::size_t i = 0; i < more.size(); ++i) {
    pruned_panel(c, pw * static_cast<double>(i), 30, pw, h, more[i].shape, more[i].pruned,
                 pruned_options(more[i], more[i].name));
    numbers += example_numbers(more[i]) + ". ";
    const std::uint64_t pieces = more[i].plain.summary.kept_components;
    if (pieces > 1) split += (split.empty() ? "" : ", ") + more[i].name + ": " + std::to_string(pieces);
  }
  c.save(ctx.out_dir + "/fig3_7d.svg");
  return {"fig3_7d.svg",
          "Fig. 3.7 (d) redone: only the pruned axes of six more silhouettes. " +
              thresholds_text() + numbers +
              "Look for one connected skeleton per shape: where plain pruning leaves several pieces (" + split +
              "), the orange branches join them as in the original axis."};
}

std::vector<FigureFile> fig_3_7(const FigureContext& ctx) {
  return {rows_figure(ctx), more_figure(ctx)};
}

GF_REGISTER_FIGURE("fig3_7", "Figure 3.7: pruning by ET and ST with topology preservation", fig_3_7);

}  // namespace
}  // namespace grassfire::figures

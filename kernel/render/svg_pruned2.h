// svg_pruned2.h -- pictures of a pruned medial axis (burn2/axis_pruning.h) and the numbers
// that describe a pruning (Figs. 3.6 c-e and 3.7 of the dissertation, 3.5.1).
//
// Computes:
//  - pruning_summary: the length, edge, node and cut-point counts, components and
//    independent cycles of the pruned axis next to those of the whole medial graph, so a
//    caption can state what was kept and that topology-preserving pruning kept the Betti
//    numbers. Lengths are sums of the certified edge-length enclosures (the kept stretch
//    of an edge, PrunedEdge::length), hence enclosures themselves.
//  - draw_pruned2: one panel, bottom to top: the shape filled light grey and its boundary
//    (render/svg_medial2.h's shape_polygon and draw_boundary); the whole medial axis, thin and
//    faint, so that what was removed stays visible; the kept stretches, thick, in one
//    colour (chains of edges through nodes of degree 2 joined into one polyline, which
//    keeps the SVG of a sampled axis small) or coloured by a field (heat colours, render/svg_medial2.h's heat_color and
//    medial2_field_along, cut at the quench point where the field has its kink);
//    optionally a second pruning over it in another colour; the cut points (where a
//    threshold is crossed inside an edge) as small dots; pruned nodes with no kept edge (a
//    tree shrunk to its EMA) as larger dots; a title above and a note below the shape.
// Coordinates: those of render/svg_medial2.h's Medial2Frame (y up, the shape's bounding box
// fitted into the panel). Positions along edges are midpoints of certified enclosures of
// the offsets (display only: no decision depends on them).
// Contract: `pruned` was computed by prune_axis on `g` with `burning`; `g` approximates the
// medial axis of `shape`, a validated shape.
// Complexity: O(n + m + pieces) for the n nodes and m edges of the graph and the pruned axis.
// Section: 3.5.1 (pruning medial axes), Figs. 3.6, 3.7.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "burn2/axis_pruning.h"
#include "render/svg_medial2.h"

namespace grassfire {

struct PruningSummary {
  Interval axis_length, kept_length;  // total edge length of the medial graph and of the pruned axis
  std::uint32_t axis_edges = 0, axis_nodes = 0, axis_components = 0;
  std::uint64_t axis_cycles = 0;
  std::size_t kept_edges = 0, kept_nodes = 0;
  std::uint64_t cut_points = 0, kept_components = 0, kept_cycles = 0;
  // kept / axis length, from the midpoints (display); 0 for an axis of length 0.
  double kept_fraction() const;
};
PruningSummary pruning_summary(const MedialGraph& g, const PrunedAxis& pruned);

struct Pruned2SvgOptions {
  std::string title;  // above the shape when not empty
  std::string note;   // one line below the shape when not empty
  bool show_axis = true;  // the whole medial axis, faint, under the kept part
  bool colour_by_field = false;                // heat colours of `field` along the kept axis
  Medial2Field field = Medial2Field::Et;
  double range_lo = 0, range_hi = 0;           // its colour scale when lo < hi, else the graph's range
  Rgb colour{0.05, 0.05, 0.05};                // the kept axis when not coloured by a field
  // A second pruning of the same graph drawn over the kept axis, in its own colour: e.g.
  // the passing points (plain pruning) inside a topology-preserving result, so that what
  // was kept only to preserve the topology shows in `colour`.
  const PrunedAxis* overlay = nullptr;
  Rgb overlay_colour{0.05, 0.05, 0.05};
  bool mark_cuts = true;                       // cut points as dots
  double axis_width = 0;                       // px of the kept axis; 0: width / 200
  double max_piece = 4;                        // px: the longest piece of a coloured edge
};

// The panel height that fits the shape at the given width (title and note included).
double pruned2_panel_height(const Shape2& shape, const Pruned2SvgOptions& options, double width);

// Draws one panel into the box (x, y, w, h) of the canvas; returns the number of
// polylines drawn for the kept axis and the overlay: one per coloured piece, and in a single
// colour one per chain of edges (edges are joined through the nodes of degree 2).
std::size_t draw_pruned2(SvgCanvas& c, double x, double y, double w, double h, const Shape2& shape,
                         const MedialGraph& g, const GrassfireResult& burning, const NodeMeasures& measures,
                         const PrunedAxis& pruned, const Pruned2SvgOptions& options);

}  // namespace grassfire

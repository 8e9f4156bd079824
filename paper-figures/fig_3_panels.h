// fig_3_panels.h -- what the chapter-3 figures (3.3, 3.4) share: a shape with its sampled
// medial axis and burning, and rows of panels drawn by render/svg_medial2.h.
#pragma once

#include <string>
#include <vector>

#include "render/svg_medial2.h"
#include "pipeline/edf2d.h"

namespace grassfire::figures {

struct Chapter3Shape {
  Shape2 shape;
  Edf2dResult result;
};
// The shape named by `arg` (a file or a built-in), its axis from `samples` boundary samples.
Chapter3Shape chapter3_shape(const std::string& arg, std::size_t samples);

// The height of a row of panels `panel_w` wide, each titled.
double row_height(const std::vector<const Chapter3Shape*>& shapes, Medial2SvgOptions o, double panel_w);
// Draws the shapes side by side at height y, with the options and one title each.
void panel_row(SvgCanvas& c, double y, double panel_w, const std::vector<const Chapter3Shape*>& shapes,
               Medial2SvgOptions o, const std::vector<std::string>& titles);
// "the point (x, y) with EDF e" or "a loop of n edges (EDF infinite)", per component.
std::string ema_summary(const Chapter3Shape& s);

}  // namespace grassfire::figures

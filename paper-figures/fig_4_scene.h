// fig_4_scene.h -- what the chapter-4 figures share: the board and fin with its burning
// time (the closed-form LPDF is curves3/lpdf.h), and drawing a complex with a scalar field and iso-curves.
#pragma once

#include <array>
#include <functional>
#include <string>
#include <vector>

#include "burn3/discrete/discrete_burning.h"
#include "curves3/lpdf.h"
#include "complex3/medial_complex.h"
#include "render/render3d.h"

namespace grassfire::figures {

// The board and fin computed on E = 10, g = 4 (triangles of side 1/4), h = 1/16; drawn in
// the window x in [-3, 8], y in [0, 8], fin z <= 3 (away from the truncation).
struct BoardFinScene {
  MedialComplex mc;
  DiscreteBurning burning;
  std::vector<std::uint32_t> drawn;  // triangles inside the window
  BoardFinScene();
};
const BoardFinScene& board_fin_scene();

Point3d p3(const Vec3d& v);

// A value per triangle corner (triangle, corner 0..2).
using CornerValue = std::function<double(std::uint32_t triangle, int corner)>;
// BT at corner c of triangle t as the limit from t's sector: at a point of a singular curve
// BT jumps between sectors (Prop. 6), and the first arrival through the sector, when it
// came before the point burned, is that sector's limit.
double sector_burn_time(const MedialComplex& mc, const DiscreteBurning& d, std::uint32_t t, int c);
// Draws the triangles coloured by `value` (hue from lo to hi; each triangle subdivided
// `subdivisions` times per edge for the colour) with iso-curves every `step` (none when
// step <= 0).
void draw_scalar(Renderer3d& r, const MedialComplex& mc, const std::vector<std::uint32_t>& triangles,
                 const CornerValue& value, double lo, double hi, double step, int subdivisions = 1);
// The edges of a stratum (border, singular) among the given triangles, as lines.
void draw_edges(Renderer3d& r, const MedialComplex& mc, const std::vector<std::uint32_t>& triangles, EdgeStratum s,
                const Rgb& color, double width, bool skip_never = false);
// A horizontal colour bar with its range.
void colour_bar(SvgCanvas& c, double x, double y, double w, double lo, double hi, const std::string& title);

Camera board_fin_camera();

}  // namespace grassfire::figures

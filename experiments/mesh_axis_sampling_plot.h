// mesh_axis_sampling_plot.h -- the picture of the mesh-axis sampling study (docs/exactness.md; experiments/study_mesh_axis_sampling.cpp), shared by the study and by the
// paper figure that redraws it from the committed CSV (paper-figures/fig_mesh_axis_sampling.cpp).
//
// Computes: two panels in one SVG, one series per mesh:
//  1. Hausdorff distance / D between the mesh axis and its reference (the exact convex axis
//     of a convex mesh, the finest axis otherwise; the finest row itself is not drawn, nor
//     a distance under 1e-9 D: the same axis, counted "not shown")
//     against h_axis / D, log-log; for convex meshes also the distance from the reference's
//     points of depth R >= 2 h_axis (dashed), the part the separation test promises;
//  2. the Betti number error of the first round (sum over b0, b1, b2 of |b - b(solid)|,
//     before any refinement) against h / D: how fine a plain sampling must be for the
//     solid's topology.
// D is the mesh's bounding diagonal, h the starting spacing, h_axis the coarsest spacing of
// the returned round. Reading: the rows of OUT/mesh_axis_sampling.csv with an axis (the
// columns are found by name in the header line, so added columns do not break it).
// Contract: none; rows without an axis are skipped. Complexity: O(rows).
#pragma once

#include <cstdlib>
#include <fstream>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "plot_svg.h"

namespace grassfire::sampling_plot {

struct Point {
  std::string mesh;
  bool convex = false;
  bool reference = false;  // the finest axis of a non-convex mesh: its own reference
  double h_over_d = 0, h_axis_over_d = 0, hausdorff_over_d = 0, core_over_d = NAN;
  long first_round_betti_error = 0;
};

inline std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> out(1);
  bool quoted = false;
  for (char c : line) {
    if (c == '"') quoted = !quoted;
    else if (c == ',' && !quoted) out.emplace_back();
    else out.back() += c;
  }
  return out;
}

// "1:2:0" and "1:0:0" -> 2.
inline long betti_error(const std::string& a, const std::string& b) {
  long sum = 0;
  std::size_t i = 0, j = 0;
  for (int k = 0; k < 3; ++k) {
    const std::size_t ei = a.find(':', i), ej = b.find(':', j);
    sum += std::labs(std::stol(a.substr(i, ei - i)) - std::stol(b.substr(j, ej - j)));
    i = ei + 1, j = ej + 1;
  }
  return sum;
}

inline std::vector<Point> read_csv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot read the sampling study's CSV");
  std::string line;
  std::getline(in, line);
  std::map<std::string, std::size_t> column;
  const std::vector<std::string> names = split_csv_line(line);
  for (std::size_t i = 0; i < names.size(); ++i) column[names[i]] = i;
  for (const char* need : {"mesh", "convex", "h", "h_over_D", "h_axis", "betti_solid", "betti_first_round", "reference",
                           "hausdorff_over_D", "missing_core"})
    if (!column.count(need)) throw std::runtime_error(path + ": no column " + need);
  std::vector<Point> out;
  while (std::getline(in, line)) {
    const std::vector<std::string> f = split_csv_line(line);
    if (f.size() != names.size() || f[column["h_axis"]].empty()) continue;  // no axis
    Point p;
    p.mesh = f[column["mesh"]];
    p.convex = f[column["convex"]] == "1";
    const double d = std::stod(f[column["h"]]) / std::stod(f[column["h_over_D"]]);
    p.h_over_d = std::stod(f[column["h_over_D"]]);
    p.h_axis_over_d = std::stod(f[column["h_axis"]]) / d;
    p.hausdorff_over_d = std::stod(f[column["hausdorff_over_D"]]);
    p.core_over_d = p.convex ? std::stod(f[column["missing_core"]]) / d : NAN;
    p.reference = !p.convex && p.hausdorff_over_d == 0 && f[column["reference"]] == "finest";
    p.first_round_betti_error = betti_error(f[column["betti_first_round"]], f[column["betti_solid"]]);
    out.push_back(p);
  }
  return out;
}

// Below this Hausdorff / D two axes are the same up to rounding (the same round at two
// densities): not drawn on the log scale, counted as "not shown" in the legend.
constexpr double kSameAxis = 1e-9;

// The points in the order given (a mesh's rows together, coarse to fine).
inline void save(const std::vector<Point>& points, const std::string& path) {
  plot::Plot distance;
  distance.title = "mesh axis against sampling: Hausdorff distance to the reference axis";
  distance.x_label = "h_axis / D (coarsest spacing of the returned round / bounding diagonal)";
  distance.y_label = "Hausdorff / D";
  distance.log_x = distance.log_y = true;
  plot::Plot topology;
  topology.title = "topology against sampling: Betti number error of the first round (before refinement)";
  topology.x_label = "h / D (spacing of the first round / bounding diagonal)";
  topology.y_label = "sum of |b - b(solid)|";
  topology.log_x = true;
  std::vector<std::string> meshes;
  for (const Point& p : points)
    if (meshes.empty() || meshes.back() != p.mesh) meshes.push_back(p.mesh);
  for (std::size_t m = 0; m < meshes.size(); ++m) {
    plot::Series hausdorff, core, errors;
    hausdorff.name = meshes[m];
    core.name = meshes[m] + ", R >= 2 h_axis";
    core.dash = "5,3";
    errors.name = meshes[m];
    for (const Point& p : points) {
      if (p.mesh != meshes[m]) continue;
      hausdorff.name = meshes[m] + (p.convex ? " (exact convex axis)" : " (finest axis)");
      if (!p.reference) {
        hausdorff.x.push_back(p.h_axis_over_d);
        hausdorff.y.push_back(p.hausdorff_over_d < kSameAxis ? 0 : p.hausdorff_over_d);
      }
      if (p.convex) {
        core.x.push_back(p.h_axis_over_d);
        core.y.push_back(p.core_over_d);
      }
      errors.x.push_back(p.h_over_d);
      errors.y.push_back(static_cast<double>(p.first_round_betti_error));
    }
    hausdorff.colour = core.colour = errors.colour = plot::series_colour(m);
    if (!hausdorff.x.empty()) distance.series.push_back(hausdorff);
    if (!core.x.empty()) distance.series.push_back(core);
    topology.series.push_back(errors);
  }
  distance.slopes.push_back({1, 0.01, 0.02, "slope 1 (Hausdorff ~ h)"});
  distance.height = 120 + 16.0 * (distance.series.size() + 1);
  distance.height = distance.height < 460 ? 460 : distance.height;
  SvgCanvas c(distance.width, distance.height + topology.height);
  c.rect(0, 0, distance.width, distance.height + topology.height, {1, 1, 1});
  plot::draw(c, distance, 0, 0);
  plot::draw(c, topology, 0, distance.height);
  c.save(path);
}

}  // namespace grassfire::sampling_plot

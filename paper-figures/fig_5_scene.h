// fig_5_scene.h -- what the chapter-5 figures share: a complex with its discrete burning,
// field, refinement, medial curves and shape analysis, and drawing them (curves, burning
// paths as arrows, a complex coloured by BT or by a per-triangle colour, a mesh surface).
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "curves3/axis_refinement.h"
#include "curves3/burning_paths.h"
#include "burn3/discrete/discrete_burning_field.h"
#include "curves3/medial_curves.h"
#include "curves3/shape_analysis.h"
#include "geometry3/triangle_mesh.h"
#include "render/render3d.h"

namespace grassfire::figures {

struct CurvesScene {
  MedialComplex mc;
  DiscreteBurning burning;
  std::unique_ptr<DiscreteBurningField> field;
  AxisRefinement k;
  MedialCurves curves;
  ShapeAnalysis analysis;
  CurvesScene(const RawComplex& raw, double h, const MedialCurveOptions& options = {});
};

// A camera looking at the bounding box of `points` from azimuth / elevation (degrees),
// far enough to see all of it with the given field of view.
Camera framing_camera(const std::vector<Vec3d>& points, double azimuth, double elevation, double fov = 30);
std::vector<Vec3d> vertex_positions(const MedialComplex& mc);

// The complex's triangles coloured by BT (the side limit at each corner), hue lo..hi.
void draw_burning(Renderer3d& r, const CurvesScene& s, double lo, double hi, double iso_step);
// The complex's triangles in one colour per triangle.
void draw_flat(Renderer3d& r, const MedialComplex& mc, const std::function<Rgb(std::uint32_t triangle)>& color);
void draw_curves(Renderer3d& r, const MedialCurves& c, const Rgb& color, double width,
                 const std::function<bool(std::uint32_t edge)>& keep = nullptr);
// The complex as a light wireframe, so that the curves inside show, and its medial curves in red.
void draw_wire_and_curves(Renderer3d& r, const CurvesScene& s);
// Fig. 5.5's layout: column titles, then two rows (the shape, its perturbed copy) of three
// 500 x 430 panels from `cam`; draw(row, column, r) fills each panel.
void draw_rows_of_three(SvgCanvas& canvas, const Camera& cam, const std::array<std::string, 3>& titles,
                        const std::function<void(int row, int column, Renderer3d& r)>& draw);
// The largest finite BT at the scene's vertices (0 when none burns).
double max_finite_bt(const CurvesScene& s);
// Each path as a polyline with an arrowhead where it arrives (points[0]); arrowheads are
// `head` long (in model units).
void draw_paths(Renderer3d& r, const std::vector<BurningPath>& paths, const Rgb& color, double width, double head);
// A triangle mesh with a scalar per vertex (hue lo..hi), each triangle subdivided n times.
void draw_mesh_scalar(Renderer3d& r, const TriangleMesh3& mesh, const std::vector<double>& value, double lo, double hi,
                      int subdivisions);
void draw_mesh_flat(Renderer3d& r, const TriangleMesh3& mesh, const Rgb& color);

// Every n-th element (n >= 1).
template <class T>
std::vector<T> every(const std::vector<T>& v, std::size_t n) {
  std::vector<T> out;
  for (std::size_t i = 0; i < v.size(); i += n) out.push_back(v[i]);
  return out;
}

}  // namespace grassfire::figures

namespace grassfire::figures {

// The mesh's triangles split n x n, each small triangle's corners coloured by the BT of
// the medial ball touching them (shape_analysis.h: map_to_surface), hue lo..hi.
void draw_surface_burning(Renderer3d& r, const TriangleMesh3& mesh, const AxisRefinement& k, int n, double lo, double hi);

}  // namespace grassfire::figures

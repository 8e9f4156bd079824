// burn3d.cpp -- see burn3d.h.
#include "pipeline/burn3d.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "complex3/builders/medial_axis_input.h"
#include "complex3/synthetic_complexes.h"
#include "io/complex_ma.h"
#include "io/mesh_io.h"
#include "io/progress.h"

namespace grassfire {

namespace {

bool is_synthetic(const std::string& input) {
  for (const std::string& n : synthetic_complex_names())
    if (input == n || (n == "book:K" && input.rfind("book:", 0) == 0) || (n == "box:A:B:C" && input.rfind("box:", 0) == 0))
      return true;
  return false;
}

nlohmann::json finite_or_null(const std::vector<double>& values) {
  nlohmann::json a = nlohmann::json::array();
  for (double v : values) a.push_back(std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr));
  return a;
}

}  // namespace

RawComplex load_burn_complex(const std::string& input, bool mesh_is_complex) {
  if (is_synthetic(input)) return synthetic_complex(input);
  const std::string ext = file_extension(input);
  if (ext == "ma") return read_ma(input);
  if (mesh_is_complex) {
    if (ext != "off" && ext != "ply" && ext != "obj")
      throw std::runtime_error(input + ": --mesh-is-complex needs a mesh (.off, .ply or .obj)");
    return mesh_as_complex(read_triangle_mesh(input));
  }
  if (ext == "off" || ext == "ply" || ext == "obj" || ext == "hs" || ext == "halfspaces" || ext == "cin" ||
      ext == "balls") {
    MedialAxisBuild axis = build_medial_axis(input, MedialInputKind::Auto);
    note("burn3d: " + input + ": medial axis by the " + axis.kind + " builder");
    return std::move(axis.complex);
  }
  std::string names;
  for (const std::string& n : synthetic_complex_names()) names += " " + n;
  throw std::runtime_error("'" + input + "' is neither a synthetic complex (" + names.substr(1) +
                           ") nor a file with extension .ma, .off, .ply, .obj, .hs, .halfspaces, .cin or .balls");
}

double default_burn_spacing(const MedialComplex& mc) {
  Vec3d lo = mc.vertex(0).approx, hi = lo;
  for (const ComplexVertex& v : mc.vertices())
    for (int i = 0; i < 3; ++i) lo[i] = std::min(lo[i], v.approx[i]), hi[i] = std::max(hi[i], v.approx[i]);
  const double h = std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]) / 100;
  return h > 0 ? h : 1;
}

DiscreteBurning burn3d_discrete(const MedialComplex& mc, const Burn3dOptions& options) {
  DiscreteBurningOptions o;
  o.spacing = options.spacing ? *options.spacing : default_burn_spacing(mc);
  if (!(o.spacing > 0) || !std::isfinite(o.spacing)) throw std::invalid_argument("--spacing must be a positive number");
  o.max_points = options.max_points;
  return burn_discrete(mc, o);
}

nlohmann::json burn3d_report(const std::string& input, const MedialComplex& mc, const DiscreteBurning& d) {
  nlohmann::json j;
  j["input"] = input;
  j["method"] = "discrete";
  j["spacing"] = d.spacing;
  j["complex"] = {{"vertices", mc.vertex_count()},
                  {"edges", mc.edge_count()},
                  {"triangles", mc.triangle_count()},
                  {"segments", mc.count(EdgeStratum::Dangling)},
                  {"border_edges", mc.count(EdgeStratum::Border)},
                  {"singular_edges", mc.count(EdgeStratum::Singular)},
                  {"singular_points", mc.count(VertexKind::SingularPoint)},
                  {"sheets", mc.sheets().size()}};
  j["sources"] = 0;  // point sources and queries: `grassfire burn3d --sources/--at` (tools/burn3d.cpp)
  j["queries"] = 0;
  j["stats"] = {{"spacing", d.spacing},
                {"steiner_points", d.stats.steiner_points},
                {"arrivals_pushed", d.stats.pushes},
                {"arrivals_popped", d.stats.pops},
                {"seconds", d.stats.seconds}};
  std::size_t unburned = 0;
  double max_bt = 0, max_et = 0;
  for (std::uint32_t v = 0; v < mc.vertex_count(); ++v) {
    if (!std::isfinite(d.vertex_bt[v])) {
      ++unburned;
      continue;
    }
    max_bt = std::max(max_bt, d.vertex_bt[v]);
    max_et = std::max(max_et, d.vertex_et[v]);
  }
  j["summary"] = {{"burned_vertices", mc.vertex_count() - unburned},
                  {"unburned_vertices", unburned},
                  {"max_bt", max_bt},
                  {"max_et", max_et}};
  std::vector<double> x, y, z, r;
  for (const ComplexVertex& v : mc.vertices()) {
    x.push_back(v.approx[0]), y.push_back(v.approx[1]), z.push_back(v.approx[2]), r.push_back(v.radius);
  }
  j["vertex_values"] = {{"x", x}, {"y", y}, {"z", z}, {"R", r}, {"BT", finite_or_null(d.vertex_bt)},
                        {"ET", finite_or_null(d.vertex_et)}};
  return j;
}

}  // namespace grassfire

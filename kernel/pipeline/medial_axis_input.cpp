// medial_axis_input.cpp -- see medial_axis_input.h.
#include "pipeline/medial_axis_input.h"

#include <chrono>
#include <stdexcept>

#include "medial3/convex/convex_polyhedron_axis.h"
#include "io/halfspace_list.h"
#include "medial3/mesh/mesh_axis.h"
#include "complex3/simplicial_homology.h"
#include "medial3/balls/union_of_balls_axis.h"
#include "io/mesh_io.h"
#include "io/mesh_input.h"

namespace grassfire {

namespace {

nlohmann::json betti_json(const BettiNumbers& b) { return {b.b0, b.b1, b.b2}; }

nlohmann::json edge_degrees_json(const RawComplex& c) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& [k, n] : edge_degree_histogram(c)) j[std::to_string(k)] = n;
  return j;
}

nlohmann::json complex_json(const RawComplex& c) {
  return {{"vertices", c.vertices.size()},
          {"triangles", c.triangles.size()},
          {"segments", c.segments.size()},
          {"border_rules", c.border_rules.size()},
          {"betti", betti_json(betti_numbers(c))},
          {"edges_by_triangle_count", edge_degrees_json(c)}};
}

nlohmann::json clip_json(const ClipStats& s) {
  return {{"sign_tests", s.sign_tests},     {"by_support", s.by_support}, {"by_structure", s.by_structure},
          {"by_filter", s.by_filter},       {"by_exact", s.by_exact},     {"exact_points", s.exact_points},
          {"exact_zero", s.number.exact_zero}};
}

MedialAxisBuild convex(const ConvexPolyhedron& p) {
  const ConvexAxis a = convex_polyhedron_axis(p);
  MedialAxisBuild out{a.complex, "convex", {}};
  out.report = {{"facets", a.u.size()},
                {"redundant_planes", a.redundant_planes},
                {"exact", a.exact},
                {"square_class", a.s.get_str()},
                {"distance_bound", a.distance_bound},
                {"polygons", a.polygons},
                {"volume", a.volume.get_d()},
                {"cells_tile_polyhedron", a.volume == a.cell_volume_sum},
                {"clipping", clip_json(a.stats)}};
  return out;
}

nlohmann::json balls_json(const UnionOfBallsAxis& a) {
  std::size_t exact = 0;
  for (const AxisVertexInfo& i : a.vertex_info) exact += i.exact;
  return {{"balls", a.balls},
          {"hidden_balls", a.hidden_balls},
          {"triangulation_dimension", a.triangulation_dimension},
          {"alpha_complex", {a.alpha_simplices[0], a.alpha_simplices[1], a.alpha_simplices[2], a.alpha_simplices[3]}},
          {"singular_simplices", {a.singular_simplices[0], a.singular_simplices[1], a.singular_simplices[2]}},
          {"boundary_vertices", a.boundary.size()},
          {"tet_polygons", a.tet_polygons},
          {"exact_vertices", exact},
          {"coordinate_error", a.coordinate_error},
          {"radius_squared_error", a.radius_squared_error},
          {"rule_point_error", a.rule_point_error},
          {"union_betti", betti_json(a.union_betti)},
          {"merged_by_position", a.merged_by_position},
          {"triangulation_seconds", a.triangulation_seconds},
          {"seconds", a.total_seconds},
          {"clipping", clip_json(a.stats)}};
}

MedialInputKind kind_of_path(const std::string& path) {
  const std::string ext = file_extension(path);
  if (is_mesh_extension(ext)) return MedialInputKind::Auto;
  if (ext == "hs" || ext == "halfspaces") return MedialInputKind::Convex;
  if (ext == "cin" || ext == "balls") return MedialInputKind::Balls;
  throw std::invalid_argument(path + ": unknown extension '" + ext +
                              "' (meshes: .off .ply .obj .stl; half-spaces: .hs .halfspaces; balls: .cin .balls)");
}

bool is_mesh_path(const std::string& path) { return is_mesh_extension(file_extension(path)); }

}  // namespace

MedialInputKind parse_medial_input_kind(const std::string& name) {
  if (name == "auto") return MedialInputKind::Auto;
  if (name == "convex") return MedialInputKind::Convex;
  if (name == "balls") return MedialInputKind::Balls;
  if (name == "mesh") return MedialInputKind::Mesh;
  throw std::invalid_argument("unknown kind '" + name + "' (auto, convex, balls, mesh)");
}

MedialAxisBuild build_medial_axis(const std::string& path, MedialInputKind kind, const MeshAxisOptions& mesh_options,
                                  const MeshRepairOptions& repair) {
  const auto start = std::chrono::steady_clock::now();
  if (kind == MedialInputKind::Auto) kind = kind_of_path(path);
  MedialAxisBuild out;
  if (kind == MedialInputKind::Balls) {
    const UnionOfBallsAxis a = union_of_balls_axis(read_ball_list(path));
    out = {a.complex, "balls", balls_json(a)};
  } else if (!is_mesh_path(path)) {
    if (kind != MedialInputKind::Convex) throw std::invalid_argument(path + ": --kind mesh needs a mesh file");
    out = convex(read_halfspaces(path));
  } else {
    TriangleMesh3 mesh = read_triangle_mesh(path);
    const nlohmann::json mesh_input = mesh_input_json(mesh);
    nlohmann::json repair_report;
    if (repair.enabled) {
      MeshRepair r = repair_mesh(mesh, repair);
      repair_report = mesh_repair_json(r);
      repair_report["summary"] = describe_repair(r);
      mesh = std::move(r.mesh);
    }
    bool use_convex = kind == MedialInputKind::Convex;
    ConvexPolyhedron p;
    if (kind == MedialInputKind::Auto) {
      try {
        p = convex_polyhedron_from_mesh(mesh);
        use_convex = true;
      } catch (const std::invalid_argument&) {
        use_convex = false;  // not convex (or not a solid: the mesh axis builder reports that)
      }
    } else if (use_convex) {
      p = convex_polyhedron_from_mesh(mesh);
    }
    if (use_convex) {
      out = convex(p);
    } else {
      const MeshAxis a = mesh_medial_axis(mesh, mesh_options);
      out = {a.complex, "mesh", mesh_axis_json(a)};
    }
    out.report["mesh_input"] = mesh_input;
    if (repair.enabled) out.report["repair"] = repair_report;
  }
  out.report["input"] = path;
  out.report["kind"] = out.kind;
  out.report["axis"] = complex_json(out.complex);
  out.report["total_seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

MeshAxisOptions medial3d_mesh_options(double samples, double angle_degrees, long refinements, long max_samples) {
  if (!(samples > 0 && samples <= 1024)) throw std::invalid_argument("--samples must be in (0, 1024]");
  if (!(angle_degrees >= 0 && angle_degrees < 180)) throw std::invalid_argument("--angle must be in [0, 180)");
  if (refinements < 0 || refinements > 12)
    throw std::invalid_argument("option --refinements must be an integer in [0, 12], got '" + std::to_string(refinements) +
                                "'");
  if (max_samples < 1000 || max_samples > 1000000000L)
    throw std::invalid_argument("option --max-samples must be an integer in [1000, 1000000000], got '" +
                                std::to_string(max_samples) + "'");
  MeshAxisOptions o;
  o.max_samples = static_cast<std::size_t>(max_samples);
  o.samples_per_edge = samples;
  o.angle_degrees = angle_degrees;
  o.max_refinements = static_cast<int>(refinements);
  return o;
}

}  // namespace grassfire

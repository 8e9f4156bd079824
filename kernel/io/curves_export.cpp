// curves_export.cpp -- JSON and polylines of medial curve graphs (see header).
#include "io/curves_export.h"

#include "io/json_numbers.h"

#include <cmath>

namespace grassfire {

nlohmann::json medial_curves_json(const MedialCurves& c, const std::string& input) {
  nlohmann::json j;
  j["format"] = "grassfire-curves3d";
  j["version"] = 1;
  j["input"] = input;
  j["method"] = c.method;
  nlohmann::json nodes = nlohmann::json::array();
  for (const CurveNode& n : c.nodes)
    nodes.push_back({{"x", n.position[0]},
                     {"y", n.position[1]},
                     {"z", n.position[2]},
                     {"R", n.radius},
                     {"bt", finite_or_null(n.bt)},
                     {"et", finite_or_null(n.bt - n.radius)}});
  j["nodes"] = std::move(nodes);
  nlohmann::json edges = nlohmann::json::array();
  for (const CurveEdge& e : c.edges)
    edges.push_back({{"u", e.u}, {"v", e.v}, {"length", e.length}, {"kind", e.raw_end ? "end" : "join"}});
  j["edges"] = std::move(edges);
  j["betti"] = {c.curve_betti.b0, c.curve_betti.b1};
  j["axis_betti"] = {c.axis_betti.b0, c.axis_betti.b1, c.axis_betti.b2};
  j["options"] = {{"arrive_cosine", c.options.arrive_cosine},
                  {"depart_cosine", c.options.depart_cosine},
                  {"time_margin", c.options.time_margin},
                  {"min_et_fraction", c.options.min_et_fraction}};
  const MedialCurveStats& s = c.stats;
  j["stats"] = {{"refined_vertices", s.refined_vertices}, {"refined_edges", s.refined_edges},
                {"refined_triangles", s.refined_triangles}, {"raw_end_edges", s.raw_end_edges},
                {"punctures", s.punctures}, {"walls_opened", s.walls_opened},
                {"residual_triangles", s.residual_triangles}, {"peeled_edges", s.peeled_edges},
                {"total_length", c.total_length()}, {"seconds", s.seconds}};
  return j;
}

nlohmann::json shape_analysis_json(const ShapeAnalysis& a, double planar_tubularity) {
  const ShapeSignature& s = a.signature;
  return {{"planar_tubularity", planar_tubularity}, {"planar_area", s.planar_area},
          {"tubular_area", s.tubular_area},         {"tubular_curve_length", s.tubular_curve_length},
          {"planar_curve_length", s.planar_curve_length}, {"sheet_areas", s.sheet_areas},
          {"curve_lengths", s.curve_lengths}};
}

PolylineSet medial_curves_polylines(const MedialCurves& c) {
  PolylineSet set;
  VertexField r{"R", {}}, bt{"BT", {}}, et{"ET", {}};
  for (const CurveNode& n : c.nodes) {
    set.points.push_back(n.position);
    r.values.push_back(n.radius);
    bt.values.push_back(n.bt);
    et.values.push_back(n.bt - n.radius);
  }
  for (const CurveEdge& e : c.edges) set.lines.push_back({e.u, e.v});
  set.fields = {std::move(r), std::move(bt), std::move(et)};
  return set;
}

nlohmann::json burning_paths_json(const std::vector<BurningPath>& paths, const std::string& input,
                                  const std::string& method, const std::string& from) {
  nlohmann::json list = nlohmann::json::array();
  for (const BurningPath& p : paths) {
    nlohmann::json points = nlohmann::json::array();
    for (const Vec3d& q : p.points) points.push_back({q[0], q[1], q[2]});
    list.push_back({{"bt", finite_or_null(p.bt)}, {"length", p.length}, {"points", std::move(points)}});
  }
  return {{"format", "grassfire-paths3d"}, {"version", 1}, {"input", input},
          {"method", method},              {"from", from},  {"paths", std::move(list)}};
}

PolylineSet burning_paths_polylines(const std::vector<BurningPath>& paths) {
  PolylineSet set;
  VertexField bt{"BT", {}};
  for (const BurningPath& p : paths) {
    if (p.points.size() < 2) continue;
    std::vector<std::uint32_t> line;
    double walked = 0;
    for (std::size_t i = 0; i < p.points.size(); ++i) {
      if (i > 0) walked += std::hypot(p.points[i][0] - p.points[i - 1][0], p.points[i][1] - p.points[i - 1][1],
                                      p.points[i][2] - p.points[i - 1][2]);
      line.push_back(static_cast<std::uint32_t>(set.points.size()));
      set.points.push_back(p.points[i]);
      bt.values.push_back(p.bt - walked);
    }
    set.lines.push_back(std::move(line));
  }
  set.fields = {std::move(bt)};
  return set;
}

}  // namespace grassfire

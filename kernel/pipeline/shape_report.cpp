// shape_report.cpp -- the validation and built-in shape documents (shape_report.h).
#include "pipeline/shape_report.h"

#include <nlohmann/json.hpp>

#include "shapes/builtin_shapes.h"

namespace grassfire {

std::string shape_validation_json(const Shape2& shape, const ShapeValidation& report) {
  nlohmann::json rings = nlohmann::json::array();
  Interval area(0.0);
  for (std::size_t r = 0; r < shape.rings.size(); ++r) {
    const RingValidation& v = report.rings[r];
    const Interval a = signed_area(shape.rings[r]);
    area += a;
    rings.push_back({{"vertices", v.vertices},
                     {"input_vertices", v.input_vertices},
                     {"reversed", v.reversed},
                     {"orientation", r == 0 ? "ccw" : "cw"},
                     {"signed_area", a.mid()},
                     {"signed_area_error", a.radius()}});
  }
  const nlohmann::json doc = {{"format", "grassfire-shape-validation"},
                              {"version", 1},
                              {"shape", shape.name},
                              {"valid", true},
                              {"rings", rings},
                              {"area", area.mid()},
                              {"area_error", area.radius()},
                              {"candidate_pairs", report.candidate_pairs},
                              {"orientations_filtered", report.predicates.filtered},
                              {"orientations_exact", report.predicates.exact}};
  return doc.dump(1) + "\n";
}

std::string builtin_shapes_json() {
  nlohmann::json shapes = nlohmann::json::array();
  for (const BuiltinShapeInfo& s : builtin_shape_list()) {
    const Shape2 shape = builtin_shape(s.name);
    std::size_t vertices = 0;
    for (const Ring& r : shape.rings) vertices += r.points.size();
    shapes.push_back({{"name", s.name}, {"description", s.description}, {"rings", shape.rings.size()},
                      {"vertices", vertices}});
  }
  const nlohmann::json doc = {{"format", "grassfire-builtin-shapes"}, {"version", 1}, {"shapes", shapes}};
  return doc.dump(1) + "\n";
}

}  // namespace grassfire

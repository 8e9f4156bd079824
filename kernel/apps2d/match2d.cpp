// match2d.cpp -- see match2d.h.
#include "apps2d/match2d.h"

#include <stdexcept>

#include <nlohmann/json.hpp>

#include "pipeline/edf2d.h"

namespace grassfire {

namespace {

using Json = nlohmann::ordered_json;

BoundarySignature signature_of(const Shape2& s, const std::string& kind, std::size_t n) {
  if (kind == "be") return eccentricity_signature(s, n);
  BoundarySignature sig = boundary_samples(s, n);
  if (kind == "curvature") {
    sig.values = curvature_signature(sig.points);
  } else {
    Edf2dOptions o;
    o.axis = AxisMethod::ExactPolygon;
    sig.values = local_feature_size(sig.points, *compute_edf2d(s, o).graph);
  }
  return sig;
}

Json samples_json(const BoundarySignature& s) {
  Json a = Json::array();
  for (std::size_t i = 0; i < s.points.size(); ++i)
    a.push_back({{"x", s.points[i].x}, {"y", s.points[i].y}, {"value", s.values[i]}});
  return a;
}

}  // namespace

Match2dRun match2d(const Shape2& a, const Shape2& b, const Match2dSetup& setup) {
  const std::string& kind = setup.signature;
  if (kind != "be" && kind != "lfs" && kind != "curvature")
    throw std::invalid_argument("option --signature must be 'be', 'lfs' or 'curvature', got '" + kind + "'");
  if (setup.samples < 8 || setup.samples > 2000)
    throw std::invalid_argument("option --samples must be an integer in [8, 2000], got '" +
                                std::to_string(setup.samples) + "'");
  if (!(setup.stretch >= 0)) throw std::invalid_argument("option --stretch must be a non-negative number");
  const std::size_t n = setup.samples;
  Match2dRun run;
  run.a = signature_of(a, kind, n);
  run.b = signature_of(b, kind, n);
  MatchOptions mo;
  mo.stretch = setup.stretch;
  run.match = match_signatures(run.a.values, run.b.values, mo);
  run.correspondence = correspondence_of(run.match, n);
  Json j;
  j["format"] = "grassfire-match2d";
  j["version"] = 1;
  j["a"] = a.name;
  j["b"] = b.name;
  j["signature"] = kind;
  j["samples"] = n;
  j["stretch"] = mo.stretch;
  j["cost"] = run.match.cost;
  j["offset"] = run.match.offset;
  j["stretch_steps"] = run.match.stretch_steps;
  j["a_samples"] = samples_json(run.a);
  j["b_samples"] = samples_json(run.b);
  Json path = Json::array();
  for (const auto& [i, k] : run.match.path) path.push_back({i, k});
  j["path"] = path;
  j["correspondence"] = run.correspondence;
  run.json = j.dump(1) + "\n";
  return run;
}

}  // namespace grassfire

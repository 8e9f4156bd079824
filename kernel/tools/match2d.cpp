// match2d.cpp -- `grassfire match2d`: correspondence of two shape boundaries guided by their
// boundary eccentricity (3.5.3, Fig. 3.9e).
//
// JSON output (format "grassfire-match2d", version 1; later versions only add members):
//   {"format": "grassfire-match2d", "version": 1, "a": NAME, "b": NAME,
//    "signature": "be"|"lfs"|"curvature", "samples": N, "stretch": S,
//    "cost": C, "offset": O, "stretch_steps": K,
//    "a_samples": [{"x", "y", "value"}...], "b_samples": [...],
//    "path": [[i, j], ...],            // sample i of a corresponds to sample j of b
//    "correspondence": [j_0, ..., j_{N-1}]}  // the first j matched to each i
// Values are the raw signatures; the matching compares them divided by their maxima
// (apps2d/boundary_matching.h).
#include <iostream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "apps2d/boundary_matching.h"
#include "apps2d/match_svg.h"
#include "support/atomic_file.h"
#include "pipeline/edf2d.h"
#include "shapes/builtin_shapes.h"
#include "io/load_shape.h"
#include "tools/commands.h"
#include "tools/options.h"

namespace grassfire::cli {

namespace {

using Json = nlohmann::ordered_json;

BoundarySignature signature_of(const Shape2& s, const std::string& kind, std::size_t n) {
  if (kind == "be") return eccentricity_signature(s, n);
  BoundarySignature sig = boundary_samples(s, n);
  if (kind == "curvature") {
    sig.values = curvature_signature(sig.points);
  } else if (kind == "lfs") {
    Edf2dOptions o;
    o.axis = AxisMethod::ExactPolygon;
    sig.values = local_feature_size(sig.points, *compute_edf2d(s, o).graph);
  } else {
    throw std::invalid_argument("option --signature must be 'be', 'lfs' or 'curvature', got '" + kind + "'");
  }
  return sig;
}

Json samples_json(const BoundarySignature& s) {
  Json a = Json::array();
  for (std::size_t i = 0; i < s.points.size(); ++i)
    a.push_back({{"x", s.points[i].x}, {"y", s.points[i].y}, {"value", s.values[i]}});
  return a;
}

int match2d_main(int argc, char** argv) {
  Options opt("match2d",
              "Matches the boundaries of two planar shapes by dynamic programming guided by a\n"
              "boundary signature, boundary eccentricity BE by default (Liu 2011, 3.5.3): every\n"
              "cyclic start offset, then a monotone correspondence minimising the difference of\n"
              "the normalised signatures plus a penalty per stretch step.");
  opt.positional("A", "the first shape: a .json, .wkt, .png or .gif file, or a built-in name (" + builtin_shape_names() + ")")
      .positional("B", "the second shape, likewise")
      .option("samples", "N", "boundary samples per shape (the DP costs O(N^3))", "200")
      .option("stretch", "S", "cost of a step where only one curve advances (normalised units)", "0.05")
      .option("signature", "K", "be (boundary eccentricity), lfs (local feature size) or curvature", "be")
      .option("json", "OUT", "write the signatures and the correspondence as JSON (format: see source)")
      .option("svg", "OUT", "draw both boundaries coloured by the signature, with lines joining the "
                            "signature's local maxima on A to their partners on B")
      .epilog("examples:\n  grassfire match2d data/shapes2d/children-1.json data/shapes2d/children-2.json --svg m.svg\n"
              "  grassfire match2d branches noisy --signature lfs --samples 150");
  add_image_options(opt);
  if (!opt.parse(argc, argv)) return opt.exit_code();
  const auto n = static_cast<std::size_t>(opt.get_long("samples", 8, 2000));
  MatchOptions mo;
  mo.stretch = opt.get_double("stretch");
  if (!(mo.stretch >= 0)) throw std::invalid_argument("option --stretch must be a non-negative number");
  const std::string kind = opt.get("signature");
  const Shape2 a = load_shape(opt.arg("A"), image_options(opt)), b = load_shape(opt.arg("B"), image_options(opt));
  const BoundarySignature sa = signature_of(a, kind, n), sb = signature_of(b, kind, n);
  const BoundaryMatch m = match_signatures(sa.values, sb.values, mo);
  const std::vector<std::uint32_t> corr = correspondence_of(m, n);
  if (opt.has("json")) {
    Json j;
    j["format"] = "grassfire-match2d";
    j["version"] = 1;
    j["a"] = a.name;
    j["b"] = b.name;
    j["signature"] = kind;
    j["samples"] = n;
    j["stretch"] = mo.stretch;
    j["cost"] = m.cost;
    j["offset"] = m.offset;
    j["stretch_steps"] = m.stretch_steps;
    j["a_samples"] = samples_json(sa);
    j["b_samples"] = samples_json(sb);
    Json path = Json::array();
    for (const auto& [i, k] : m.path) path.push_back({i, k});
    j["path"] = path;
    j["correspondence"] = corr;
    write_file_atomically(opt.get("json"), j.dump(1) + "\n");
  }
  if (opt.has("svg"))
    write_file_atomically(opt.get("svg"), match_svg(a, sa, b, sb, m, signature_maxima(sa.values, n / 20), a.name + "  ->  " + b.name));
  if (!opt.has("quiet")) {
    std::cout << "shapes     " << a.name << " -> " << b.name << "\n"
              << "signature  " << kind << " at " << n << " boundary samples each";
    if (sa.filled + sb.filled > 0) std::cout << " (" << sa.filled + sb.filled << " samples without a medial point filled)";
    std::cout << "\nmatch      offset " << m.offset << ", cost " << m.cost << ", " << m.stretch_steps
              << " stretch steps, " << m.path.size() << " pairs\n";
  }
  return 0;
}

}  // namespace

GF_REGISTER_COMMAND("match2d", "correspond two shape boundaries guided by boundary eccentricity", match2d_main);

}  // namespace grassfire::cli

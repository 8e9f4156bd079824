// prune2d.cpp -- `grassfire prune2d`: the medial axis pruned by ET and ST thresholds (3.5.1).
//
// JSON output (format "grassfire-pruned2d", version 1; later versions only add members):
//   {"format": "grassfire-pruned2d", "version": 1, "shape": NAME, "axis": "sampled"|"exact",
//    "thresholds": {"et": T (absolute), "st": S, "relative": bool, "size": D, "topology": bool},
//    "nodes": [{"x", "y", "R", "edf", "et", "st", "source": {"node": id} | {"edge": id, "offset": s}}],
//    "edges": [{"u", "v", "length", "kind", "source_edge", "from", "to"}],
//    "error_bound": {"position", "offset", "R", "edf", "et", "st", "length"}}
// Nodes and edges read like those of "grassfire-medial2d" (io/medial2_json.h): ids are array
// indices, "edf" and "et" are "inf" on the 2-core. A node comes from an original node, or is
// a cut point at distance "offset" from the source edge's end u; "from" and "to" delimit the
// kept stretch of the source edge the same way. R at cut points is linear along the edge (the
// piecewise-linear graph, burn2/axis_pruning.h); x, y of cut points are for drawing.
#include <algorithm>
#include <cmath>
#include <iostream>

#include <mpfr.h>
#include <nlohmann/json.hpp>

#include "burn2/axis_pruning.h"
#include "io/atomic_file.h"
#include "io/decimal_text.h"
#include "io/disk_list.h"
#include "medial2/union_find.h"
#include "pipeline/edf2d.h"
#include "shapes/builtin_shapes.h"
#include "shapes/load_shape.h"
#include "tools/commands.h"
#include "tools/options.h"

namespace grassfire::cli {

namespace {

using Json = nlohmann::ordered_json;

mpq_class threshold(const Options& opt, const std::string& name) {
  const std::optional<mpq_class> q = parse_exact_decimal(opt.get(name));
  const mpq_class v = q ? *q : mpq_class(-1);
  if (!q || sgn(v) < 0)
    throw std::invalid_argument("option --" + name + " must be a non-negative decimal number, got '" + opt.get(name) +
                                "'");
  return v;
}

Json value(const Interval& x, double& bound) {
  if (x.is_infinite()) return "inf";
  bound = std::max(bound, x.radius());
  return x.mid();
}

std::string pruned_json(const std::string& shape, const char* axis, const PruningThresholds& t, bool relative,
                        double size, const PrunedAxis& p, double position_error) {
  double b_off = 0, b_r = 0, b_edf = 0, b_et = 0, b_st = 0, b_len = 0;
  Json j;
  j["format"] = "grassfire-pruned2d";
  j["version"] = 1;
  j["shape"] = shape;
  j["axis"] = axis;
  j["thresholds"] = {{"et", nearest_double(t.erosion)}, {"st", nearest_double(t.tubularity)}, {"relative", relative},
                     {"size", size},                {"topology", t.topology}};
  Json nodes = Json::array();
  for (const PrunedNode& n : p.nodes) {
    Json o{{"x", n.position.x}, {"y", n.position.y}, {"R", value(n.radius, b_r)}, {"edf", value(n.edf, b_edf)},
           {"et", value(n.erosion, b_et)}, {"st", value(n.tubularity, b_st)}};
    if (n.source_node != kCutPoint)
      o["source"] = {{"node", n.source_node}};
    else
      o["source"] = {{"edge", n.source_edge}, {"offset", value(n.offset, b_off)}};
    nodes.push_back(std::move(o));
  }
  j["nodes"] = std::move(nodes);
  Json edges = Json::array();
  for (const PrunedEdge& e : p.edges)
    edges.push_back({{"u", e.u},
                     {"v", e.v},
                     {"length", value(e.length, b_len)},
                     {"kind", to_string(e.kind)},
                     {"source_edge", e.source_edge},
                     {"from", value(e.from, b_off)},
                     {"to", value(e.to, b_off)}});
  j["edges"] = std::move(edges);
  j["error_bound"] = {{"position", position_error}, {"offset", b_off}, {"R", b_r},     {"edf", b_edf},
                      {"et", b_et},                 {"st", b_st},      {"length", b_len}};
  return j.dump(1) + "\n";
}

std::uint64_t component_count(const PrunedAxis& p) {
  UnionFind components(p.nodes.size());
  std::uint64_t count = p.nodes.size();
  for (const PrunedEdge& e : p.edges)
    if (components.find(e.u) != components.find(e.v)) {
      components.unite(e.u, e.v);
      --count;
    }
  return count;
}

int prune2d_main(int argc, char** argv) {
  Options opt("prune2d",
              "Prunes the medial axis of a planar shape (Liu 2011, 3.5.1): keeps the points whose\n"
              "erosion thickness ET = EDF - R is at least T and whose shape tubularity\n"
              "ST = 1 - R/EDF is at least S, cutting edges exactly where a threshold is crossed;\n"
              "--topology peels only failing leaves instead (the thinning of 3.3.2), which keeps\n"
              "the homotopy type of the axis.");
  opt.positional("SHAPE", "a .json, .wkt, .png or .gif file, or a built-in name (" + builtin_shape_names() + ")")
      .option("et", "T", "ET threshold, in shape units (a fraction of the shape's size with --relative)", "0")
      .option("st", "S", "ST threshold, in [0, 1]", "0")
      .flag("relative", "T is a fraction of the shape's size, the larger side of its bounding box")
      .flag("topology", "topology-preserving pruning: peel failing leaves only")
      .option("samples", "N", "boundary samples for the Voronoi medial axis", std::to_string(kDefaultSamples))
      .flag("exact", "exact medial axis of the polygon instead of samples")
      .option("json", "OUT", "write the pruned graph as JSON (format: kernel/tools/prune2d.cpp)")
      .epilog("Thresholds are read exactly as decimals. The dissertation's (Fig. 3.6 e, 3.7) are\n"
              "ET 0.05 of the shape's size and ST 1 - 1/sqrt(2) ~ 0.3; the ST of a branch into a right-\n"
              "angled corner is exactly 1 - 1/sqrt(2) all along it, so take S a little above to remove it:\n"
              "  grassfire prune2d blunt-sharp --et 0.05 --relative --st 0.3 --topology");
  add_image_options(opt);
  if (!opt.parse(argc, argv)) return opt.exit_code();
  PruningThresholds t;
  t.erosion = threshold(opt, "et");
  t.tubularity = threshold(opt, "st");
  if (t.tubularity > 1) throw std::invalid_argument("option --st must be at most 1");
  t.topology = opt.has("topology");
  const Shape2 shape = load_shape(opt.arg("SHAPE"), image_options(opt));
  const double size = shape_dimension(shape);
  if (opt.has("relative")) t.erosion *= mpq_class(size);
  Edf2dOptions options;
  options.samples = static_cast<std::size_t>(opt.get_long("samples", 8, 1000000000L));
  if (opt.has("exact")) options.axis = AxisMethod::ExactPolygon;
  const Edf2dResult r = compute_edf2d(shape, options);
  const PrunedAxis p = prune_axis(*r.graph, *r.burning, t);
  double position_error = 0;
  for (const MedialNode& n : r.graph->nodes()) position_error = std::max(position_error, n.position_error);
  if (opt.has("json"))
    write_file_atomically(opt.get("json"), pruned_json(shape.name, opt.has("exact") ? "exact" : "sampled", t,
                                                       opt.has("relative"), size, p, position_error));
  if (!opt.has("quiet")) {
    const std::uint64_t components = component_count(p);
    std::cout << "shape      " << shape.name << "\n"
              << "axis       " << r.graph->node_count() << " nodes, " << r.graph->edge_count() << " edges\n"
              << "thresholds ET >= " << nearest_double(t.erosion) << ", ST >= " << nearest_double(t.tubularity)
              << (t.topology ? ", topology-preserving" : "") << "\n"
              << "pruned     " << p.nodes.size() << " nodes (" << p.cut_points << " cut points), " << p.edges.size()
              << " edges, " << components << " components, " << p.edges.size() + components - p.nodes.size()
              << " independent cycles\n";
    if (p.uncertified) std::cout << "uncertified " << p.uncertified << " ties\n";
  }
  return 0;
}

}  // namespace

GF_REGISTER_COMMAND("prune2d", "medial axis pruned by ET and ST thresholds (3.5.1)", prune2d_main);

}  // namespace grassfire::cli

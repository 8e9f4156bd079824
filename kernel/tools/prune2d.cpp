// prune2d.cpp -- `grassfire prune2d`: the medial axis pruned by ET and ST thresholds (3.5.1).
//
// Runs pipeline/prune2d.h (which documents the JSON output, format "grassfire-pruned2d").
#include <iostream>

#include "support/atomic_file.h"
#include "io/disk_list.h"
#include "pipeline/prune2d.h"
#include "shapes/builtin_shapes.h"
#include "io/load_shape.h"
#include "tools/commands.h"
#include "tools/options.h"

namespace grassfire::cli {

namespace {

mpq_class threshold(const Options& opt, const std::string& name) {
  const std::optional<mpq_class> q = parse_exact_decimal(opt.get(name));
  const mpq_class v = q ? *q : mpq_class(-1);
  if (!q || sgn(v) < 0)
    throw std::invalid_argument("option --" + name + " must be a non-negative decimal number, got '" + opt.get(name) +
                                "'");
  return v;
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
      .option("json", "OUT", "write the pruned graph as JSON (format: kernel/pipeline/prune2d.h)")
      .epilog("Thresholds are read exactly as decimals. The dissertation's (Fig. 3.6 e, 3.7) are\n"
              "ET 0.05 of the shape's size and ST 1 - 1/sqrt(2) ~ 0.3; the ST of a branch into a right-\n"
              "angled corner is exactly 1 - 1/sqrt(2) all along it, so take S a little above to remove it:\n"
              "  grassfire prune2d blunt-sharp --et 0.05 --relative --st 0.3 --topology");
  add_image_options(opt);
  if (!opt.parse(argc, argv)) return opt.exit_code();
  Prune2dSetup setup;
  setup.erosion = threshold(opt, "et");
  setup.tubularity = threshold(opt, "st");
  if (setup.tubularity > 1) throw std::invalid_argument("option --st must be at most 1");
  setup.topology = opt.has("topology");
  setup.relative = opt.has("relative");
  const Shape2 shape = load_shape(opt.arg("SHAPE"), image_options(opt));
  setup.options.samples = static_cast<std::size_t>(opt.get_long("samples", 8, 1000000000L));
  if (opt.has("exact")) setup.options.axis = AxisMethod::ExactPolygon;
  const Prune2dRun r = prune2d(shape, setup);
  const PruningThresholds& t = r.thresholds;
  const PrunedAxis& p = r.pruned;
  if (opt.has("json")) write_file_atomically(opt.get("json"), r.json);
  if (!opt.has("quiet")) {
    const std::uint64_t components = r.components;
    std::cout << "shape      " << shape.name << "\n"
              << "axis       " << r.edf.graph->node_count() << " nodes, " << r.edf.graph->edge_count() << " edges\n"
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

// edf2d.cpp -- `grassfire edf2d`: medial axis, EDF, EMA, ET and ST of a planar shape.
#include <cstdio>
#include <iostream>
#include <sstream>

#include "support/atomic_file.h"
#include "io/disk_list.h"
#include "render/svg_medial2.h"
#include "pipeline/edf2d.h"
#include "pipeline/edf2d_json.h"
#include "shapes/builtin_shapes.h"
#include "io/load_shape.h"
#include "tools/commands.h"
#include "tools/options.h"

namespace grassfire::cli {

namespace {

std::string describe_ema(const MedialGraph& g, const ExtendedMedialAxis& ema) {
  std::ostringstream os;
  if (ema.kind == ExtendedMedialAxis::Kind::Cycles) {
    os << "cycles: " << ema.nodes.size() << " nodes, " << ema.edges.size() << " edges (EDF infinite)";
    return os.str();
  }
  const Point2 p = position_of(g, ema.point);
  os << "point (" << p.x << ", " << p.y << ") EDF " << ema.edf.mid();
  if (ema.point.at_node)
    os << " at node " << ema.point.node;
  else
    os << " inside edge " << ema.point.edge;
  return os.str();
}

void print_summary(std::ostream& os, const Shape2& shape, const Edf2dOptions& opt, const Edf2dResult& r) {
  const MedialGraph& g = *r.graph;
  const GrassfireResult& b = *r.burning;
  std::size_t samples = 0;
  for (const auto& ring : r.samples) samples += ring.size();
  os << "shape      " << shape.name;
  if (opt.axis != AxisMethod::DiskUnion) os << " (" << shape.rings.size() << " rings)";
  os << "\n";
  if (opt.axis == AxisMethod::ExactPolygon) {
    const PolygonAxisReport& pr = r.polygon_report;
    os << "axis       exact polygon axis (" << to_string(pr.construction);
    if (pr.voronoi_fallbacks > 0)
      os << "; fallbacks " << pr.voronoi_fallbacks << ": " << to_string(pr.rejected_construction)
         << " gave a wrong diagram (" << pr.fallback_reason << ")";
    os << ")\n";
  } else if (opt.axis == AxisMethod::DiskUnion)
    os << "axis       exact axis of a union of " << r.disk_report.disks << " disks (" << r.disk_report.covered_disks
       << " covered, " << r.disk_report.corners << " boundary corners)\n";
  else
    os << "axis       Voronoi of " << samples << " boundary samples\n";
  std::uint32_t leaves = 0;
  for (std::uint32_t v = 0; v < g.node_count(); ++v) leaves += g.degree(v) == 1;
  os << "graph      " << g.node_count() << " nodes, " << g.edge_count() << " edges, " << leaves << " leaves, "
     << g.component_count() << " components, " << g.cycle_rank() << " independent cycles\n";
  if (r.axis_report.fragment_nodes > 0)
    os << "fragments  " << r.axis_report.components - 1 << " small components (" << r.axis_report.fragment_nodes
       << " nodes) of the Voronoi graph dropped; more samples reduce them\n";
  for (const ExtendedMedialAxis& e : b.ema) os << "EMA        " << describe_ema(g, e) << "\n";
  const NumberStats& st = b.stats();
  os << "certified  " << st.filter_decided << " by interval filter, " << st.mpfr_decided << " by multiprecision, "
     << st.exact_zero << " exact ties, " << st.uncertified_zero << " uncertified\n";
  char buf[200];
  std::snprintf(buf, sizeof buf, "time       %.3f s (resample %.3f, Delaunay %.3f, axis %.3f, burning %.3f)\n",
                r.timings.total(), r.timings.resample, r.timings.delaunay, r.timings.axis, r.timings.burn);
  os << buf;
}

int edf2d_main(int argc, char** argv) {
  Options opt("edf2d",
              "Computes the medial axis of a planar shape, the extended distance function (EDF),\n"
              "the extended medial axis (EMA), erosion thickness ET = EDF - R and shape\n"
              "tubularity ST = 1 - R/EDF (Liu 2011, ch. 3), with certified arithmetic.");
  opt.positional("SHAPE", "a .json (2D Shape Structure dataset), .wkt, .png or .gif file, or a built-in name (" +
                              builtin_shape_names() + "); not with --disks", false)
      .option("disks", "FILE", "a union of disks instead of SHAPE (one 'x y r' line per disk): its exact axis")
      .option("samples", "N", "boundary samples for the Voronoi medial axis", std::to_string(kDefaultSamples))
      .option("spacing", "H", "arc-length spacing of the samples instead of a count")
      .flag("exact", "exact medial axis of the polygon (segment Voronoi diagram) instead of samples")
      .option("variant", "V", "burning algorithm: exact (arrival-ordered, the definition) or dissertation "
                              "(the thinning of 3.3.2)", "exact")
      .option("json", "OUT", "write nodes, edges, EDF, ET, ST and the EMA as JSON (format: README)")
      .option("svg", "OUT", "draw the shape, its medial axis coloured by --field and the EMA as SVG")
      .option("field", "F", "the field --svg colours the axis by: edf, et, st or r", "edf")
      .epilog("examples:\n  grassfire edf2d hole --json hole.json\n"
              "  grassfire edf2d data/shapes2d/Bone-1.json --samples 5000\n"
              "  grassfire edf2d rectangle --exact --variant dissertation\n"
              "  grassfire edf2d --disks tests/data/disks/three.txt");
  add_image_options(opt);
  if (!opt.parse(argc, argv)) return opt.exit_code();
  Edf2dOptions options;
  if (opt.has("exact")) options.axis = AxisMethod::ExactPolygon;
  if (opt.has("spacing")) {
    options.spacing = opt.get_double("spacing");
    if (!(options.spacing > 0)) throw std::invalid_argument("option --spacing must be positive");
  } else {
    options.samples = static_cast<std::size_t>(opt.get_long("samples", 8, 1000000000L));
  }
  const std::string variant = opt.get("variant");
  if (variant == "dissertation")
    options.variant = GrassfireVariant::Dissertation;
  else if (variant != "exact")
    throw std::invalid_argument("option --variant must be 'exact' or 'dissertation', got '" + variant + "'");
  const Medial2Field field = parse_medial2_field(opt.get("field"));
  if (opt.has("disks") == opt.has_arg("SHAPE")) {  // a malformed command line, like a missing argument
    std::cerr << "grassfire edf2d: give either a SHAPE or --disks FILE\n\n" << opt.usage();
    return 2;
  }
  if (opt.has("disks") && opt.has("exact")) throw std::invalid_argument("--exact applies to a SHAPE, not to --disks");
  DiskList disks;
  Shape2 shape;
  if (opt.has("disks")) {
    disks = read_disk_list(opt.get("disks"));
    options.axis = AxisMethod::DiskUnion;
    options.disks = &disks;
    shape.name = disks.name;
  } else {
    shape = load_shape(opt.arg("SHAPE"), image_options(opt));
  }
  const Edf2dResult r = compute_edf2d(shape, options);
  if (opt.has("json")) write_file_atomically(opt.get("json"), edf2d_json(shape, options, r));
  if (opt.has("svg")) {
    Medial2SvgOptions svg;
    svg.field = field;
    svg.title = shape.name;
    write_file_atomically(opt.get("svg"), medial2_svg(shape, *r.graph, *r.burning, r.measures, svg));
  }
  if (!opt.has("quiet")) print_summary(std::cout, shape, options, r);
  return 0;
}

}  // namespace

GF_REGISTER_COMMAND("edf2d", "medial axis, EDF, EMA, ET and ST of a planar shape", edf2d_main);

}  // namespace grassfire::cli

// complex.cpp -- `grassfire complex`: load a complex, check it, describe it, export it.
#include <iostream>

#include "burn3/point_sources.h"
#include "complex3/medial_complex.h"
#include "io/complex_export.h"
#include "io/complex_json.h"
#include "io/complex_ma.h"
#include "support/progress.h"
#include "pipeline/complex_input.h"
#include "tools/commands.h"
#include "tools/options.h"

namespace grassfire::cli {
namespace {

int run_complex(int argc, char** argv) {
  Options opt("complex", "Load a 2-complex, validate it exactly, describe its strata, and export it.");
  opt.positional("INPUT", complex_input_help())
      .flag("mesh-is-complex", "take a mesh itself as the complex (R = 0) instead of its medial axis")
      .flag("no-border-ignition", "set every border edge's rule to never (only point sources would burn it)")
      .option("json", "OUT", "write the complex in the grassfire-complex JSON format (exact)")
      .option("ma", "OUT", "write the complex as .ma (nearest doubles where a value is not a decimal)")
      .option("ply", "OUT", "write the complex with per-vertex R as PLY");
  add_repair_options(opt);
  opt.epilog("Nothing is written unless the complex is valid (MedialComplex checks, exact).\n"
              "Example: grassfire complex board-fin --json board_fin.json");
  if (!opt.parse(argc, argv)) return opt.exit_code();
  const std::string input = opt.arg("INPUT");
  RawComplex raw = load_complex(input, opt.has("mesh-is-complex"), "complex", repair_options(opt));
  if (opt.has("no-border-ignition")) raw = without_border_ignition(std::move(raw));
  const MedialComplex mc(raw);
  mc.validate();
  if (opt.has("json")) write_complex_json(raw, opt.get("json"));
  if (opt.has("ma") && !write_ma_file(raw, opt.get("ma")))
    note("complex: " + opt.get("ma") + ": some values are not decimals and were written as nearest doubles");
  if (opt.has("ply")) {
    std::vector<double> r;
    for (const ComplexVertex& v : mc.vertices()) r.push_back(v.radius);
    write_complex_ply(mc, {{"R", r}}, opt.get("ply"));
  }
  if (opt.has("quiet")) return 0;
  std::cout << "complex " << input << ": " << mc.vertex_count() << " vertices, " << mc.edge_count() << " edges, "
            << mc.triangle_count() << " triangles, " << mc.count(EdgeStratum::Dangling) << " segments, "
            << mc.count(EdgeStratum::Border) << " border edges, " << mc.count(EdgeStratum::Singular)
            << " singular edges, " << mc.count(VertexKind::SingularPoint) << " singular points, " << mc.sheets().size()
            << " sheets\n";
  return 0;
}

GF_REGISTER_COMMAND("complex", "load, validate, describe and export a 3D complex (grassfire-complex JSON, .ma)",
                    run_complex);

}  // namespace
}  // namespace grassfire::cli

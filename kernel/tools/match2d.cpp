// match2d.cpp -- `grassfire match2d`: correspondence of two shape boundaries guided by their
// boundary eccentricity (3.5.3, Fig. 3.9e).
//
// Runs apps2d/match2d.h (which documents the JSON output, format "grassfire-match2d").
#include <iostream>
#include <sstream>

#include "apps2d/boundary_matching.h"
#include "apps2d/match_svg.h"
#include "support/atomic_file.h"
#include "apps2d/match2d.h"
#include "shapes/builtin_shapes.h"
#include "io/load_shape.h"
#include "tools/commands.h"
#include "tools/options.h"

namespace grassfire::cli {

namespace {

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
      .option("json", "OUT", "write the signatures and the correspondence as JSON (format: kernel/apps2d/match2d.h)")
      .option("svg", "OUT", "draw both boundaries coloured by the signature, with lines joining the "
                            "signature's local maxima on A to their partners on B")
      .epilog("examples:\n  grassfire match2d data/shapes2d/children-1.json data/shapes2d/children-2.json --svg m.svg\n"
              "  grassfire match2d branches noisy --signature lfs --samples 150");
  add_image_options(opt);
  if (!opt.parse(argc, argv)) return opt.exit_code();
  Match2dSetup setup;
  setup.samples = static_cast<std::size_t>(opt.get_long("samples", 8, 2000));
  setup.stretch = opt.get_double("stretch");
  if (!(setup.stretch >= 0)) throw std::invalid_argument("option --stretch must be a non-negative number");
  setup.signature = opt.get("signature");
  const std::string& kind = setup.signature;
  const std::size_t n = setup.samples;
  const Shape2 a = load_shape(opt.arg("A"), image_options(opt)), b = load_shape(opt.arg("B"), image_options(opt));
  const Match2dRun r = match2d(a, b, setup);
  const BoundarySignature &sa = r.a, &sb = r.b;
  const BoundaryMatch& m = r.match;
  if (opt.has("json")) write_file_atomically(opt.get("json"), r.json);
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

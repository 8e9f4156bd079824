// validate.cpp -- `grassfire validate SHAPE`: load, check exactly and describe a shape.
#include <cstdio>
#include <iostream>

#include "io/load_shape.h"
#include "pipeline/shape_report.h"
#include "support/atomic_file.h"
#include "tools/commands.h"
#include "tools/options.h"

namespace grassfire::cli {
namespace {

std::string format_area(const Interval& a) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "%.12g (certified within %.2g)", a.mid(), a.radius());
  return buf;
}

int run_validate(int argc, char** argv) {
  Options opt("validate", "Load a shape, check it exactly (simple rings, no ring meeting another, holes inside the\n"
                          "outer ring and outside each other) and describe it. Exit 0 when valid, 1 with the first\n"
                          "problem otherwise.");
  opt.positional("SHAPE", "a .json (shapes2d), .wkt / .txt (Well-Known Text) or .png / .gif (binary image) file, "
                          "or a built-in name")
      .epilog("Repeated consecutive vertices and a repeated closing vertex are dropped silently; the outer\n"
              "ring is made counter-clockwise and holes clockwise. Vertex numbers in messages are\n"
              "0-based positions in the file.");
  opt.option("json", "OUT", "also write the description as JSON (format: kernel/pipeline/shape_report.h)");
  add_image_options(opt);
  if (!opt.parse(argc, argv)) return opt.exit_code();
  ShapeValidation report;
  const Shape2 shape = load_shape(opt.arg("SHAPE"), image_options(opt), &report);
  if (opt.has("json")) write_file_atomically(opt.get("json"), shape_validation_json(shape, report));
  if (opt.has("quiet")) return 0;  // the exit code says valid
  std::cout << shape.name << ": valid, " << shape.rings.size() << (shape.rings.size() == 1 ? " ring" : " rings")
            << "\n";
  Interval area(0.0);
  for (std::size_t r = 0; r < shape.rings.size(); ++r) {
    const RingValidation& v = report.rings[r];
    const Interval a = signed_area(shape.rings[r]);
    area += a;
    std::cout << "  " << ring_label(r) << ": " << v.vertices << " vertices";
    if (v.input_vertices != v.vertices) std::cout << " (" << v.input_vertices - v.vertices << " repeated dropped)";
    std::cout << ", " << (r == 0 ? "counter-clockwise" : "clockwise")
              << (v.reversed ? " (reversed from the input)" : " (as given)") << ", signed area " << format_area(a)
              << "\n";
  }
  std::cout << "  area " << format_area(area) << "\n"
            << "  exact checks: " << report.candidate_pairs << " edge pairs, " << report.predicates.filtered
            << " orientations decided by the filter, " << report.predicates.exact << " by the exact fallback\n";
  return 0;
}

GF_REGISTER_COMMAND("validate", "check a shape file or built-in shape exactly and describe it", run_validate);

}  // namespace
}  // namespace grassfire::cli

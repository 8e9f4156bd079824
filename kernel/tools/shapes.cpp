// shapes.cpp -- `grassfire shapes`: the built-in shapes, and any of them as WKT or JSON.
#include <iostream>

#include "io/shape_json.h"
#include "io/shape_wkt.h"
#include "pipeline/shape_report.h"
#include "shapes/builtin_shapes.h"
#include "support/atomic_file.h"
#include "tools/commands.h"
#include "tools/options.h"

namespace grassfire::cli {
namespace {

int run_shapes(int argc, char** argv) {
  Options opt("shapes", "List the built-in shapes, or print one in a file format.");
  opt.option("wkt", "NAME", "print the built-in shape NAME as Well-Known Text (POLYGON) and exit")
      .option("json", "NAME", "print the built-in shape NAME in the shapes2d JSON format (one ring only)")
      .option("list-json", "OUT", "write the list of built-in shapes as JSON (format: kernel/pipeline/shape_report.h)")
      .epilog("Any command that takes a SHAPE accepts a built-in name, builtin:NAME, or a .json / .wkt / .txt file.\n"
              "Example: grassfire shapes --wkt hole > hole.wkt");
  if (!opt.parse(argc, argv)) return opt.exit_code();
  if (opt.has("wkt")) {
    write_shape_wkt(builtin_shape(opt.get("wkt")), std::cout);
    return 0;
  }
  if (opt.has("json")) {
    write_shape_json(builtin_shape(opt.get("json")), std::cout);
    return 0;
  }
  if (opt.has("list-json")) {
    write_file_atomically(opt.get("list-json"), builtin_shapes_json());
    return 0;
  }
  for (const BuiltinShapeInfo& s : builtin_shape_list()) {
    const Shape2 shape = builtin_shape(s.name);
    std::size_t vertices = 0;
    for (const Ring& r : shape.rings) vertices += r.points.size();
    std::cout << s.name << std::string(s.name.size() < 16 ? 16 - s.name.size() : 1, ' ') << s.description << " ["
              << shape.rings.size() << (shape.rings.size() == 1 ? " ring, " : " rings, ") << vertices
              << " vertices]\n";
  }
  return 0;
}

GF_REGISTER_COMMAND("shapes", "list the built-in shapes; print one as WKT or JSON", run_shapes);

}  // namespace
}  // namespace grassfire::cli

// field_input.cpp -- complex and burning field for the 3D analysis commands (see header).
#include "tools/field_input.h"

#include <stdexcept>

namespace grassfire::cli {

void declare_field_options(Options& opt, const std::string& default_method) {
  opt.option("method", "NAME",
             "burning method: discrete (Dijkstra over vertices and Steiner points with the link rule) or exact "
             "(the certified window-propagation engine)",
             default_method)
      .option("spacing", "H",
              "Steiner point spacing h of the discrete method; exact: the spacing of the points at which medial curves "
              "are traced along edges (default: 1/100 of the bounding box diagonal)")
      .flag("singular-walls", "exact: burn complexes with singular edges, each edge a wall where fronts stop\n"
                              "(an upper bound of BT, not Definition 9)")
      .option("max-points", "N", "refuse to place more than N graph points", "50000000")
      .flag("mesh-is-complex", "use a mesh itself as the 2-complex (R = 0) instead of its medial axis")
      .option("field", "FILE", "read the discrete burning burn3d --field wrote for INPUT instead of burning again\n"
                               "(refused when it was burned on another complex)");
  add_repair_options(opt);
}

FieldSetup field_setup(const Options& opt, const std::string& input, const std::string& command) {
  FieldSetup setup;
  setup.input = input;
  setup.method = opt.get("method");
  setup.mesh_is_complex = opt.has("mesh-is-complex");
  setup.singular_walls = opt.has("singular-walls");
  if (opt.has("spacing")) setup.spacing = opt.get_double("spacing");
  setup.max_points = static_cast<std::uint64_t>(opt.get_long("max-points", 1, 2'000'000'000L));
  setup.command = command;
  setup.repair = repair_options(opt);
  if (opt.has("field")) setup.field_file = opt.get("field");
  return setup;
}

FieldInput load_field(const Options& opt, const std::string& input, const std::string& command) {
  return load_burning_field(field_setup(opt, input, command));
}

}  // namespace grassfire::cli

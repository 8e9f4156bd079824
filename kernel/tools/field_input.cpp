// field_input.cpp -- complex and burning field for the 3D analysis commands (see header).
#include "tools/field_input.h"

#include <cmath>
#include <optional>
#include <stdexcept>

#include "burn3/discrete_burning_field.h"
#include "burn3/exact/exact_burning_field.h"
#include "pipeline/burn3d.h"
#include "pipeline/complex_input.h"

namespace grassfire::cli {

void declare_field_options(Options& opt) {
  opt.option("method", "NAME",
             "burning method: discrete (Dijkstra over vertices and Steiner points with the link rule) or exact "
             "(the certified window-propagation engine)",
             "discrete")
      .option("spacing", "H",
              "Steiner point spacing h of the discrete method; exact: the spacing of the points at which medial curves "
              "are traced along edges (default: 1/100 of the bounding box diagonal)")
      .flag("singular-walls", "exact: burn complexes with singular edges, each edge a wall where fronts stop\n"
                              "(an upper bound of BT, not Definition 9)")
      .option("max-points", "N", "refuse to place more than N graph points", "50000000")
      .flag("mesh-is-complex", "use a mesh itself as the 2-complex (R = 0) instead of its medial axis");
  add_repair_options(opt);
}

namespace {

// The exact engine from the border ignition (the same refusal as burn3d --method exact).
void load_exact_field(FieldInput& in, bool singular_walls, double spacing, const std::string& input) {
  const std::optional<std::string> why = exact_engine_unsupported(*in.complex);
  if (why && !singular_walls)
    throw std::runtime_error(input + ": method 'exact' cannot burn this complex: it has " + *why +
                             "; use --method discrete");
  ExactBurningOptions options;
  options.singular_walls = singular_walls;  // else Definition 9 (the junction rule)
  in.exact = std::make_unique<ExactBurning>(*in.complex, options);
  in.exact->add_border_ignition();
  in.exact->run();
  in.field = std::make_unique<ExactBurningField>(*in.exact, spacing);
}

}  // namespace

FieldInput load_field(const Options& opt, const std::string& input, const std::string& command) {
  const std::string method = opt.get("method");
  if (method != "discrete" && method != "exact")
    throw std::runtime_error("unknown method '" + method + "' (discrete or exact)");
  if (opt.has("singular-walls") && method != "exact") throw std::runtime_error("--singular-walls needs --method exact");
  FieldInput in;
  in.complex = std::make_unique<MedialComplex>(load_complex(input, opt.has("mesh-is-complex"), command, repair_options(opt)));
  in.complex->validate();
  if (in.complex->vertex_count() == 0) throw std::runtime_error(input + ": the complex is empty");
  DiscreteBurningOptions o;
  o.spacing = opt.has("spacing") ? opt.get_double("spacing") : default_burn_spacing(*in.complex);
  if (!(o.spacing > 0) || !std::isfinite(o.spacing)) throw std::runtime_error("--spacing must be a positive number");
  if (method == "exact") {
    load_exact_field(in, opt.has("singular-walls"), o.spacing, input);
    return in;
  }
  o.max_points = static_cast<std::uint64_t>(opt.get_long("max-points", 1, 2'000'000'000L));
  in.burning = std::make_unique<DiscreteBurning>(burn_discrete(*in.complex, o));
  in.field = std::make_unique<DiscreteBurningField>(*in.complex, *in.burning);
  return in;
}

}  // namespace grassfire::cli

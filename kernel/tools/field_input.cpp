// field_input.cpp -- complex and burning field for the 3D analysis commands (see header).
#include "tools/field_input.h"

#include <cmath>
#include <stdexcept>

#include "burn3/discrete_burning_field.h"
#include "pipeline/burn3d.h"
#include "pipeline/complex_input.h"

namespace grassfire::cli {

void declare_field_options(Options& opt) {
  opt.option("method", "NAME", "burning method: discrete (Dijkstra over vertices and Steiner points with the link rule)",
             "discrete")
      .option("spacing", "H", "Steiner point spacing h of the discrete method (default: 1/100 of the bounding box diagonal)")
      .option("max-points", "N", "refuse to place more than N graph points", "50000000")
      .flag("mesh-is-complex", "use a mesh itself as the 2-complex (R = 0) instead of its medial axis");
}

FieldInput load_field(const Options& opt, const std::string& input, const std::string& command) {
  if (opt.get("method") != "discrete")
    throw std::runtime_error("method '" + opt.get("method") + "' is not available: only 'discrete' (the exact "
                             "sweep-event engine is not part of this build)");
  FieldInput in;
  in.complex = std::make_unique<MedialComplex>(load_complex(input, opt.has("mesh-is-complex"), command));
  in.complex->validate();
  if (in.complex->vertex_count() == 0) throw std::runtime_error(input + ": the complex is empty");
  DiscreteBurningOptions o;
  o.spacing = opt.has("spacing") ? opt.get_double("spacing") : default_burn_spacing(*in.complex);
  if (!(o.spacing > 0) || !std::isfinite(o.spacing)) throw std::runtime_error("--spacing must be a positive number");
  o.max_points = static_cast<std::uint64_t>(opt.get_long("max-points", 1, 2'000'000'000L));
  in.burning = std::make_unique<DiscreteBurning>(burn_discrete(*in.complex, o));
  in.field = std::make_unique<DiscreteBurningField>(*in.complex, *in.burning);
  return in;
}

}  // namespace grassfire::cli

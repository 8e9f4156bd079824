// burn3d_field.cpp -- see burn3d_field.h.
#include "pipeline/burn3d_field.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "burn3/discrete/discrete_burning_field.h"
#include "burn3/exact/burn_outputs.h"
#include "burn3/exact/exact_burning_field.h"
#include "io/burn_field_file.h"
#include "pipeline/burn3d.h"
#include "pipeline/complex_input.h"
#include "support/number_text.h"
#include "support/progress.h"

namespace grassfire {
namespace {

// The exact engine from the border ignition (the same refusal as burn3d --method exact).
void load_exact_field(FieldRun& in, const FieldSetup& setup, Progress& progress) {
  const std::optional<std::string> why = exact_engine_unsupported(*in.complex);
  if (why && !setup.singular_walls)
    throw std::runtime_error(setup.input + ": method 'exact' cannot burn this complex: it has " + *why +
                             "; use --method discrete");
  ExactBurningOptions options;
  options.singular_walls = setup.singular_walls;  // else Definition 9 (the junction rule)
  options.on_event = exact_sweep_reporter(*in.complex, 0, [&](double done, const std::string& detail) {
    progress.fraction("exact propagation", done, detail);
  });
  in.exact = std::make_unique<ExactBurning>(*in.complex, options);
  in.exact->add_border_ignition();
  in.exact->run();
  in.field = std::make_unique<ExactBurningField>(*in.exact, in.spacing);
  for (const CertifiedValue& v : vertex_values(*in.exact).bt)
    in.vertex_bt_error.push_back(std::isfinite(v.value) ? v.error : std::numeric_limits<double>::infinity());
}

}  // namespace

FieldRun load_burning_field(const FieldSetup& setup) {
  if (setup.method != "discrete" && setup.method != "exact")
    throw std::invalid_argument("unknown method '" + setup.method + "' (discrete or exact)");
  if (setup.singular_walls && setup.method != "exact") throw std::invalid_argument("--singular-walls needs --method exact");
  if (setup.max_points < 1 || setup.max_points > 2'000'000'000ULL)
    throw std::invalid_argument("--max-points must be in [1, 2000000000]");
  if (setup.field_file && setup.method != "discrete")
    throw std::invalid_argument("--field " + *setup.field_file + " holds a discrete burning: it goes with --method discrete");
  // The stages on stderr as burn3d shows them (support/progress.h), for every command and
  // Python function that burns through here.
  Progress progress(setup.command + " " + setup.input, 0);
  progress.stage("loading the complex");
  FieldRun in;
  in.complex = std::make_unique<MedialComplex>(load_complex(setup.input, setup.mesh_is_complex, setup.command, setup.repair));
  in.complex->validate();
  if (in.complex->vertex_count() == 0) throw std::runtime_error(setup.input + ": the complex is empty");
  if (setup.field_file) {
    progress.stage("reading the field");
    in.burning = std::make_unique<DiscreteBurning>(read_burn_field(*setup.field_file, *in.complex));
    in.spacing = in.burning->spacing;
    if (setup.spacing && *setup.spacing != in.spacing)
      throw std::invalid_argument("--spacing " + shortest_double(*setup.spacing) + " is not the spacing of --field " +
                                  *setup.field_file + " (" + shortest_double(in.spacing) + ")");
    in.field = std::make_unique<DiscreteBurningField>(*in.complex, *in.burning);
    return in;
  }
  in.spacing = setup.spacing ? *setup.spacing : default_burn_spacing(*in.complex);
  if (!(in.spacing > 0) || !std::isfinite(in.spacing)) throw std::invalid_argument("--spacing must be a positive number");
  if (setup.method == "exact") {
    progress.stage("exact propagation");
    load_exact_field(in, setup, progress);
    return in;
  }
  DiscreteBurningOptions o;
  o.spacing = in.spacing;
  o.max_points = setup.max_points;
  o.progress = [&](std::uint64_t burned, std::uint64_t total) {
    progress.fraction("burning", static_cast<double>(burned) / static_cast<double>(total));
  };
  in.burning = std::make_unique<DiscreteBurning>(burn_discrete(*in.complex, o));
  in.field = std::make_unique<DiscreteBurningField>(*in.complex, *in.burning);
  return in;
}

}  // namespace grassfire

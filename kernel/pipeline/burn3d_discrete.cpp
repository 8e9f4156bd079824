// burn3d_discrete.cpp -- `burn3d --method discrete`: the Steiner-point baseline.
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>

#include "burn3/discrete/discrete_burning.h"
#include "burn3/discrete/discrete_query.h"
#include "pipeline/burn3d_methods.h"

namespace grassfire {

BurnOutcome burn_by_discrete(const BurnRequest& request) {
  const MedialComplex& mc = request.mc;
  DiscreteBurningOptions o;
  o.spacing = request.spacing;
  o.max_points = request.max_points;
  o.sources = request.sources;
  if (request.progress)
    o.progress = [&](std::uint64_t burned, std::uint64_t total) {
      request.progress("burning", static_cast<double>(burned) / static_cast<double>(total), "");
    };
  BurnOutcome out;
  out.discrete = std::make_shared<const DiscreteBurning>(burn_discrete(mc, o));
  const DiscreteBurning& d = *out.discrete;
  out.vertex_bt = d.vertex_bt;
  for (std::size_t i = 0; i < request.queries.size(); ++i) {
    // An upper bound only: no certified bound below it (discrete_query.h).
    out.query_values.push_back({discrete_burning_time_at(mc, d, request.sources, request.queries[i]),
                                std::numeric_limits<double>::infinity()});
    if (request.progress && (i & 1023) == 1023)
      request.progress("queries", static_cast<double>(i + 1) / static_cast<double>(request.queries.size()), "");
  }
  out.report = {{"spacing", d.spacing},
                {"steiner_points", d.stats.steiner_points},
                {"arrivals_pushed", d.stats.pushes},
                {"arrivals_popped", d.stats.pops},
                {"seconds", d.stats.seconds}};
  std::ostringstream s;
  s << "discrete h = " << d.spacing << ": " << d.stats.steiner_points << " Steiner points, " << d.stats.seconds << " s";
  out.summary = s.str();
  return out;
}

}  // namespace grassfire

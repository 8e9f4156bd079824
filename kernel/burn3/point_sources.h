// point_sources.h -- fire started at points of a complex (docs/exact-engine.md: a closed mesh has no
// border, so point sources are how it burns).
//
// A point source ignites one point x of the complex at time t0: BT(x) <= t0, and fire
// leaves x in every direction at unit speed (4.2.3 with the ignition set extended by the
// sources; a source at a point of a singular curve ignites it regardless of the link rule).
// Sources add to the border's own ignition; without_border_ignition turns that off, so
// that only the sources burn (multi-source geodesic distance on a manifold, docs/design.md 5,
// reference case 3).
// Contract: each location lies on the complex (snap_squared == 0). Complexity: O(1) each.
#pragma once

#include <gmpxx.h>

#include <vector>

#include "complex3/point_location.h"
#include "complex3/raw_complex.h"

namespace grassfire {

struct PointSource {
  ComplexPoint location;
  mpq_class t0;
};

// The complex with every border edge's rule set to Never (border edges: edges of exactly
// one triangle; dangling segments keep no rule). Other members unchanged.
RawComplex without_border_ignition(RawComplex raw);

}  // namespace grassfire

// A consumer of the installed library: the exact medial axis and EDF of the built-in
// 10 x 4 rectangle, whose EMA is its centre (5, 2) with EDF 3 + 2 sqrt 2 (a corner leaf
// at R = 0, 2 sqrt 2 along the corner branch, 3 along the middle segment).
#include <grassfire/grassfire_version.h>
#include <grassfire/pipeline/edf2d.h>
#include <grassfire/io/load_shape.h>

#include <cmath>
#include <cstdio>

int main() {
  using namespace grassfire;
  Edf2dOptions options;
  options.axis = AxisMethod::ExactPolygon;
  const Edf2dResult r = compute_edf2d(load_shape("rectangle"), options);
  const ExtendedMedialAxis& ema = r.burning->ema.at(0);
  const Point2 p = position_of(*r.graph, ema.point);
  const double expected = 3 + 2 * std::sqrt(2.0);
  std::printf("grassfire %s: EMA (%g, %g), EDF [%.17g, %.17g]\n", GRASSFIRE_VERSION, p.x, p.y, ema.edf.lo, ema.edf.hi);
  // The EDF is a certified enclosure; x, y inside an edge are interpolated doubles, for display.
  const bool ok = std::abs(p.x - 5) < 1e-9 && std::abs(p.y - 2) < 1e-9 && ema.edf.lo <= expected && expected <= ema.edf.hi;
  return ok ? 0 : 1;
}

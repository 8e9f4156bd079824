// point_sources.cpp -- see point_sources.h.
#include "burn3/point_sources.h"

#include <algorithm>
#include <map>

namespace grassfire {

RawComplex without_border_ignition(RawComplex raw) {
  std::map<std::array<std::uint32_t, 2>, int> triangles_at;
  for (const auto& t : raw.triangles)
    for (int i = 0; i < 3; ++i) {
      std::array<std::uint32_t, 2> e = {t[i], t[(i + 1) % 3]};
      if (e[0] > e[1]) std::swap(e[0], e[1]);
      ++triangles_at[e];
    }
  raw.border_rules.clear();
  for (const auto& [edge, count] : triangles_at)
    if (count == 1) raw.border_rules.push_back({edge, IgnitionRule::Never, {}});
  return raw;
}

}  // namespace grassfire

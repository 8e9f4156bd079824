// Helpers shared by the [complex3] and [burn3] tests.
#pragma once

#include <catch2/catch.hpp>

#include "complex3/medial_complex.h"

namespace grassfire::testing {

// Every test validates every complex it builds.
inline MedialComplex built(const RawComplex& raw) {
  MedialComplex mc(raw);
  mc.validate();
  return mc;
}

inline std::uint32_t vertex_at(const MedialComplex& mc, const ExactPoint3& p) {
  for (std::uint32_t v = 0; v < mc.vertex_count(); ++v)
    if (mc.vertex(v).exact == p) return v;
  FAIL("no vertex at (" << p.x.get_d() << ", " << p.y.get_d() << ", " << p.z.get_d() << ")");
  return kNoIndex;
}

}  // namespace grassfire::testing

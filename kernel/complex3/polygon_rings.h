// polygon_rings.h -- polygons of a 2-complex stored as vertex rings in one array.
//
// Ring i is vertex[offset[i] .. offset[i + 1]): the polygon's vertices in cyclic order,
// its k-th side (ring[k], ring[k + 1 mod n]). Used by the inner Voronoi complex, its
// pruning and its homology (no per-polygon allocation: complexes have 10^5..10^6 faces).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace grassfire {

struct PolygonRings {
  std::vector<std::uint32_t> offset{0};
  std::vector<std::uint32_t> vertex;
  std::size_t size() const { return offset.size() - 1; }
  std::uint32_t ring_size(std::size_t i) const { return offset[i + 1] - offset[i]; }
  const std::uint32_t* ring(std::size_t i) const { return vertex.data() + offset[i]; }
  std::array<std::uint32_t, 2> side(std::size_t i, std::uint32_t k) const {
    return {ring(i)[k], ring(i)[(k + 1) % ring_size(i)]};
  }
  void close() { offset.push_back(static_cast<std::uint32_t>(vertex.size())); }  // ends the ring being pushed
};

}  // namespace grassfire

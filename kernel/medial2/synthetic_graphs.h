// synthetic_graphs.h -- seeded random medial graphs with exact values, for tests and checks.
//
// Computes: graphs whose R is strictly 1-Lipschitz along edges (|R(u) - R(v)| < length),
// as on every true medial axis, in two families:
//  - integer: integer R and integer lengths, with many exact ties between burn times;
//  - geometric: nodes at integer points, lengths = Euclidean distances (square roots of
//    integers), R = 9/10 of the distance to the nearest of a few integer "boundary" sites.
// Trees are random recursive trees; `extra_edges` adds random chords that create cycles.
// Contract: nodes >= 1. Complexity: O(n * sites).
#pragma once

#include <cstdint>

#include "medial2/medial_graph.h"

namespace grassfire {

enum class SyntheticFamily { Integer, Geometric };

MedialGraph random_medial_graph(std::uint64_t seed, std::uint32_t nodes, std::uint32_t extra_edges,
                                SyntheticFamily family);

}  // namespace grassfire

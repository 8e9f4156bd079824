// sector_geometry.h -- which vertices can bend a shortest burning path (pseudo-source
// vertices), per sector of the vertex's link (4.2.2, docs/design.md 5).
//
// Computes, for every sector (a fan of triangles around its apex joined across manifold
// edges), whether fire reaching the apex through the sector must restart there as a point
// source: a geodesic bends at a vertex only if the angle of the fan there exceeds pi (an
// open fan: border, wall or pinch) or 2 pi (a closed fan: a saddle), Mitchell, Mount and
// Papadimitriou 1987. The test is certified and errs only towards "bends" (a superfluous
// pseudo-source costs time, never a wrong time):
//  - fans inside one coplanar patch (unfolding.h): a closed fan is flat (exactly 2 pi); an open fan turns
//    from its first end edge to its last, and its angle exceeds pi iff that turn is
//    reflex, decided by exact rational orientation (a straight border has exactly pi);
//  - other fans: the corner angles' sum Theta against pi or 2 pi: the product of the unit
//    complex numbers of the corners in Interval arithmetic, Theta's quadrant tracked along
//    it by certified signs (each corner adds less than pi), decides; if that cannot, Arb
//    (atan2 at 64, 128, 256 bits); a sum that no stage separates from the limit is taken to
//    bend (counted: undecided_angles). No double decides (the mutant double_bending does).
// Also the map from a triangle corner to its sector.
// Contract: a validated MedialComplex. Complexity: O(corners) Interval operations (Arb
// only for fans whose angle equals the limit or nearly).
#pragma once

#include <cstdint>
#include <vector>

#include "burn3/exact/engine_mutant.h"
#include "burn3/exact/unfolding.h"

namespace grassfire {

struct SectorGeometry {
  std::vector<std::uint32_t> corner_sector;  // 3 t + i -> sector id
  std::vector<bool> bends;                   // per sector: a pseudo-source vertex there
  std::uint64_t undecided_angles = 0;        // fans taken to bend because no precision decided
};

SectorGeometry sector_geometry(const Unfolding& u, EngineMutant mutant = EngineMutant::none);

}  // namespace grassfire

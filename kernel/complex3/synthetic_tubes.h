// synthetic_tubes.h -- hand-made complexes with holes: the medial axes of torus-like
// shapes, for the medial curves (5.1.2: the curves must keep the axis' cycles).
//
// Computes RawComplexes with exact rational vertices and R = 0 (every border ignites at
// f = 0):
//  - tube: the side of a prism over k rational points of the circle of radius r (the
//    medial axis of a thick-walled pipe is a cylinder), height H, `rows` rows; both rims
//    ignite. b0 = 1, b1 = 1. BT = the distance to the nearer rim (the side unrolls into a
//    strip): the fronts quench on the middle ring z = H / 2, the one medial curve.
//  - annulus: the flat square ring between [-a, a]^2 and [-b, b]^2 in z = 0 (the medial
//    axis of a flat washer), a grid of g cells per unit; both boundaries ignite. b1 = 1.
//    BT = the distance to the nearer boundary square: ridges on the middle square
//    |x| or |y| = (a + b) / 2 and on the diagonals from the inner to the outer corners.
//  - frame torus: the closed surface of (the annulus' square ring) x [0, c], a polyhedral
//    torus; no border, so BT = infinity everywhere (Prop. 7). b0 = 1, b1 = 2, b2 = 1.
// Names for synthetic_complex(): tube, annulus, torus (default parameters below).
// Contract: parameters as documented (std::invalid_argument otherwise).
// Complexity: linear in the triangles produced.
#pragma once

#include "complex3/raw_complex.h"

namespace grassfire {

struct TubeOptions {
  int sides = 12;   // k
  int rows = 8;     // rows of the side
  int radius = 2;   // r
  int height = 8;   // H
};
RawComplex tube(const TubeOptions& options = {});
// BT of the tube at height z.
double tube_burning_time(const TubeOptions& options, double z);

struct AnnulusOptions {
  int outer = 4;           // a
  int inner = 2;           // b < a
  int cells_per_unit = 2;  // g
};
RawComplex square_annulus(const AnnulusOptions& options = {});
// BT of the annulus at (x, y): the distance to the nearer boundary square.
double annulus_burning_time(const AnnulusOptions& options, double x, double y);

// The polyhedral torus: boundary of the square ring between [-a, a]^2 and [-b, b]^2 times
// [0, c], every face a grid of unit squares split in two.
RawComplex frame_torus(int outer = 3, int inner = 1, int thickness = 1);

}  // namespace grassfire

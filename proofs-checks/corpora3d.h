// corpora3d.h -- the 3D corpora of the chapter-4 checks, named for what they are, with the
// independent reference of the burning time where one exists.
//
// Corpora (sizes by CheckContext::size):
//  - synthetic: hand-built complexes (complex3/synthetic_complexes.h): the board and fin,
//    books, the Y, closed surfaces and pinched ones; closed forms where derived.
//  - generated: seeded random books, box medial axes, octahedra with flaps and hairs, and
//    planar convex sheets (fans with random rims and radii).
//  - generated (data/ma): the box medial axes the project wrote into data/ma.
//  - generated from real shapes (data/ma/real): the axes the project's builders made from
//    CGAL's meshes and ball set (grassfire medial3d --ma; see data/ma/real/README.md).
//  - convex polyhedra: the exact axes of data/meshes' cube and octahedron and of seeded
//    random cuts of the cube (random_cut_cube).
// References of BT (Definition 10) at a point, each derived independently of the
// baseline: the closed forms of the board and fin (docs/design.md 5), of books and the Y, of
// box axes (synthetic_complexes.h), of the regular cube and octahedron (every sheet is the
// bisector of two faces meeting at an edge of dihedral angle theta and burns from that
// edge: BT = R / sin(theta / 2), i.e. sqrt2 R and sqrt(3/2) R); and on planar convex sheets
// the brute-force minimum over the border of |xy| + f(y) (burn3_reference.h).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "check_registry.h"
#include "complex3/medial_complex.h"

namespace grassfire::checks {

// BT at a point p of the complex by an independent computation, given R there (the
// caller interpolates R linearly along the edge of p, which is exact where a reference
// reads it: R is affine on every sheet of a convex polyhedron's axis); NaN where the
// closed form does not apply.
using BurningReference = std::function<double(const MedialComplex& mc, const Vec3d& p, double radius)>;

struct Instance3 {
  std::string name;
  MedialComplex mc;
  BurningReference reference;  // empty when there is none
  bool planar_convex_sheet = false;  // the reference is the brute force of burn3_reference.h
  double spacing = 0;                // h of the baseline on this instance
};

struct Corpus3 {
  std::string name;
  std::string references;  // which references its instances have
  std::vector<Instance3> instances;
};

std::vector<Corpus3> burning_corpora(const CheckContext& ctx);

}  // namespace grassfire::checks

// validate_shape.h -- exact check of the Shape2 contract (geometry2/shape2.h), and normalization.
//
// Computes: whether a shape is a valid planar polygon with holes: at least one ring, finite
// coordinates, every ring with at least 3 vertices, every ring simple, no two rings
// meeting, every hole inside the outer ring and outside every other hole. On success the
// shape is normalized in place (and only then):
//   - a vertex equal to the previous one is dropped, and so are vertices equal to the first
//     vertex at the end of the ring (the shapes2d dataset and WKT repeat the first vertex at
//     the end); this is the only silent change besides orientation;
//   - the outer ring is made counter-clockwise and holes clockwise (interior on the left),
//     by reversing the order of the vertices after vertex 0 (vertex 0 stays first).
// Checks run in stages; the first failing stage throws InvalidShapeError, naming within
// that stage the first offence in order of (ring index, smallest vertex index involved):
//   1. the shape has a ring; every coordinate is finite;
//   2. every ring keeps at least 3 vertices once repeated vertices are dropped;
//   3. no two edges meet, except consecutive edges at their shared vertex: a proper
//      crossing, a touch (e.g. a ring passing twice through one point) or a collinear
//      overlap of any two edges of any rings is an error; consecutive edges that overlap
//      (a zero-width spike, the boundary doubling back) are an error too;
//   4. each hole's vertex 0 lies inside the outer ring and outside every other hole (once
//      rings are disjoint, one vertex decides for its whole ring); a hole inside another
//      hole is reported at the inner one.
// Vertex indices in messages are 0-based positions in the ring as given (before dropping
// repeated vertices); "at about (x, y)" points are rounded, for reading only.
// Method: every decision uses the exact predicates of geometry2/predicates2.h. Candidate
// pairs of edges come from an exact uniform grid (shapes/edge_grid.h), which finds every
// pair that meets; PairSearch::AllPairs tests all pairs and locates holes by scanning whole
// rings, the O(n^2) definition-level reference that tests compare the grid against.
// Contract: none (this is the check); the shape is left unchanged when an error is thrown.
// Complexity: with the grid, O(n log n) for n vertices whose edges have comparable lengths
// (0.25 s for a wavy circle of 10^6 vertices), plus, per hole, the edges registered in one
// grid row. The worst case is quadratic: k edges all passing through one small region (a
// star with k long spikes) are all paired (k = 20000: 2 s). AllPairs: O(n^2).
// Section: the input of the 2D pipeline (dissertation 2.1.2, 3.3.2 assume a simple shape).
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "geometry2/predicates2.h"
#include "number/interval.h"
#include "geometry2/shape2.h"

namespace grassfire {

// Thrown when a shape breaks the contract. what() is "<source>: ring R (outer|hole):
// <problem>", or "<source>: <problem>" for problems of the whole shape.
class InvalidShapeError : public std::runtime_error {
 public:
  InvalidShapeError(const std::string& source, long ring, long vertex, const std::string& problem);
  const std::string& source() const { return source_; }
  long ring() const { return ring_; }      // -1 for problems of the whole shape
  long vertex() const { return vertex_; }  // first offending vertex as given, -1 if none
  const std::string& problem() const { return problem_; }

 private:
  std::string source_;
  long ring_;
  long vertex_;
  std::string problem_;
};

struct RingValidation {
  std::size_t input_vertices = 0;  // as given
  std::size_t vertices = 0;        // after dropping repeated vertices
  bool reversed = false;           // the orientation was flipped
};

struct ShapeValidation {
  std::vector<RingValidation> rings;
  std::uint64_t candidate_pairs = 0;  // pairs of edges tested exactly
  OrientationStats predicates;
};

enum class PairSearch { Grid, AllPairs };

// Checks `shape` and normalizes it in place; `source` (a file path or a built-in name)
// starts every error message. Throws InvalidShapeError.
ShapeValidation validate_shape(Shape2& shape, const std::string& source, PairSearch search = PairSearch::Grid);

// Certified enclosure of the signed area of a ring (positive when counter-clockwise).
Interval signed_area(const Ring& ring);

// "ring 0 (outer)" or "ring 3 (hole)".
std::string ring_label(std::size_t ring);

}  // namespace grassfire

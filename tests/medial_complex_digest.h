// medial_complex_digest.h -- a canonical text of everything a MedialComplex derives (strata,
// lengths, angular orders, incidences, sheets, planarity, every exact frame, sectors, link
// elements, vertex kinds, border points, ignition), and the corpus it is taken on.
//
// tests/data/medial_complex_digests.txt holds the FNV-1a hashes of these texts computed by
// the implementation before the filtered predicates (commit 84237b0, all rational); the
// test test_complex3_filtered.cpp recomputes them with the current one. The header uses
// only accessors both implementations have, so the same file generates the reference.
// Corpus: named synthetic complexes, the .ma medial axes in data/ma (boxes, and the axes our
// builders made of CGAL's pipe and joint meshes and of caffeine, read from files: the builders
// themselves change, and the axis of a mesh was not numbered alike from one process to the
// next), the meshes themselves (Loop-refined to
// about 800 faces), and seeded random complexes (height fields with rational heights,
// books with random rational pages: ties, coplanar sheets and singular edges, overlaps;
// Loop-refined meshes rounded to coarse rational grids: coplanar neighbours, coincident
// vertices, intersecting triangles). Refusals are part of the digest (their message).
#pragma once

#include <cstdint>
#include <cstdio>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "complex3/complex_builder.h"
#include "complex3/medial_complex.h"
#include "geometry3/refined_mesh.h"
#include "complex3/synthetic_complexes.h"
#include "geometry3/triangle_mesh.h"
#include "io/complex_ma.h"
#include "io/mesh_io.h"

namespace grassfire::testing {

inline std::string hex(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%a", x);
  return buf;
}

inline void put(std::ostream& os, const ExactPoint3& p) { os << p.x << ' ' << p.y << ' ' << p.z; }

inline std::string medial_complex_text(const MedialComplex& mc) {
  std::ostringstream os;
  const std::vector<PlanarFrame>& frames = mc.frames();
  for (std::uint32_t v = 0; v < mc.vertex_count(); ++v) {
    const ComplexVertex& x = mc.vertex(v);
    os << "v " << v << ' ' << to_string(x.kind) << ' ' << mc.is_border_point(v) << ' '
       << hex(mc.ignition_at_vertex(v)) << ' ' << hex(x.radius) << ' ' << hex(x.approx[0]) << ' '
       << hex(x.approx[1]) << ' ' << hex(x.approx[2]) << " |";
    for (std::uint32_t e : mc.vertex_edges(v)) os << ' ' << e;
    os << " |";
    for (std::uint32_t t : mc.vertex_triangles(v)) os << ' ' << t;
    os << " |";
    for (const LinkElement& el : mc.link_elements(v)) os << ' ' << (el.is_pole ? 'p' : 's') << el.id;
    os << '\n';
  }
  for (std::uint32_t e = 0; e < mc.edge_count(); ++e) {
    const ComplexEdge& x = mc.edge(e);
    os << "e " << x.v[0] << ' ' << x.v[1] << ' ' << to_string(x.stratum) << ' ' << hex(x.length) << ' '
       << static_cast<int>(x.rule) << ' ' << mc.edge_end_element(e, 0) << ' ' << mc.edge_end_element(e, 1) << " |";
    for (std::uint32_t t : mc.edge_triangles(e)) os << ' ' << t;
    os << '\n';
  }
  for (std::uint32_t t = 0; t < mc.triangle_count(); ++t) {
    const ComplexTriangle& x = mc.triangle(t);
    os << "t " << x.v[0] << ' ' << x.v[1] << ' ' << x.v[2] << ' ' << x.e[0] << ' ' << x.e[1] << ' ' << x.e[2] << ' '
       << x.sheet << ' ' << (&mc.triangle_frame(t) - frames.data()) << ' ' << mc.corner_element(t, 0) << ' '
       << mc.corner_element(t, 1) << ' ' << mc.corner_element(t, 2) << '\n';
  }
  for (const Sheet& s : mc.sheets()) {
    os << "s " << s.planar << ' ' << s.frame << " |";
    for (std::uint32_t t : s.triangles) os << ' ' << t;
    os << '\n';
  }
  for (const PlanarFrame& f : frames) {
    os << "f ";
    for (const ExactPoint3* p : {&f.origin, &f.e1, &f.e2, &f.normal}) put(os, *p), os << ' ';
    os << f.e1_norm2 << ' ' << f.e2_norm2 << '\n';
  }
  for (const Sector& s : mc.sectors()) {
    os << "c " << s.apex << ' ' << s.sheet << ' ' << s.closed << ' ' << s.ends[0] << ' ' << s.ends[1] << " |";
    for (std::uint32_t t : s.triangles) os << ' ' << t;
    os << '\n';
  }
  return os.str();
}

inline std::uint64_t fnv1a(const std::string& s) {
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char c : s) h = (h ^ c) * 1099511628211ull;
  return h;
}

// A height field over an n x n grid with rational heights drawn from a few values (so that
// coplanar neighbours, and whole planar patches, occur), split along random diagonals.
inline RawComplex random_height_field(std::uint32_t seed, int n) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> height(0, 3), denominator(1, 3), diagonal(0, 1);
  ComplexBuilder b("height-field-" + std::to_string(seed));
  std::vector<std::vector<std::uint32_t>> id(n + 1, std::vector<std::uint32_t>(n + 1));
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) id[i][j] = b.vertex({i, j, mpq_class(height(rng), 2 * denominator(rng) + 1)});
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      if (diagonal(rng)) b.quad(id[i][j], id[i + 1][j], id[i + 1][j + 1], id[i][j + 1]);
      else b.quad(id[i + 1][j], id[i + 1][j + 1], id[i][j + 1], id[i][j]);
    }
  return b.take();
}

// A book about the edge from the origin to a random small integer point: 3..7 pages whose
// third vertices are random points of a small half-integer grid (ties, opposite and
// coplanar pages, and pages in the same half-plane occur; points on the edge's line are
// skipped). Some draws overlap: both implementations must then refuse them alike.
inline RawComplex random_book(std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> coordinate(-3, 3), spine(-2, 2), pages(3, 7), denominator(1, 2);
  ComplexBuilder b("random-book-" + std::to_string(seed));
  const ExactPoint3 origin{0, 0, 0};
  ExactPoint3 d{0, 0, 0};
  while (is_zero(d)) d = {spine(rng), spine(rng), spine(rng)};
  const std::uint32_t a = b.vertex(origin), e = b.vertex(d);
  for (int k = pages(rng), j = 0; j < k; ++j) {
    const int q = denominator(rng);
    const ExactPoint3 p{mpq_class(coordinate(rng), q), mpq_class(coordinate(rng), q), mpq_class(coordinate(rng), q)};
    if (collinear(origin, d, p)) continue;
    b.triangle(a, e, b.vertex(p));
  }
  return b.take();
}

// A Loop-refined mesh whose coordinates are rounded down to the grid of step 1/(64 grid)
// and moved by a seeded random -1, 0 or +1 steps (small denominators: on the coarse grid
// coplanar neighbours occur, and degenerate or intersecting triangles, which both
// implementations must refuse alike).
inline RawComplex perturbed_mesh_complex(const TriangleMesh3& mesh, std::uint32_t seed, int grid) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> jitter(-1, 1);
  RawComplex raw = mesh_as_complex(mesh);
  raw.source = "perturbed-" + std::to_string(seed);
  for (ExactPoint3& p : raw.vertices)
    for (mpq_class* c : {&p.x, &p.y, &p.z}) {
      const mpq_class scaled = *c * (grid * 64);
      mpz_class n;
      mpz_fdiv_q(n.get_mpz_t(), scaled.get_num_mpz_t(), scaled.get_den_mpz_t());
      *c = mpq_class(n + jitter(rng), grid * 64);
      c->canonicalize();
    }
  return raw;
}

// The digest text, or the refusal message when construction (or validate()) throws.
inline std::string digest_text(const RawComplex& raw) {
  try {
    const MedialComplex mc(raw);
    mc.validate();
    return medial_complex_text(mc);
  } catch (const std::exception& e) {
    return std::string("refused: ") + e.what();
  }
}

// Named complexes, in a fixed order (names present in every version).
inline std::vector<std::pair<std::string, RawComplex>> digest_corpus(const std::string& data) {
  std::vector<std::pair<std::string, RawComplex>> out;
  for (const char* name : {"board-fin", "board-cylinder", "book:3", "book:5", "y-junction", "tetrahedron", "octahedron",
                           "double-cone", "tetrahedron-flap", "box:4:3:1"})
    out.emplace_back(name, synthetic_complex(name));
  for (int k : {2, 4, 7}) {
    BookOptions o;
    o.pages = k;
    o.widths.assign(k, 2);
    for (int j = 0; j < k; ++j) o.widths[j] = 1 + (j * 7 + k) % 4;
    out.emplace_back("book-widths-" + std::to_string(k), book(o));
  }
  for (const char* ma : {"box_4_3_1.ma", "box_7_4_3.ma"}) out.emplace_back(ma, read_ma(data + "/ma/" + ma));
  for (const char* ma : {"real/caffeine.ma", "real/pipe.ma", "real/joint.ma"}) out.emplace_back(ma, read_ma(data + "/ma/" + ma));
  for (const char* mesh : {"cube.off", "octahedron.off", "tripod.off", "cross.off"}) {
    out.emplace_back(std::string("refined-") + mesh,
                     mesh_as_complex(refined_mesh(read_triangle_mesh(data + "/meshes/" + mesh), 800)));
  }
  for (std::uint32_t seed = 1; seed <= 6; ++seed) out.emplace_back("height-field", random_height_field(seed, 6));
  for (std::uint32_t seed = 1; seed <= 40; ++seed) out.emplace_back("random-book", random_book(seed));
  const TriangleMesh3 cube = refined_mesh(read_triangle_mesh(data + "/meshes/cube.off"), 300);
  const TriangleMesh3 tripod = refined_mesh(read_triangle_mesh(data + "/meshes/tripod.off"), 300);
  for (std::uint32_t seed = 1; seed <= 4; ++seed)
    for (int grid : {1, 16}) {
      out.emplace_back("perturbed-cube-" + std::to_string(grid), perturbed_mesh_complex(cube, seed, grid));
      out.emplace_back("perturbed-tripod-" + std::to_string(grid), perturbed_mesh_complex(tripod, seed, grid));
    }
  return out;
}

}  // namespace grassfire::testing

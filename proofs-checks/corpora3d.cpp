// corpora3d.cpp -- the 3D corpora and their references (see corpora3d.h).
#include "corpora3d.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <random>
#include <set>

#include "burn3/burn3_reference.h"
#include "medial3/convex/convex_polyhedron_axis.h"
#include "complex3/complex_builder.h"
#include "complex3/synthetic_complexes.h"
#include "io/complex_ma.h"
#include "io/mesh_io.h"

namespace grassfire::checks {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double diagonal(const MedialComplex& mc) {
  Vec3d lo = mc.vertex(0).approx, hi = lo;
  for (const ComplexVertex& v : mc.vertices())
    for (int i = 0; i < 3; ++i) lo[i] = std::min(lo[i], v.approx[i]), hi[i] = std::max(hi[i], v.approx[i]);
  return std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
}

void add(Corpus3& c, const CheckContext& ctx, const std::string& name, const RawComplex& raw,
         BurningReference reference = {}) {
  MedialComplex mc(raw);
  mc.validate();
  const double h = diagonal(mc) / (ctx.quick() ? 24 : 48);
  c.instances.push_back({name, std::move(mc), std::move(reference), false, h});
}

// BT of a book at a point: its page is the one whose half-plane passes nearest.
BurningReference book_reference(const BookOptions& o) {
  std::vector<std::array<double, 2>> dirs;
  for (int j = 0; j < o.pages; ++j) {
    const auto d = rational_unit_direction(2 * M_PI * j / o.pages);
    dirs.push_back({d[0].get_d(), d[1].get_d()});
  }
  return [o, dirs](const MedialComplex&, const Vec3d& p, double) {
    const double u = std::hypot(p[0], p[1]);
    int page = 0;
    double best = std::numeric_limits<double>::infinity();
    for (int j = 0; u > 0 && j < o.pages; ++j) {
      const double off = std::hypot(p[0] - u * dirs[j][0], p[1] - u * dirs[j][1]);
      if (off < best) best = off, page = j;
    }
    return book_burning_time(o, page, u, p[2]);
  };
}

BurningReference box_reference(double a, double b, double c) {
  return [=](const MedialComplex&, const Vec3d& p, double) { return box_medial_axis_burning_time(a, b, c, p); };
}

// The box [-a, a] x [-b, b] x [-c, c] of a box axis read back from a file: its extent.
BurningReference box_reference_from_extent(const MedialComplex& mc) {
  double e[3] = {0, 0, 0};
  for (const ComplexVertex& v : mc.vertices())
    for (int i = 0; i < 3; ++i) e[i] = std::max(e[i], std::abs(v.approx[i]));
  return box_reference(e[0], e[1], e[2]);
}

RawComplex octahedron_with_flaps(std::mt19937& rng, int scale) {
  ComplexBuilder b("octahedron+flaps");
  const RawComplex oct = octahedron_surface();
  auto v = [&](const ExactPoint3& p) { return b.vertex(mpq_class(scale) * p); };
  for (const auto& t : oct.triangles) b.triangle(v(oct.vertices[t[0]]), v(oct.vertices[t[1]]), v(oct.vertices[t[2]]));
  std::bernoulli_distribution coin(0.4);
  std::set<std::pair<std::uint32_t, std::uint32_t>> seen;
  for (const auto& t : oct.triangles)
    for (int i = 0; i < 3; ++i) {  // a flap outside the edge t[i] t[i+1], in the plane of it and O
      const std::uint32_t a = std::min(t[i], t[(i + 1) % 3]), c = std::max(t[i], t[(i + 1) % 3]);
      if (!seen.insert({a, c}).second || !coin(rng)) continue;
      b.triangle(v(oct.vertices[a]), v(oct.vertices[c]), v(oct.vertices[a] + oct.vertices[c]));
    }
  for (const ExactPoint3& p : oct.vertices)
    if (coin(rng)) b.segment(v(p), v(mpq_class(2) * p));  // a hair
  return b.take();
}

Corpus3 synthetic(const CheckContext& ctx) {
  Corpus3 c{"synthetic: hand-built complexes", "closed forms (board and fin, books, Y)", {}};
  const BoardFinOptions bf{8, 1};
  add(c, ctx, "board-fin", board_fin(bf), [bf](const MedialComplex&, const Vec3d& p, double) {
    const double t = board_fin_burning_time(p);
    return t <= bf.extent ? t : kNaN;  // the closed form holds where BT <= E (synthetic_complexes.h)
  });
  for (int k = ctx.tiny() ? 3 : 2; k <= (ctx.tiny() ? 3 : ctx.quick() ? 4 : 6); ++k) {
    const BookOptions o{k, {}, 0, 1};
    add(c, ctx, "book:" + std::to_string(k), book(o), book_reference(o));
  }
  add(c, ctx, "y-junction", y_junction(1), book_reference(y_junction_options(1)));
  add(c, ctx, "tetrahedron-flap", tetrahedron_with_flap());
  if (ctx.tiny()) return c;
  add(c, ctx, "board-cylinder", board_cylinder({16, 3, 4, 2.0, 6}));
  add(c, ctx, "tetrahedron", tetrahedron_surface());
  add(c, ctx, "octahedron", octahedron_surface());
  add(c, ctx, "double-cone", pinched_double_cone(8));
  return c;
}

Corpus3 generated(const CheckContext& ctx) {
  Corpus3 c{"generated: seeded random books, box axes, octahedra with flaps, planar convex sheets",
            "closed forms (books, boxes); brute force min over the border of |xy| + f (planar sheets)", {}};
  std::mt19937 rng(2011);
  const int n = ctx.tiny() ? 1 : ctx.quick() ? 3 : 12;
  for (int i = 0; i < n; ++i) {
    std::uniform_int_distribution<int> pages(2, 6), width(1, 4), dim(1, 6);
    BookOptions o;
    o.pages = pages(rng);
    for (int j = 0; j < o.pages; ++j) o.widths.push_back(width(rng));
    o.cells_per_unit = 1;
    add(c, ctx, "random book " + std::to_string(i), book(o), book_reference(o));
    long d[3] = {dim(rng), dim(rng), dim(rng)};
    std::sort(d, d + 3, std::greater<long>());
    if (d[1] == d[2]) ++d[0], ++d[1];
    add(c, ctx, "random box " + std::to_string(i), box_medial_axis(d[0], d[1], d[2], 1 + i % 2),
        box_reference(d[0], d[1], d[2]));
    add(c, ctx, "octahedron+flaps " + std::to_string(i), octahedron_with_flaps(rng, 2));
  }
  for (std::uint32_t i = 0; i < (ctx.tiny() ? 1u : ctx.quick() ? 4u : 12u); ++i) {
    add(c, ctx, "planar sheet " + std::to_string(i), random_planar_fan(2011 + i));
    Instance3& in = c.instances.back();
    in.reference = [](const MedialComplex& mc, const Vec3d& p, double) { return planar_convex_sheet_burning_time(mc, p); };
    in.planar_convex_sheet = true;
  }
  return c;
}

std::vector<std::string> files_in(const std::string& dir, const std::string& ext) {
  std::vector<std::string> files;
  if (!std::filesystem::is_directory(dir)) return files;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.path().extension() == ext) files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

Corpus3 box_files(const CheckContext& ctx) {
  Corpus3 c{"generated (data/ma): box axes written by the project", "closed form (boxes)", {}};
  for (const std::string& f : files_in(ctx.data_dir + "/ma", ".ma")) {
    if (ctx.tiny() && !c.instances.empty()) break;
    add(c, ctx, std::filesystem::path(f).filename().string(), read_ma(f));
    c.instances.back().reference = box_reference_from_extent(c.instances.back().mc);
  }
  return c;
}

Corpus3 from_real_shapes(const CheckContext& ctx) {
  Corpus3 c{"generated from real shapes (data/ma/real): our builders' axes of CGAL meshes and balls", "none", {}};
  for (const std::string& f : files_in(ctx.data_dir + "/ma/real", ".ma")) {
    const std::string name = std::filesystem::path(f).filename().string();
    if (ctx.tiny() && name != "caffeine.ma" && name != "tripod.ma") continue;
    add(c, ctx, name, read_ma(f));
  }
  return c;
}

Corpus3 convex(const CheckContext& ctx) {
  Corpus3 c{"convex polyhedra: data/meshes cube and octahedron, seeded random cuts of the cube (exact builder)",
            "closed forms (cube sqrt2 R, octahedron sqrt(3/2) R)", {}};
  const double ratio[2] = {std::sqrt(2.0), std::sqrt(1.5)};
  int k = 0;
  for (const char* mesh : {"cube.off", "octahedron.off"}) {
    const std::string path = ctx.data_dir + "/meshes/" + mesh;
    const double q = ratio[k++];
    add(c, ctx, mesh, convex_polyhedron_axis(convex_polyhedron_from_mesh(read_triangle_mesh(path))).complex,
        [q](const MedialComplex&, const Vec3d&, double radius) { return q * radius; });
    if (ctx.tiny()) break;
  }
  for (std::uint32_t seed = 0; seed < (ctx.tiny() ? 1u : ctx.quick() ? 4u : 16u); ++seed) {
    const ConvexPolyhedron p = random_cut_cube(seed);
    add(c, ctx, p.source, convex_polyhedron_axis(p).complex);
  }
  return c;
}

}  // namespace

std::vector<Corpus3> burning_corpora(const CheckContext& ctx) {
  return {synthetic(ctx), generated(ctx), box_files(ctx), from_real_shapes(ctx), convex(ctx)};
}

}  // namespace grassfire::checks

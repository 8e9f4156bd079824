// mesh_samples.cpp -- see mesh_samples.h.
#include "medial3/mesh/mesh_samples.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <unordered_map>

namespace grassfire {

namespace {

using P3 = std::array<double, 3>;

double distance(const P3& a, const P3& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

P3 lerp(const P3& a, const P3& b, double t) {
  return {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])};
}

long parts(double length, double h) { return std::max(1L, static_cast<long>(std::ceil(length / h))); }

using L3 = std::array<std::int64_t, 3>;

struct LatticeHash {
  std::size_t operator()(const L3& p) const {
    std::size_t h = 1469598103934665603ull;
    for (std::int64_t x : p) h = (h ^ static_cast<std::size_t>(x)) * 1099511628211ull;
    return h;
  }
};

// Rounds points to the lattice and keeps the first of equal ones; add() returns the id.
class Collector {
 public:
  Collector(std::vector<L3>* out, double grid) : out_(out), grid_(grid) {}
  std::uint32_t add(const P3& p) {
    const L3 n{std::llround(p[0] / grid_), std::llround(p[1] / grid_), std::llround(p[2] / grid_)};
    auto [it, fresh] = ids_.emplace(n, static_cast<std::uint32_t>(out_->size()));
    if (fresh) out_->push_back(n);
    return it->second;
  }

 private:
  std::vector<L3>* out_;
  double grid_;
  std::unordered_map<L3, std::uint32_t, LatticeHash> ids_;
};

// Rows parallel to the longest edge ab, between the edges ac and bc; inner points only.
void sample_interior(const P3& a, const P3& b, const P3& c, double h, Collector& in, std::vector<std::uint32_t>* ids) {
  const double ab = distance(a, b);
  if (ab == 0) return;
  const P3 foot = lerp(a, b, std::clamp(((c[0] - a[0]) * (b[0] - a[0]) + (c[1] - a[1]) * (b[1] - a[1]) +
                                         (c[2] - a[2]) * (b[2] - a[2])) / (ab * ab), 0.0, 1.0));
  const long rows = parts(distance(c, foot), h);
  for (long k = 1; k < rows; ++k) {
    const double t = static_cast<double>(k) / static_cast<double>(rows);
    const P3 p = lerp(a, c, t), q = lerp(b, c, t);
    const long n = parts(distance(p, q), h);
    for (long i = 1; i < n; ++i) ids->push_back(in.add(lerp(p, q, static_cast<double>(i) / static_cast<double>(n))));
  }
}

// The corners (a, b, d) of a triangle with ab its longest edge, a < b: ties between edges
// and the order within the edge broken by comparing the points lexicographically, so that
// neither the labels nor the corner order of the mesh changes the interior samples.
std::array<P3, 3> longest_edge_first(const P3& x, const P3& y, const P3& z) {
  std::array<std::array<P3, 3>, 3> candidates = {{{std::min(x, y), std::max(x, y), z},
                                                  {std::min(y, z), std::max(y, z), x},
                                                  {std::min(z, x), std::max(z, x), y}}};
  const auto longer = [](const std::array<P3, 3>& u, const std::array<P3, 3>& v) {
    const double lu = distance(u[0], u[1]), lv = distance(v[0], v[1]);
    return lu != lv ? lu > lv : u < v;
  };
  return *std::min_element(candidates.begin(), candidates.end(), longer);
}

// Sample ids in lexicographic order of the lattice points: everything built on the samples
// (the triangulation's insertion order, cell and face ids, the order of the pruning) is
// then a function of the sample set alone, not of the mesh's labels.
void sort_samples(SurfaceSamples* s) {
  std::vector<std::uint32_t> order(s->lattice.size());
  for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::uint32_t i, std::uint32_t j) { return s->lattice[i] < s->lattice[j]; });
  std::vector<std::uint32_t> rank(order.size());
  std::vector<L3> sorted(order.size());
  for (std::uint32_t r = 0; r < order.size(); ++r) {
    rank[order[r]] = r;
    sorted[r] = s->lattice[order[r]];
  }
  s->lattice = std::move(sorted);
  for (std::uint32_t& id : s->on_triangle) id = rank[id];
}

std::uint64_t edge_key(std::uint32_t a, std::uint32_t b) {
  return (static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b);
}

}  // namespace

double mean_edge_length(const TriangleMesh3& mesh) {
  double sum = 0;
  std::size_t n = 0;
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      sum += distance(mesh.vertices[t[k]], mesh.vertices[t[(k + 1) % 3]]);  // each edge twice in a closed mesh
      ++n;
    }
  return n == 0 ? 0 : sum / static_cast<double>(n);
}

std::array<double, 3> SurfaceSamples::point(std::size_t i) const {
  return {grid * static_cast<double>(lattice[i][0]), grid * static_cast<double>(lattice[i][1]),
          grid * static_cast<double>(lattice[i][2])};
}

double sample_grid(const TriangleMesh3& mesh) {
  double extent = 0, largest = 0;
  for (int k = 0; k < 3; ++k) {
    double lo = INFINITY, hi = -INFINITY;
    for (const P3& v : mesh.vertices) {
      lo = std::min(lo, v[k]);
      hi = std::max(hi, v[k]);
    }
    extent = std::max(extent, hi - lo);
    largest = std::max({largest, std::fabs(lo), std::fabs(hi)});
  }
  if (!(extent > 0)) throw std::invalid_argument(mesh.source + ": the mesh has no extent");
  const double g = std::ldexp(1.0, std::ilogb(extent) + 1 - 26);  // extent < 2^(ilogb + 1)
  if (largest / g >= 0x1p52) throw std::invalid_argument(mesh.source + ": the mesh lies too far from the origin for its size");
  return g;
}

SurfaceSamples sample_surface(const TriangleMesh3& mesh, double spacing) {
  return sample_surface(mesh, std::vector<double>(mesh.triangles.size(), spacing));
}

SurfaceSamples sample_surface(const TriangleMesh3& mesh, const std::vector<double>& spacing) {
  if (spacing.size() != mesh.triangles.size()) throw std::invalid_argument(mesh.source + ": one spacing per triangle is needed");
  for (double h : spacing)
    if (!(h > 0) || !std::isfinite(h)) throw std::invalid_argument(mesh.source + ": sample spacing must be positive");
  SurfaceSamples out;
  out.grid = sample_grid(mesh);
  Collector c(&out.lattice, out.grid);
  std::vector<std::uint32_t> vertex(mesh.vertices.size());
  for (std::uint32_t v = 0; v < mesh.vertices.size(); ++v) vertex[v] = c.add(mesh.vertices[v]);
  std::unordered_map<std::uint64_t, double> edge_spacing;
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      auto [it, fresh] = edge_spacing.emplace(edge_key(mesh.triangles[t][k], mesh.triangles[t][(k + 1) % 3]), spacing[t]);
      if (!fresh) it->second = std::min(it->second, spacing[t]);
    }
  std::vector<std::pair<std::uint64_t, double>> edges(edge_spacing.begin(), edge_spacing.end());
  std::sort(edges.begin(), edges.end());  // sample ids independent of the hash order
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> edge_samples;
  for (const auto& [key, h] : edges) {
    // From the lexicographically smaller end: the points do not depend on the labels.
    const P3& p = std::min(mesh.vertices[key >> 32], mesh.vertices[key & 0xffffffffu]);
    const P3& q = std::max(mesh.vertices[key >> 32], mesh.vertices[key & 0xffffffffu]);
    const long n = parts(distance(p, q), h);
    std::vector<std::uint32_t>& ids = edge_samples[key];
    for (long i = 1; i < n; ++i) ids.push_back(c.add(lerp(p, q, static_cast<double>(i) / static_cast<double>(n))));
  }
  out.offset.push_back(0);
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    for (int k = 0; k < 3; ++k) {
      out.on_triangle.push_back(vertex[tri[k]]);
      const auto& e = edge_samples.at(edge_key(tri[k], tri[(k + 1) % 3]));
      out.on_triangle.insert(out.on_triangle.end(), e.begin(), e.end());
    }
    const auto [a, b, d] = longest_edge_first(mesh.vertices[tri[0]], mesh.vertices[tri[1]], mesh.vertices[tri[2]]);
    sample_interior(a, b, d, spacing[t], c, &out.on_triangle);
    out.offset.push_back(static_cast<std::uint32_t>(out.on_triangle.size()));
  }
  sort_samples(&out);
  return out;
}

}  // namespace grassfire

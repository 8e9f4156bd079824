// polygon_axis_congruence.cpp -- local congruence classes of an exact polygon axis's atoms
// (see polygon_axis_symmetry.h): canonical keys of the site configurations behind each
// node's R and each edge's length, under the lattice isometries X -> A X + t.
#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>
#include <vector>

#include "geometry2/predicates2.h"
#include "medial2/polygon/polygon_axis_symmetry.h"

namespace grassfire {

namespace {

// The eight signed permutation matrices (the identity first).
constexpr int kLinear[8][4] = {{1, 0, 0, 1},   {-1, 0, 0, 1}, {1, 0, 0, -1}, {-1, 0, 0, -1},
                               {0, 1, 1, 0},   {0, -1, -1, 0}, {0, -1, 1, 0}, {0, 1, -1, 0}};

// A point site (kind 0: a = x, y) or a segment site's line, oriented with the interior on
// its left (kind 1: a = the primitive direction dx, dy and k = cross(d, p) for a point p
// of it; p is kept for translating). Values depend on lines only, not on where a segment
// ends, so two runs of one line are one object.
struct Obj {
  std::int64_t kind = 0;
  std::array<std::int64_t, 2> a{};
  __int128 k = 0;
  std::int64_t px = 0, py = 0, qx = 0, qy = 0;  // the segment's ends (a point: px, py)
  bool operator<(const Obj& o) const {
    if (kind != o.kind) return kind < o.kind;
    if (a != o.a) return a < o.a;
    return k < o.k;
  }
};

struct Image {
  std::int64_t code = 0;  // kind and root
  int count = 0;
  std::array<Obj, 3> obj;
};

void apply(const int* a, std::int64_t x, std::int64_t y, std::int64_t* out) {
  out[0] = a[0] * x + a[1] * y;
  out[1] = a[2] * x + a[3] * y;
}

std::int64_t gcd64(std::int64_t a, std::int64_t b) {
  a = a < 0 ? -a : a;
  b = b < 0 ? -b : b;
  while (b != 0) {
    const std::int64_t t = a % b;
    a = b;
    b = t;
  }
  return a;
}

// Every segment's primitive direction (its direction divided by the gcd of its
// components), computed once: transform_site runs 8 times per site and circle, and a
// signed permutation A maps the primitive direction of d to that of A d (no divisions).
using Directions = std::vector<std::array<std::int64_t, 2>>;
Directions primitive_directions(const PolygonSites& s) {
  Directions out(s.vertex_count());
  for (std::uint32_t i = 0; i < s.vertex_count(); ++i) {
    const Point2 p = s.vertex[i], q = s.vertex[s.next[i]];
    const std::int64_t dx = static_cast<std::int64_t>(q.x) - static_cast<std::int64_t>(p.x);
    const std::int64_t dy = static_cast<std::int64_t>(q.y) - static_cast<std::int64_t>(p.y);
    const std::int64_t g = gcd64(dx, dy);
    out[i] = {dx / g, dy / g};
  }
  return out;
}

Obj transform_site(const PolygonSites& s, const Directions& dirs, std::uint32_t site, const int* a) {
  Obj o;
  auto at = [&](std::uint32_t v, std::int64_t* out) {
    apply(a, static_cast<std::int64_t>(s.vertex[v].x), static_cast<std::int64_t>(s.vertex[v].y), out);
  };
  std::int64_t p[2], q[2];
  if (s.is_point(site)) {
    at(site, p);
    o.a = {p[0], p[1]};
    o.px = p[0], o.py = p[1];
    return o;
  }
  o.kind = 1;
  // A reflection maps the segment start -> end to one with the interior on its right:
  // the mapped polygon edge runs end -> start (direction -A d).
  const bool reverses = a[0] * a[3] - a[1] * a[2] < 0;
  at(reverses ? s.seg_end(site) : s.seg_start(site), p);
  at(reverses ? s.seg_start(site) : s.seg_end(site), q);
  const std::array<std::int64_t, 2>& d = dirs[s.seg_start(site)];
  std::int64_t m[2];
  apply(a, d[0], d[1], m);
  o.a = reverses ? std::array<std::int64_t, 2>{-m[0], -m[1]} : std::array<std::int64_t, 2>{m[0], m[1]};
  o.k = static_cast<__int128>(o.a[0]) * p[1] - static_cast<__int128>(o.a[1]) * p[0];
  o.px = p[0], o.py = p[1], o.qx = q[0], o.qy = q[1];
  return o;
}

// The circle's configuration under A, roles mapped as in polygon_axis_symmetry.h and
// then put in the order its formula is symmetric under (key_of there, by coordinates).
// When at most one circle satisfies c's conditions (voronoi_circle.h), the root is no
// part of its value (the two roots coincide), so it is dropped and the symmetric roles
// are sorted.
Image transform_circle(const PolygonSites& s, const Directions& dirs, const VoronoiCircle& c,
                       const int* a, bool unique) {
  Image im;
  im.count = c.kind == CircleKind::Apex ? 1 : 3;
  for (int i = 0; i < im.count; ++i) im.obj[i] = transform_site(s, dirs, c.sites[i], a);
  if (a[0] * a[3] - a[1] * a[2] < 0) reflect_roles(c.kind, im.obj);
  const int root = canonical_roles(c.kind, c.root, im.obj, unique);
  im.code = static_cast<std::int64_t>(c.kind) * 4 + root + 1;
  return im;
}

// A flat key: objects translated so that the lexicographically smallest point is 0. The
// builder points at the images' objects (no copies: it runs 16 times per edge).
struct KeyBuilder {
  std::array<const Obj*, 8> obj;
  std::array<std::int64_t, 4> codes;
  int objects = 0, ncodes = 0;
  void add(const Image& im) {
    codes[ncodes++] = im.code * 4 + im.count;
    for (int i = 0; i < im.count; ++i) obj[objects++] = &im.obj[i];
  }
  // The key: codes, then every object's kind and coordinates (at most 4 + 8 * 5 values;
  // the entries past `size` are never read, so they are left uninitialised).
  struct Key {
    std::array<std::int64_t, 48> v;
    int size = 0;
    bool operator<(const Key& o) const {
      return std::lexicographical_compare(v.begin(), v.begin() + size, o.v.begin(), o.v.begin() + o.size);
    }
    bool operator==(const Key& o) const {
      return size == o.size && std::equal(v.begin(), v.begin() + size, o.v.begin());
    }
  };
  // The origin of the key: the least point site (the least segment end when there is no
  // point site) of the objects.
  static void origin(const Obj* const* objs, int count, std::int64_t& mx, std::int64_t& my) {
    mx = 0, my = 0;
    bool found = false;
    auto consider = [&](std::int64_t x, std::int64_t y) {
      if (!found || x < mx || (x == mx && y < my)) mx = x, my = y;
      found = true;
    };
    bool has_point = false;
    for (int i = 0; i < count; ++i) has_point = has_point || objs[i]->kind == 0;
    for (int i = 0; i < count; ++i) {
      if (objs[i]->kind == 0) {
        consider(objs[i]->px, objs[i]->py);
      } else if (!has_point) {
        consider(objs[i]->px, objs[i]->py);
        consider(objs[i]->qx, objs[i]->qy);
      }
    }
  }
  // One object's kind and coordinates about the origin m; returns the values written.
  static int encode(const Obj& o, std::int64_t mx, std::int64_t my, std::int64_t* out) {
    out[0] = o.kind;
    if (o.kind == 0) {
      out[1] = o.a[0] - mx;
      out[2] = o.a[1] - my;
      return 3;
    }
    // cross(d, p - m) = k - cross(d, m)
    const __int128 c = o.k - (static_cast<__int128>(o.a[0]) * my - static_cast<__int128>(o.a[1]) * mx);
    out[1] = o.a[0];
    out[2] = o.a[1];
    out[3] = static_cast<std::int64_t>(c >> 64);
    out[4] = static_cast<std::int64_t>(static_cast<std::uint64_t>(c));
    return 5;
  }
  // Translated so that origin() is the origin.
  void build(Key& k) const {
    std::int64_t mx = 0, my = 0;
    origin(obj.data(), objects, mx, my);
    k.size = 0;
    for (int i = 0; i < ncodes; ++i) k.v[k.size++] = codes[i];
    for (int i = 0; i < objects; ++i) k.size += encode(*obj[i], mx, my, &k.v[k.size]);
  }
};

// The least of several keys, each built in place into next() (no copies).
class LeastKey {
 public:
  KeyBuilder::Key& next() { return keys_[spare_]; }
  // Offers the key just built into next().
  void offer() {
    if (best_ < 0 || keys_[spare_] < keys_[best_]) {
      best_ = spare_;
      spare_ ^= 1;
    }
  }
  const KeyBuilder::Key& best() const { return keys_[best_]; }

 private:
  KeyBuilder::Key keys_[2];
  int best_ = -1, spare_ = 0;
};

struct KeyHash {
  std::size_t operator()(const KeyBuilder::Key& k) const {
    std::uint64_t h = 1469598103934665603ull;
    for (int i = 0; i < k.size; ++i) h = (h ^ static_cast<std::uint64_t>(k.v[i])) * 1099511628211ull;
    return static_cast<std::size_t>(h ^ (h >> 29));
  }
};

bool is_integer_frame(const PolygonSites& s) {
  for (const Point2& p : s.vertex)
    if (!(std::fabs(p.x) <= 2147483647.0 && p.x == std::floor(p.x) && std::fabs(p.y) <= 2147483647.0 &&
          p.y == std::floor(p.y)))
      return false;
  return true;
}

template <class F>
void for_each_circle(const AxisNodeData& d, F&& f) {
  f(d.circle);
  for (const VoronoiCircle& c : d.aliases) f(c);
}

// Atoms whose enclosure overlaps that of an atom of another class (only those can be
// equal to an atom they are not yet joined with); the others keep their classes. The
// scan looks at most kWindow neighbours in the order of lower bounds and marks an atom
// as a candidate when the window is too crowded to tell.
template <class Get>
std::vector<bool> candidates(std::uint32_t count, Get enclosure, UnionFind& uf) {
  constexpr std::uint32_t kWindow = 64;
  std::vector<std::uint32_t> order(count);
  for (std::uint32_t i = 0; i < count; ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    return enclosure(a).lo < enclosure(b).lo;
  });
  std::vector<bool> out(count, false);
  for (std::uint32_t k = 0; k < count; ++k) {
    const Interval& x = enclosure(order[k]);
    std::uint32_t j = k + 1;
    for (; j < count && j <= k + kWindow && enclosure(order[j]).lo <= x.hi; ++j)
      if (uf.find(order[j]) != uf.find(order[k])) out[order[j]] = out[order[k]] = true;
    if (j == k + kWindow + 1 && j < count && enclosure(order[j]).lo <= x.hi) out[order[k]] = true;
  }
  return out;
}

}  // namespace

std::vector<std::uint32_t> conditions_of_sites(const PolygonSites& s) {
  const std::uint32_t n = s.vertex_count();
  std::vector<std::uint32_t> out(2 * n);
  auto straight = [&](std::uint32_t v) {
    const Point2 a = s.vertex[s.prev[v]], b = s.vertex[v], c = s.vertex[s.next[v]];
    return orientation(a, b, c) == 0 && (b.x - a.x) * (c.x - b.x) + (b.y - a.y) * (c.y - b.y) > 0;
  };
  for (std::uint32_t i = 0; i < n; ++i) {
    out[i] = i;
    std::uint32_t start = i;
    for (std::uint32_t steps = 0; steps < n && straight(start); ++steps) start = s.prev[start];
    out[n + i] = n + start;
  }
  return out;
}

std::vector<JoinedEdges> joinable_edges(const PolygonSites& s, const std::vector<AxisNodeData>& nodes,
                                        const std::vector<AxisEdgeData>& edges) {
  std::vector<JoinedEdges> out;
  if (!is_integer_frame(s)) return out;
  const std::vector<std::uint32_t> cond = conditions_of_sites(s);
  std::vector<std::uint32_t> degree(nodes.size(), 0), first(nodes.size(), 0), second(nodes.size(), 0);
  for (std::uint32_t e = 0; e < edges.size(); ++e)
    for (std::uint32_t v : {edges[e].u, edges[e].v}) {
      if (degree[v] == 0) first[v] = e;
      if (degree[v] == 1) second[v] = e;
      ++degree[v];
    }
  auto pair_of = [&](const AxisEdgeData& d) {
    const std::uint32_t a = cond[d.site_a], b = cond[d.site_b];
    return std::make_pair(std::min(a, b), std::max(a, b));
  };
  for (std::uint32_t v = 0; v < nodes.size(); ++v) {
    if (degree[v] != 2 || nodes[v].circle.kind == CircleKind::Apex) continue;
    const AxisEdgeData &a = edges[first[v]], &b = edges[second[v]];
    if (a.parabolic != b.parabolic || pair_of(a) != pair_of(b) || a.u == a.v || b.u == b.v) continue;
    // Both far ends differ from v and from each other: a path, not a loop.
    const std::uint32_t fa = a.u == v ? a.v : a.u, fb = b.u == v ? b.v : b.u;
    if (fa == fb) continue;
    out.push_back({first[v], second[v], v});
  }
  return out;
}

void unite_congruent_atoms(const PolygonSites& s, const std::vector<AxisNodeData>& nodes,
                           const std::vector<AxisEdgeData>& edges, const std::vector<JoinedEdges>& joined,
                           UnionFind& node_uf, UnionFind& edge_uf) {
  if (!is_integer_frame(s)) return;
  const Directions dirs = primitive_directions(s);
  const auto n = static_cast<std::uint32_t>(nodes.size());
  const auto m = static_cast<std::uint32_t>(edges.size());
  // Every apex has R = 0.
  std::uint32_t first_apex = n;
  for (std::uint32_t i = 0; i < n; ++i)
    if (nodes[i].circle.kind == CircleKind::Apex) {
      if (first_apex == n) first_apex = i;
      node_uf.unite(i, first_apex);
    }
  // The eight images of a node's circles, in a direct-mapped cache of kSlots nodes: kept
  // for every node they cost ~2 KiB each (350 MB at 10^5 segments, and the page faults
  // and cache misses made this stage superlinear); nodes of nearby edges share slots.
  constexpr std::uint32_t kSlots = 4096;
  std::vector<std::vector<Image>> images(std::min(n, kSlots));
  std::vector<std::uint32_t> image_owner(images.size(), n);
  auto slot_of = [&](std::uint32_t i) { return i % kSlots; };
  auto images_of = [&](std::uint32_t i) -> const std::vector<Image>& {
    std::vector<Image>& out = images[slot_of(i)];
    if (image_owner[slot_of(i)] == i) return out;
    image_owner[slot_of(i)] = i;
    out.clear();
    std::array<bool, 8> unique{};
    std::size_t count = 0;
    for_each_circle(nodes[i], [&](const VoronoiCircle& c) {
      if (count < unique.size()) unique[count] = at_most_one_circle(s, c);
      ++count;
    });
    out.reserve(8 * count);
    for (const auto& a : kLinear) {
      std::size_t j = 0;
      for_each_circle(nodes[i], [&](const VoronoiCircle& c) {
        out.push_back(transform_circle(s, dirs, c, a, j < unique.size() && unique[j]));
        ++j;
      });
    }
    return out;
  };
  const std::vector<bool> node_candidates = candidates(n, [&](std::uint32_t i) -> const Interval& { return nodes[i].radius; }, node_uf);
  // Edges, then the joined pairs as edges from the first's far end to the second's.
  const auto total = static_cast<std::uint32_t>(m + joined.size());
  std::vector<AxisEdgeData> items(edges);
  for (const JoinedEdges& j : joined) {
    AxisEdgeData d = edges[j.first];
    d.u = d.u == j.middle ? d.v : d.u;
    d.v = edges[j.second].u == j.middle ? edges[j.second].v : edges[j.second].u;
    d.length = edges[j.first].length + edges[j.second].length;
    items.push_back(d);
  }
  const std::vector<bool> edge_candidates =
      candidates(total, [&](std::uint32_t e) -> const Interval& { return items[e].length; }, edge_uf);
  // Nodes in increasing order, interleaved with the edges: before an edge, every node up to
  // its larger end, so that both ends' images are still cached for the edge (the node and
  // the edge passes, each in its own order, unite exactly as one after the other would).
  std::unordered_map<KeyBuilder::Key, std::uint32_t, KeyHash> seen, seen_edges;
  std::uint32_t next_node = 0;
  auto nodes_until = [&](std::uint32_t end) {
    for (; next_node < end; ++next_node) {
      const std::uint32_t i = next_node;
      if (!node_candidates[i] || nodes[i].circle.kind == CircleKind::Apex) continue;
      LeastKey best;
      for (const Image& im : images_of(i)) {
        KeyBuilder k;
        k.add(im);
        k.build(best.next());
        best.offer();
      }
      const auto [it, fresh] = seen.emplace(best.best(), i);
      if (!fresh) node_uf.unite(i, it->second);
    }
  };
  for (std::uint32_t e = 0; e < total; ++e) {
    if (!edge_candidates[e]) continue;
    const AxisEdgeData& d = items[e];
    nodes_until(std::max(d.u, d.v) + 1);
    LeastKey best;
    // images_of(i) holds, for each of the eight maps in turn, one image per circle; u's
    // are copied when v's would evict them from the shared slot.
    std::vector<Image> u_copy;
    const std::vector<Image>* u_images = &images_of(d.u);
    if (slot_of(d.u) == slot_of(d.v) && d.u != d.v) {
      u_copy = *u_images;
      u_images = &u_copy;
    }
    const std::vector<Image>& iu = *u_images;
    const std::vector<Image>& iv = images_of(d.v);
    const std::size_t cu = iu.size() / 8, cv = iv.size() / 8;
    for (int a = 0; a < 8; ++a) {
      Obj focus, line;
      if (d.parabolic) {
        focus = transform_site(s, dirs, s.is_point(d.site_a) ? d.site_a : d.site_b, kLinear[a]);
        line = transform_site(s, dirs, s.is_point(d.site_a) ? d.site_b : d.site_a, kLinear[a]);
      }
      if (cu == 1 && cv == 1) {
        // One circle at each end: both orders have the same objects, so one origin and one
        // encoding of each object serve the two keys (the values build() would write).
        const Image &A = iu[a], &B = iv[a];
        std::array<const Obj*, 8> all;
        int count = 0;
        for (int i = 0; i < A.count; ++i) all[count++] = &A.obj[i];
        for (int i = 0; i < B.count; ++i) all[count++] = &B.obj[i];
        if (d.parabolic) {
          all[count++] = &focus;
          all[count++] = &line;
        }
        std::int64_t mx = 0, my = 0;
        KeyBuilder::origin(all.data(), count, mx, my);
        std::array<std::int64_t, 40> ea, eb, ef;
        int la = 0, lb = 0, lf = 0;
        for (int i = 0; i < A.count; ++i) la += KeyBuilder::encode(A.obj[i], mx, my, &ea[la]);
        for (int i = 0; i < B.count; ++i) lb += KeyBuilder::encode(B.obj[i], mx, my, &eb[lb]);
        if (d.parabolic) {
          lf += KeyBuilder::encode(focus, mx, my, &ef[lf]);
          lf += KeyBuilder::encode(line, mx, my, &ef[lf]);
        }
        const std::int64_t ca = A.code * 4 + A.count, cb = B.code * 4 + B.count;
        for (int order = 0; order < 2; ++order) {
          KeyBuilder::Key& key = best.next();
          std::int64_t* v = key.v.data();
          int n = 0;
          v[n++] = d.parabolic;
          v[n++] = order ? cb : ca;
          v[n++] = order ? ca : cb;
          const std::int64_t* first = order ? eb.data() : ea.data();
          const std::int64_t* second = order ? ea.data() : eb.data();
          const int lfirst = order ? lb : la, lsecond = order ? la : lb;
          for (int i = 0; i < lfirst; ++i) v[n++] = first[i];
          for (int i = 0; i < lsecond; ++i) v[n++] = second[i];
          for (int i = 0; i < lf; ++i) v[n++] = ef[i];
          key.size = n;
          best.offer();
        }
        continue;
      }
      for (int order = 0; order < 2; ++order)
        for (std::size_t x = 0; x < cu; ++x)
          for (std::size_t y = 0; y < cv; ++y) {
            KeyBuilder k;
            k.codes[k.ncodes++] = d.parabolic;
            k.add(order ? iv[a * cv + y] : iu[a * cu + x]);
            k.add(order ? iu[a * cu + x] : iv[a * cv + y]);
            if (d.parabolic) {
              k.obj[k.objects++] = &focus;
              k.obj[k.objects++] = &line;
            }
            k.build(best.next());
            best.offer();
          }
    }
    const auto [it, fresh] = seen_edges.emplace(best.best(), e);
    if (!fresh) edge_uf.unite(e, it->second);
  }
  nodes_until(n);
}

}  // namespace grassfire

// image_shape.cpp -- see image_shape.h.
//
// Boundary edges are the unit sides between a foreground pixel and a background pixel
// (outside the image is background), directed with the foreground on the left; at every
// lattice point one edge leaves per edge that arrives, two at a saddle. Tracing follows
// one edge after another; at a saddle it turns left (around the foreground pixel: 4-
// connectivity) or right (around the background pixel: 8-connectivity). Coordinates are
// kept doubled (integers) until the end, so that the half-pixel points are exact.
#include "shapes/image_shape.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <functional>
#include <numeric>

#include "shapes/validate_shape.h"

namespace grassfire {

namespace {

using P2 = std::array<std::int64_t, 2>;  // doubled coordinates
constexpr std::array<P2, 4> kDir = {{{1, 0}, {0, 1}, {-1, 0}, {0, -1}}};  // +X, +Y, -X, -Y

struct Mask {
  std::uint32_t width = 0, height = 0;
  std::vector<bool> on;
  bool at(std::int64_t x, std::int64_t y) const {  // image coordinates; outside is background
    return x >= 0 && y >= 0 && x < width && y < height && on[std::size_t(y) * width + std::size_t(x)];
  }
};

std::int64_t cross(const P2& a, const P2& b) { return a[0] * b[1] - a[1] * b[0]; }

// Components of the foreground: a label per pixel (-1 for background) and their sizes.
std::vector<std::int64_t> label_components(const Mask& m, bool eight, std::vector<std::size_t>& sizes) {
  std::vector<std::int64_t> label(m.on.size(), -1);
  std::vector<std::size_t> stack;
  for (std::size_t start = 0; start < m.on.size(); ++start) {
    if (!m.on[start] || label[start] >= 0) continue;
    const std::int64_t id = static_cast<std::int64_t>(sizes.size());
    sizes.push_back(0);
    label[start] = id;
    stack.assign(1, start);
    while (!stack.empty()) {
      const std::size_t p = stack.back();
      stack.pop_back();
      ++sizes.back();
      const std::int64_t x = p % m.width, y = p / m.width;
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        for (std::int64_t dx = -1; dx <= 1; ++dx) {
          if ((dx == 0 && dy == 0) || (!eight && dx != 0 && dy != 0) || !m.at(x + dx, y + dy)) continue;
          const std::size_t q = std::size_t(y + dy) * m.width + std::size_t(x + dx);
          if (label[q] < 0) label[q] = id, stack.push_back(q);
        }
    }
  }
  return label;
}

std::string describe_sizes(std::vector<std::size_t> sizes) {
  std::sort(sizes.rbegin(), sizes.rend());
  std::string s;
  for (std::size_t i = 0; i < sizes.size() && i < 5; ++i)
    s += (i == 0 ? "" : i + 1 == sizes.size() ? " and " : ", ") + std::to_string(sizes[i]);
  if (sizes.size() > 5) s += ", ...";
  return s + " pixels";
}

// The one component the shape is made of: the only one, or the largest when allowed.
Mask single_component(const Mask& m, const ImageShapeOptions& o, const std::string& source) {
  std::vector<std::size_t> sizes;
  const std::vector<std::int64_t> label = label_components(m, o.connectivity == PixelConnectivity::Eight, sizes);
  if (sizes.empty()) throw ImageShapeError(source + ": the image has no foreground pixel (see --foreground)");
  if (sizes.size() > 1 && !o.largest)
    throw ImageShapeError(source + ": the foreground has " + std::to_string(sizes.size()) + " components (" +
                          (o.connectivity == PixelConnectivity::Eight ? "8" : "4") + "-connected) of " +
                          describe_sizes(sizes) + "; a shape is one component: --largest keeps the largest");
  const std::int64_t keep = std::max_element(sizes.begin(), sizes.end()) - sizes.begin();
  Mask out = m;
  for (std::size_t i = 0; i < out.on.size(); ++i) out.on[i] = label[i] == keep;
  return out;
}

struct BoundaryEdges {
  std::uint32_t columns = 0;  // lattice points per row: width + 1
  std::vector<P2> start;      // lattice point (undoubled)
  std::vector<int> dir;       // index into kDir
  std::vector<std::array<std::int64_t, 2>> leaving;  // per lattice point: up to two edges, -1 for none
  std::int64_t point_id(const P2& p) const { return p[1] * columns + p[0]; }
};

void add_edge(BoundaryEdges& b, P2 from, int dir) {
  std::array<std::int64_t, 2>& slot = b.leaving[b.point_id(from)];
  slot[slot[0] < 0 ? 0 : 1] = static_cast<std::int64_t>(b.start.size());
  b.start.push_back(from);
  b.dir.push_back(dir);
}

// Pixel (x, row) is [x, x + 1] x [Y, Y + 1] with Y = H - row - 1; each side facing the
// background is an edge with the pixel on its left.
BoundaryEdges boundary_edges(const Mask& m) {
  BoundaryEdges b;
  b.columns = m.width + 1;
  b.leaving.assign(std::size_t(m.width + 1) * (m.height + 1), {-1, -1});
  for (std::int64_t row = 0; row < m.height; ++row)
    for (std::int64_t x = 0; x < m.width; ++x) {
      if (!m.at(x, row)) continue;
      const std::int64_t y = m.height - row - 1;
      if (!m.at(x, row + 1)) add_edge(b, {x, y}, 0);          // bottom side, going +X
      if (!m.at(x + 1, row)) add_edge(b, {x + 1, y}, 1);      // right side, going +Y
      if (!m.at(x, row - 1)) add_edge(b, {x + 1, y + 1}, 2);  // top side, going -X
      if (!m.at(x - 1, row)) add_edge(b, {x, y + 1}, 3);      // left side, going -Y
    }
  return b;
}

// The edge that continues edge e: the only one leaving its end, or at a saddle the left
// turn (4-connectivity) or the right turn (8-connectivity).
std::int64_t next_edge(const BoundaryEdges& b, std::int64_t e, bool eight) {
  const P2& d = kDir[b.dir[e]];
  const P2 end = {b.start[e][0] + d[0], b.start[e][1] + d[1]};
  const std::array<std::int64_t, 2>& out = b.leaving[b.point_id(end)];
  if (out[1] < 0) return out[0];
  const bool first_is_left = cross(d, kDir[b.dir[out[0]]]) > 0;
  return first_is_left != eight ? out[0] : out[1];
}

// Drops every vertex collinear with its two neighbours (exact: integer coordinates).
std::vector<P2> merge_collinear(const std::vector<P2>& ring) {
  std::vector<P2> out;
  for (const P2& p : ring) {
    while (out.size() >= 2 &&
           cross({out.back()[0] - out[out.size() - 2][0], out.back()[1] - out[out.size() - 2][1]},
                 {p[0] - out.back()[0], p[1] - out.back()[1]}) == 0)
      out.pop_back();
    out.push_back(p);
  }
  // The seam: the last and first vertices may be collinear with their neighbours too.
  for (bool changed = true; changed && out.size() > 3;) {
    changed = false;
    const std::size_t n = out.size();
    const P2 &a = out[n - 2], &b = out[n - 1], &c = out[0], &d = out[1];
    if (cross({b[0] - a[0], b[1] - a[1]}, {c[0] - b[0], c[1] - b[1]}) == 0) {
      out.pop_back(), changed = true;
    } else if (cross({c[0] - b[0], c[1] - b[1]}, {d[0] - c[0], d[1] - c[1]}) == 0) {
      out.erase(out.begin()), changed = true;
    }
  }
  return out;
}

// One closed boundary from edge `first`, as doubled vertices of the chosen contour.
std::vector<P2> trace_ring(const BoundaryEdges& b, std::int64_t first, bool eight, ImageContour contour,
                           std::vector<bool>& used) {
  std::vector<std::int64_t> edges;
  for (std::int64_t e = first; !used[e]; e = next_edge(b, e, eight)) used[e] = true, edges.push_back(e);
  std::vector<P2> ring;
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const std::int64_t e = edges[i], prev = edges[(i + edges.size() - 1) % edges.size()];
    const P2 v = {2 * b.start[e][0], 2 * b.start[e][1]};
    const P2 &d_out = kDir[b.dir[e]], &d_in = kDir[b.dir[prev]];
    const bool saddle = b.leaving[b.point_id(b.start[e])][1] >= 0;
    if (contour == ImageContour::MarchingSquares) {
      ring.push_back({v[0] + d_out[0], v[1] + d_out[1]});
    } else if (saddle) {
      ring.push_back({v[0] - d_in[0], v[1] - d_in[1]});
      ring.push_back({v[0] + d_out[0], v[1] + d_out[1]});
    } else {
      ring.push_back(v);
    }
  }
  return merge_collinear(ring);
}

std::int64_t twice_area(const std::vector<P2>& ring) {
  std::int64_t a = 0;
  for (std::size_t i = 0; i < ring.size(); ++i) a += cross(ring[i], ring[(i + 1) % ring.size()]);
  return a;
}

Ring to_ring(const std::vector<P2>& ring) {
  Ring r;
  for (const P2& p : ring) r.points.push_back({0.5 * double(p[0]), 0.5 * double(p[1])});
  return r;
}

long parse_long_option(const std::string& name, const std::string& value, long lo, long hi) {
  std::size_t used = 0;
  long x = 0;
  try {
    x = std::stol(value, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != value.size() || x < lo || x > hi)
    throw std::invalid_argument("option --" + name + " must be an integer in [" + std::to_string(lo) + ", " +
                                std::to_string(hi) + "], got '" + value + "'");
  return x;
}

}  // namespace

ImageShapeOptions parse_image_shape_options(const std::map<std::string, std::string>& named) {
  ImageShapeOptions o;
  for (const auto& [name, value] : named) {
    auto bad = [&, &name = name, &value = value](const std::string& allowed) {
      return std::invalid_argument("option --" + name + " must be " + allowed + ", got '" + value + "'");
    };
    if (name == "connectivity") {
      if (value != "4" && value != "8") throw bad("4 or 8");
      o.connectivity = value == "4" ? PixelConnectivity::Four : PixelConnectivity::Eight;
    } else if (name == "contour") {
      if (value != "pixel" && value != "marching-squares") throw bad("'pixel' or 'marching-squares'");
      o.contour = value == "pixel" ? ImageContour::PixelBoundary : ImageContour::MarchingSquares;
    } else if (name == "foreground") {
      const std::map<std::string, ImageForeground> kinds = {{"auto", ImageForeground::Auto},
                                                            {"dark", ImageForeground::Dark},
                                                            {"light", ImageForeground::Light},
                                                            {"opaque", ImageForeground::Opaque}};
      if (!kinds.count(value)) throw bad("'auto', 'dark', 'light' or 'opaque'");
      o.foreground = kinds.at(value);
    } else if (name == "threshold") {
      o.threshold = static_cast<int>(parse_long_option(name, value, 1, 255));
    } else if (name == "largest") {
      if (value != "true" && value != "false") throw bad("true or false");
      o.largest = value == "true";
    } else {
      throw std::invalid_argument("unknown image option '" + name +
                                  "' (connectivity, contour, foreground, threshold, largest)");
    }
  }
  return o;
}

std::vector<bool> foreground_mask(const GrayAlphaImage& image, const ImageShapeOptions& o) {
  const std::size_t n = image.gray.size();
  const bool transparency = std::any_of(image.alpha.begin(), image.alpha.end(), [](std::uint8_t a) { return a < 128; });
  ImageForeground rule = o.foreground;
  if (rule == ImageForeground::Auto && transparency) rule = ImageForeground::Opaque;
  if (rule == ImageForeground::Auto) {  // the border's majority class is the background
    std::size_t dark = 0, border = 0;
    for (std::uint32_t y = 0; y < image.height; ++y)
      for (std::uint32_t x = 0; x < image.width; ++x)
        if (x == 0 || y == 0 || x + 1 == image.width || y + 1 == image.height)
          ++border, dark += image.gray_at(x, y) < o.threshold;
    rule = 2 * dark > border ? ImageForeground::Light : ImageForeground::Dark;
  }
  std::vector<bool> mask(n);
  for (std::size_t i = 0; i < n; ++i) {
    const bool opaque = image.alpha[i] >= 128, dark = image.gray[i] < o.threshold;
    mask[i] = opaque && (rule == ImageForeground::Opaque || (rule == ImageForeground::Dark) == dark);
  }
  return mask;
}

Shape2 image_shape(const GrayAlphaImage& image, const ImageShapeOptions& o, const std::string& source) {
  const Mask all{image.width, image.height, foreground_mask(image, o)};
  const Mask m = single_component(all, o, source);
  const BoundaryEdges b = boundary_edges(m);
  const bool eight = o.connectivity == PixelConnectivity::Eight;
  std::vector<bool> used(b.start.size(), false);
  Shape2 shape;
  shape.name = source;
  shape.rings.emplace_back();  // the outer ring goes first
  for (std::size_t e = 0; e < b.start.size(); ++e) {
    if (used[e]) continue;
    const std::vector<P2> ring = trace_ring(b, static_cast<std::int64_t>(e), eight, o.contour, used);
    if (twice_area(ring) > 0) {
      if (!shape.rings[0].points.empty()) throw std::logic_error(source + ": two outer boundaries in one component");
      shape.rings[0] = to_ring(ring);
    } else {
      shape.rings.push_back(to_ring(ring));
    }
  }
  validate_shape(shape, source);
  return shape;
}

}  // namespace grassfire

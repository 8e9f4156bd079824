// fig_4_link_cylinder.cpp -- Figure 4.6 (the link and the disk types at a point of the
// junction of the board and fin, with the burning rule applied to it) and Figure 4.7 (the
// board and a hollow cylinder, approximated by a prism, where fronts wrap around the
// singular circle).
#include <cmath>
#include <cstdio>

#include "burn3/discrete/discrete_burning.h"
#include "complex3/synthetic_complexes.h"
#include "fig_4_scene.h"
#include "figure_registry.h"

namespace grassfire::figures {
namespace {

const Rgb kBack{0.25, 0.45, 0.85}, kFront{0.2, 0.65, 0.3}, kFin{0.9, 0.5, 0.15}, kBlack{0, 0, 0};

enum Side { kBackSide = 0, kFrontSide = 1, kFinSide = 2 };

int side_of(const MedialComplex& mc, std::uint32_t t) {
  Vec3d c{0, 0, 0};
  for (std::uint32_t v : mc.triangle(t).v)
    for (int i = 0; i < 3; ++i) c[i] += mc.vertex(v).approx[i] / 3;
  return c[2] > 0 ? kFinSide : c[1] < c[0] ? kBackSide : kFrontSide;
}

std::string fixed(double v, int digits = 2) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

// A half-disk of radius rho about x, spanned by the N direction u and the side direction w,
// as a fan of small triangles.
void half_disk(Renderer3d& r, const Point3d& x, const Point3d& u, const Point3d& w, double rho, const Rgb& color) {
  const int n = 24;
  for (int i = 0; i < n; ++i) {
    auto at = [&](int k) {
      const double phi = M_PI * k / n;
      return Point3d{x[0] + rho * (std::cos(phi) * u[0] + std::sin(phi) * w[0]),
                     x[1] + rho * (std::cos(phi) * u[1] + std::sin(phi) * w[1]),
                     x[2] + rho * (std::cos(phi) * u[2] + std::sin(phi) * w[2])};
    };
    r.triangle(x, at(i), at(i + 1), color);
    r.line(at(i), at(i + 1), shade(color, 0.6), 2.5);
  }
}

const Point3d kU = {M_SQRT1_2, M_SQRT1_2, 0};
const Point3d kW[3] = {{M_SQRT1_2, -M_SQRT1_2, 0}, {-M_SQRT1_2, M_SQRT1_2, 0}, {0, 0, 1}};
const Rgb kSideColor[3] = {kBack, kFront, kFin};
const char* kSideName[3] = {"back board", "front board", "fin"};

// Looking mostly along N, from the front side and above, so that the three half-disks
// fan out as a T: back board away, front board towards the viewer, fin up.
Camera link_camera() {
  Camera cam;
  const double a = 0.62, b = 0.55, c = 0.56;  // along N, towards the front side, up
  cam.eye = {5 + 7 * (a * M_SQRT1_2 - b * M_SQRT1_2), 5 + 7 * (a * M_SQRT1_2 + b * M_SQRT1_2), 7 * c};
  cam.target = {5, 5, 0.2};
  return cam;
}

std::vector<FigureFile> fig_4_6(const FigureContext& ctx) {
  const BoardFinScene& s = board_fin_scene();
  const Point3d x = {5, 5, 0};
  std::uint32_t vx = kNoIndex;
  for (std::uint32_t v = 0; v < s.mc.vertex_count(); ++v)
    if (s.mc.vertex(v).exact == ExactPoint3{5, 5, 0}) vx = v;
  double arrival[3] = {DiscreteBurning::kInfinity, DiscreteBurning::kInfinity, DiscreteBurning::kInfinity};
  double along[2] = {DiscreteBurning::kInfinity, DiscreteBurning::kInfinity};  // from c's side, from beyond
  const std::vector<double> arr = s.burning.vertex_arrivals(vx);
  for (std::size_t j = 0; j < arr.size(); ++j) {
    const LinkElement& el = s.mc.link_elements(vx)[j];
    if (!el.is_pole) {
      arrival[side_of(s.mc, s.mc.sectors()[el.id].triangles.front())] = arr[j];
      continue;
    }
    const ComplexEdge& e = s.mc.edge(el.id);
    const std::uint32_t other = e.v[0] == vx ? e.v[1] : e.v[0];
    along[s.mc.vertex(other).approx[0] < 5 ? 0 : 1] = arr[j];
  }
  SvgCanvas canvas(1200, 820);
  {  // (a) the neighbourhood, the link (three half-circles) and its two poles
    Renderer3d r(link_camera());
    for (int side = 0; side < 3; ++side) half_disk(r, x, kU, kW[side], 1.0, mix(kSideColor[side], {1, 1, 1}, 0.55));
    r.line({x[0] - 1.4 * kU[0], x[1] - 1.4 * kU[1], 0}, {x[0] + 1.4 * kU[0], x[1] + 1.4 * kU[1], 0}, {0.85, 0.1, 0.1}, 2.5);
    r.point({x[0] - kU[0], x[1] - kU[1], 0}, 5, kBlack);
    r.point({x[0] + kU[0], x[1] + kU[1], 0}, 5, kBlack);
    r.point(x, 4, {1, 1, 1});
    r.label(x, "x", 16, {0, 22});
    r.label({x[0] + 1.4 * kU[0], x[1] + 1.4 * kU[1], 0}, "N", 15, {12, 4});
    for (int side = 0; side < 3; ++side)
      r.label({x[0] + 1.15 * kW[side][0], x[1] + 1.15 * kW[side][1], 1.15 * kW[side][2]}, kSideName[side], 13);
    r.render(canvas, 0, 40, 560, 420);
    canvas.text({280, 30}, "(a) a ball about x cuts the link: three half-circles joined at two poles", 13, "middle");
  }
  const int disks[3][2] = {{kBackSide, kFrontSide}, {kBackSide, kFinSide}, {kFrontSide, kFinSide}};
  for (int d = 0; d < 3; ++d) {  // (b) the disk types: pairs of half-disks
    Renderer3d r(link_camera());
    for (int side = 0; side < 3; ++side) {
      const bool in = side == disks[d][0] || side == disks[d][1];
      half_disk(r, x, kU, kW[side], 1.0, in ? kSideColor[side] : Rgb{0.88, 0.88, 0.88});
    }
    r.point(x, 3, {1, 1, 1});
    r.render(canvas, 560 + 213.0 * d, 40, 213, 200);
    canvas.text({560 + 213.0 * d + 106, 250}, "D" + std::to_string(d + 1) + ": " + kSideName[disks[d][0]] + " + " +
                                                   kSideName[disks[d][1]], 11, "middle");
  }
  canvas.text({880, 30}, "(b) the disk types at x: each is a cycle of the link", 13, "middle");
  // (c) the burning rule on the link, with the baseline's arrival times at x.
  const double cx = 870, cy = 560, a = 170;
  const double bt = s.burning.vertex_bt[vx];
  canvas.text({cx, 300}, "(c) burning rule at x = (5, 5, 0), beyond the kink (discrete, h = 1/16)", 13, "middle");
  const double heights[3] = {110, 0, -110};
  for (int side = 0; side < 3; ++side) {
    std::vector<Point2d> arc;
    for (int i = 0; i <= 40; ++i) {
      const double phi = M_PI * i / 40;
      arc.push_back({cx - a * std::cos(phi), cy - heights[side] * std::sin(phi)});
    }
    const bool arrived = arrival[side] <= bt;
    canvas.polyline(arc, kSideColor[side], arrived ? 2 : 5, arrived ? "8,6" : "");
    const std::string what = std::isfinite(arrival[side]) && arrived
                                 ? kSideName[side] + std::string(": fire arrives at ") + fixed(arrival[side])
                                 : kSideName[side] + std::string(": no fire before x burns");
    canvas.text({cx, cy - heights[side] - (side == kBackSide ? -22 : 10)}, what, 13, "middle", shade(kSideColor[side], 0.8));
  }
  for (int j = 0; j < 2; ++j) {
    const bool arrived = along[j] <= bt;
    const double px = j == 0 ? cx - a : cx + a;
    canvas.circle({px, cy}, 8, arrived ? Rgb{1, 1, 1} : kBlack, kBlack, 2);
    canvas.text({px + (j == 0 ? -14 : 14), cy + 5}, j == 0 ? "N, side of c" : "N, far side", 13, j == 0 ? "end" : "start");
    if (std::isfinite(along[j]) && arrived)
      canvas.text({px + (j == 0 ? -14 : 14), cy + 23}, "fire along N at " + fixed(along[j]), 12, j == 0 ? "end" : "start");
  }
  const char* lines[] = {"arrived elements removed (dashed arcs, hollow poles): no cycle is left,",
                         "so every disk type D1, D2, D3 has received fire (Definition 9).",
                         "Beyond the kink the fin's front and the fire running along N arrive",
                         "together; fire goes on into the front board, whose arc is intact."};
  canvas.text({cx, 715}, "x burns at t = " + fixed(bt) + " (closed form 4 sqrt 2 = " + fixed(std::sqrt(2.0) * 4) + ")", 13,
              "middle");
  for (int i = 0; i < 4; ++i) canvas.text({cx, 737.0 + 19 * i}, lines[i], 12, "middle");
  canvas.text({280, 520}, "The regular neighbourhood radius R_M(x) is 5 here (the distance to B);", 12, "middle");
  canvas.text({280, 540}, "any smaller ball cuts the same link.", 12, "middle");
  canvas.save(ctx.out_dir + "/fig4_6.svg");
  return {{"fig4_6.svg",
           "Fig. 4.6: (a) a ball about the point x = (5, 5, 0) of the junction N cuts the complex in its link: three "
           "half-circles (back board, front board, fin) joined at the two directions of N; (b) the disk types of "
           "Definition 8 are the cycles of the link, D1, D2, D3; (c) the burning rule: at x (beyond the kink) fire from "
           "the board's border B arrives first (t = 5), then from the fin's border F (t = 4 sqrt 2); with both arcs "
           "removed no cycle is left, so x burns then and fire continues into the front board."}};
}

std::vector<FigureFile> fig_4_7(const FigureContext& ctx) {
  BoardCylinderOptions o;
  o.sides = 48, o.rings = 10, o.rows = 16, o.radius = 2, o.half_width = 6, o.height = 8, o.near_side_only = true;
  const MedialComplex mc(board_cylinder(o));
  mc.validate();
  const DiscreteBurning d = burn_discrete(mc, {0.08});
  std::vector<std::uint32_t> all(mc.triangle_count());
  for (std::uint32_t t = 0; t < all.size(); ++t) all[t] = t;
  Camera cam;
  cam.eye = {-16, 5, 12};
  cam.target = {0, 0, 1.5};
  Renderer3d r(cam);
  double hi = 0;
  for (double b : d.vertex_bt) hi = std::max(hi, b);
  draw_scalar(r, mc, all, [&](std::uint32_t t, int c) { return sector_burn_time(mc, d, t, c); }, 0, std::ceil(hi), 0.5,
              3);
  draw_edges(r, mc, all, EdgeStratum::Singular, {0.85, 0.1, 0.1}, 3);
  draw_edges(r, mc, all, EdgeStratum::Border, kBlack, 2, true);
  // A point behind the cylinder whose burning path wraps around the singular circle:
  // tangent to the circle, along it to (-r, 0), then straight to B.
  std::uint32_t vx = 0;
  double best = 1e9;
  for (std::uint32_t v = 0; v < mc.vertex_count(); ++v) {
    const Vec3d& p = mc.vertex(v).approx;
    const double dist = std::hypot(p[0], p[1] - 4.5) + std::abs(p[2]) * 100;
    if (dist < best) best = dist, vx = v;
  }
  const Vec3d px = mc.vertex(vx).approx;
  const double rad = 2, dx = std::hypot(px[0], px[1]);
  const double tangent = std::sqrt(dx * dx - rad * rad);
  const double theta_t = std::atan2(px[1], px[0]) + std::acos(rad / dx);  // tangent point, left side
  const double wrap = tangent + rad * (M_PI - theta_t) + (6 + 0.0);
  const Point3d t_pt = {rad * std::cos(theta_t), rad * std::sin(theta_t), 0};
  r.line(p3(px), t_pt, kBlack, 2.2, "6,4");
  for (double a = theta_t; a < M_PI; a += 0.05)
    r.line({rad * std::cos(a), rad * std::sin(a), 0}, {rad * std::cos(std::min(M_PI, a + 0.05)), rad * std::sin(std::min(M_PI, a + 0.05)), 0},
           kBlack, 2.2, "6,4");
  r.line({-rad, 0, 0}, {-rad, -6, 0}, kBlack, 2.2, "6,4");
  r.point(p3(px), 5, {1, 1, 1});
  r.label(p3(px), "x", 16, {0, -12});
  r.label({-rad, -6, 0}, "y", 16, {-4, 20});
  SvgCanvas canvas(1100, 860);
  r.render(canvas, 0, 50, 1100, 800);
  colour_bar(canvas, 430, 22, 240, 0, std::ceil(hi), "burning time BT");
  canvas.text({550, 845}, "BT(x) = " + fixed(d.vertex_bt[vx], 3) + " (discrete, h = 0.08); path length around the circle " +
                              fixed(wrap, 3) + " (round circle; the prism is inscribed)", 13, "middle");
  canvas.save(ctx.out_dir + "/fig4_7.svg");
  return {{"fig4_7.svg",
           "Fig. 4.7: a board (only its near side y = -6 ignites) and a hollow cylinder of height 8 on top, approximated "
           "by a prism over 48 exact rational points of the circle of radius 2; the cylinder's rim ignites too. Hue: BT "
           "(discrete baseline), iso-curves every 0.5; red: the singular circle. The burning path from x behind the "
           "cylinder to y on the border (dashed) touches the singular circle, which is not yet burned there: BT(x) is "
           "the infimum of the lengths of paths that avoid it, not attained (4.2.3)."}};
}

GF_REGISTER_FIGURE("fig4_6", "Figure 4.6: link and disk types at a singular point", fig_4_6);
GF_REGISTER_FIGURE("fig4_7", "Figure 4.7: board and hollow cylinder", fig_4_7);

}  // namespace
}  // namespace grassfire::figures

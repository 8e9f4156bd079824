// polytope_cells.cpp -- see polytope_cells.h.
#include "medial3/convex/polytope_cells.h"

#include <map>
#include <stdexcept>

#include "geometry3/exact_predicates3.h"

namespace grassfire {

namespace {

mpq_class as_rational(const RadicalNumber& x) {
  mpq_class q = 0;
  for (const RadicalNumber::Term& t : x.terms()) {
    if (t.key.n != 0) throw std::logic_error("polytope_cells: plane with radicals");
    q += t.coef;
  }
  return q;
}

// Box corner k has x = hi when bit 0 is set, y = hi for bit 1, z = hi for bit 2. Faces
// are listed counter-clockwise seen from outside (normal = (p1 - p0) x (p2 - p0)).
constexpr std::uint32_t kBoxFaces[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};

ConvexCell box_cell(PlaneSet& planes, const ExactPoint3& lo, const ExactPoint3& hi) {
  // Face f: x <= hi.x is  x - hi.x <= 0, x >= lo.x is  -x + lo.x <= 0, and so on.
  const mpq_class* bound[2][3] = {{&lo.x, &lo.y, &lo.z}, {&hi.x, &hi.y, &hi.z}};
  std::vector<CellFace> faces;
  for (int f = 0; f < 6; ++f) {
    const int axis = f / 2, upper = f % 2;
    std::array<RadicalNumber, 4> c{0, 0, 0, 0};
    c[axis] = upper ? 1 : -1;
    c[3] = upper ? RadicalNumber(-*bound[1][axis]) : RadicalNumber(*bound[0][axis]);
    const std::uint32_t id = planes.add(make_cell_plane(c, static_cast<std::uint64_t>(f)));
    faces.push_back({{kBoxFaces[f][0], kBoxFaces[f][1], kBoxFaces[f][2], kBoxFaces[f][3]}, {id}});
  }
  std::vector<CellVertex> corners;
  for (std::uint32_t k = 0; k < 8; ++k) {
    const ExactPoint3 p{*bound[k & 1][0], *bound[(k >> 1) & 1][1], *bound[(k >> 2) & 1][2]};
    std::vector<std::uint32_t> support{(k & 1) ? 1u : 0u, (k & 2) ? 3u : 2u, (k & 4) ? 5u : 4u};
    corners.push_back(rational_vertex(p, support));
  }
  return ConvexCell(planes, std::move(corners), std::move(faces));
}

}  // namespace

PolytopeCell clip_box(const ExactPoint3& lo, const ExactPoint3& hi, const std::vector<CellPlane>& cuts) {
  PlaneSet planes;
  ConvexCell cell = box_cell(planes, lo, hi);
  PolytopeCell out;
  for (const CellPlane& c : cuts) {
    if (cell.clip(planes.add(c)) == ConvexCell::Clip::Emptied) break;
  }
  out.stats = planes.stats;
  std::map<std::uint32_t, std::uint32_t> index;
  for (const CellFace& f : cell.faces()) {
    PolytopeFace pf;
    pf.label = planes[f.planes[0]].label();
    out.touches_box |= pf.label < kFirstFreeLabel;
    for (std::uint32_t v : f.vertices) {
      auto [it, fresh] = index.emplace(v, static_cast<std::uint32_t>(out.points.size()));
      if (fresh) {
        const HomogeneousPoint& h = planes.exact(cell.vertex(v));
        const mpq_class w = as_rational(h.c[3]);
        out.points.push_back({as_rational(h.c[0]) / w, as_rational(h.c[1]) / w, as_rational(h.c[2]) / w});
      }
      pf.vertices.push_back(it->second);
    }
    out.faces.push_back(std::move(pf));
  }
  out.stats = planes.stats;
  return out;
}

PolytopeCell polytope_from_planes(const std::vector<CellPlane>& planes, const std::string& source) {
  mpz_class m = 1;
  for (const CellPlane& p : planes) {
    std::array<mpq_class, 4> c;
    mpz_class l = 1;
    for (int k = 0; k < 4; ++k) {
      c[k] = as_rational(p.coef()[k]);
      mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), c[k].get_den_mpz_t());
    }
    for (int k = 0; k < 4; ++k) {
      const mpq_class scaled_q = abs(c[k] * l);
      const mpz_class scaled = scaled_q.get_num();
      if (scaled > m) m = scaled;
    }
  }
  const mpq_class b(6 * m * m * m + 1);
  PolytopeCell p = clip_box({-b, -b, -b}, {b, b, b}, planes);
  if (p.faces.empty()) throw std::invalid_argument(source + ": the half-spaces have no common interior point");
  if (p.touches_box) throw std::invalid_argument(source + ": the half-spaces do not bound a polyhedron (it is unbounded)");
  return p;
}

ExactPoint3 polygon_centroid(const PolytopeCell& cell, const PolytopeFace& face) {
  ExactPoint3 s{0, 0, 0};
  for (std::uint32_t v : face.vertices) s = s + cell.points[v];
  return make_rational(1, face.vertices.size()) * s;
}

mpq_class polytope_volume(const PolytopeCell& cell) {
  if (cell.points.empty()) return 0;
  ExactPoint3 c{0, 0, 0};
  for (const ExactPoint3& p : cell.points) c = c + p;
  c = make_rational(1, cell.points.size()) * c;
  mpq_class six = 0;  // faces are outward, so every fan tetrahedron counts positively
  for (const PolytopeFace& f : cell.faces)
    for (std::size_t k = 1; k + 1 < f.vertices.size(); ++k)
      six += dot(cross(cell.points[f.vertices[0]] - c, cell.points[f.vertices[k]] - c), cell.points[f.vertices[k + 1]] - c);
  return six / 6;
}

}  // namespace grassfire

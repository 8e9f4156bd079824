// medial2_json.cpp -- see medial2_json.h.
#include "io/medial2_json.h"

#include <nlohmann/json.hpp>

#include <algorithm>

namespace grassfire {

nlohmann::ordered_json certified_json(const Interval& x, double& bound) {
  if (x.is_infinite()) return "inf";
  bound = std::max(bound, x.radius());
  return x.mid();
}

namespace {

using Json = nlohmann::ordered_json;

Json value(const Interval& x, double& bound) { return certified_json(x, bound); }

Json ema_json(const MedialGraph& g, const ExtendedMedialAxis& ema, double& bound) {
  Json j;
  if (ema.kind == ExtendedMedialAxis::Kind::Cycles) {
    j["kind"] = "cycles";
    j["nodes"] = ema.nodes;
    j["edges"] = ema.edges;
    return j;
  }
  const Point2 p = position_of(g, ema.point);
  j["kind"] = "point";
  j["x"] = p.x;
  j["y"] = p.y;
  j["edf"] = value(ema.edf, bound);
  if (ema.point.at_node) {
    j["node"] = ema.point.node;
  } else {
    const MedialEdge& e = g.edge(ema.point.edge);
    const Interval offset = ema.point.from == e.u ? ema.point.offset : e.length - ema.point.offset;
    j["edge"] = ema.point.edge;
    j["offset"] = value(offset, bound);
  }
  return j;
}

}  // namespace

std::string medial2d_json(const Medial2dJsonInput& in) {
  const MedialGraph& g = *in.graph;
  const GrassfireResult& r = *in.burning;
  double b_r = 0, b_edf = 0, b_et = 0, b_st = 0, b_len = 0, b_ema = 0, b_pos = 0, b_pr = 0;
  Json j;
  j["format"] = "grassfire-medial2d";
  j["version"] = 1;
  j["shape"] = in.shape_name;
  j["variant"] = to_string(r.variant);
  j["samples"] = in.samples;
  Json nodes = Json::array();
  for (std::uint32_t v = 0; v < g.node_count(); ++v) {
    const MedialNode& n = g.node(v);
    Json o;
    o["x"] = n.position.x;
    o["y"] = n.position.y;
    b_pos = std::max(b_pos, n.position_error);
    o["R"] = value(n.radius, b_r);
    o["edf"] = value(r.edf(v), b_edf);
    o["et"] = value(in.measures->erosion_thickness[v], b_et);
    o["st"] = value(in.measures->tubularity[v], b_st);
    if (in.residue) o["pr"] = value(in.residue->node[v].value, b_pr);
    nodes.push_back(std::move(o));
  }
  j["nodes"] = std::move(nodes);
  Json edges = Json::array();
  for (const MedialEdge& e : g.edges()) {
    Json o;
    o["u"] = e.u;
    o["v"] = e.v;
    o["length"] = value(e.length, b_len);
    o["kind"] = to_string(e.kind);
    edges.push_back(std::move(o));
  }
  j["edges"] = std::move(edges);
  if (r.ema.size() == 1) {
    j["ema"] = ema_json(g, r.ema[0], b_ema);
  } else {
    Json parts = Json::array();
    for (const ExtendedMedialAxis& e : r.ema) parts.push_back(ema_json(g, e, b_ema));
    j["ema"] = {{"kind", "components"}, {"parts", std::move(parts)}};
  }
  if (in.residue) {
    const ResidueMaximum& m = in.residue->maximum;
    j["pr_max"] = {{"x", m.position.x},
                   {"y", m.position.y},
                   {"pr", value(m.value.value, b_pr)},
                   {"closest", {{m.closest[0].x, m.closest[0].y}, {m.closest[1].x, m.closest[1].y}}}};
  }
  j["error_bound"] = {{"position", b_pos}, {"R", b_r},          {"edf", b_edf}, {"et", b_et},
                      {"st", b_st},        {"length", b_len}, {"ema", b_ema}};
  if (in.residue) j["error_bound"]["pr"] = b_pr;
  const NumberStats& st = r.stats();
  j["certification"] = {{"filter_decided", st.filter_decided},
                        {"multiprecision_decided", st.mpfr_decided},
                        {"exact_zero", st.exact_zero},
                        {"uncertified_ties", st.uncertified_zero},
                        {"queue_ties", r.queue_ties},
                        {"voronoi_fallbacks", in.voronoi_fallbacks}};
  return j.dump(1) + "\n";
}

}  // namespace grassfire

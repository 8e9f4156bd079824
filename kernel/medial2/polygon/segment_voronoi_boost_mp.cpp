// segment_voronoi_boost_mp.cpp -- the interior segment Voronoi topology of any finite double
// polygon by Boost.Polygon's builder on exact integers of any size (the mp traits of
// boost_mp_traits.h; see segment_voronoi.h).
// The doubles are integers times 2^low (low = the smallest exponent of a lowest set bit), so
// x 2^-low are exact integers; translated to the centre of their bounding box (a translation
// does not change the diagram) they need B bits, and the tier of boost_mp_traits.h is the
// cheapest whose floats carry B + kGuardBits bits. For B <= 126 the construction first runs
// in the double-interval filter stage (Tier128Filter with FilterPredicates: the same
// branches as the MPFR run, MPFR only for the decisions the intervals leave open); an
// event-order tie it cannot resolve reruns the whole construction in MPFR (Tier128).
#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "medial2/polygon/boost_mp_traits.h"
#include "medial2/polygon/boost_voronoi_events.h"
#include "medial2/polygon/segment_voronoi.h"

namespace grassfire {

namespace bp = boost::polygon;

namespace {

// The frame's coordinates as exact integers x 2^-low, translated to their bounding box's
// centre (x0 y0 x1 y1 ... in vertex order).
std::vector<mpz_class> exact_integers(const PolygonSites& sites) {
  int low = 1 << 20;
  for (const Point2& p : sites.vertex)
    for (double x : {p.x, p.y}) {
      if (!std::isfinite(x)) throw std::invalid_argument("boost_segment_voronoi_mp: a coordinate is not finite");
      if (x != 0) {
        int e = 0;
        const double m = std::frexp(x, &e);
        const long long mi = static_cast<long long>(std::ldexp(m, 53));
        low = std::min(low, e - 53 + __builtin_ctzll(static_cast<unsigned long long>(mi < 0 ? -mi : mi)));
      }
    }
  std::vector<mpz_class> v;
  v.reserve(2 * sites.vertex.size());
  for (const Point2& p : sites.vertex)
    for (double x : {p.x, p.y}) {
      mpz_class z = 0;
      if (x != 0) {
        int e = 0;
        long long mi = static_cast<long long>(std::ldexp(std::frexp(x, &e), 53));
        const int tz = __builtin_ctzll(static_cast<unsigned long long>(mi < 0 ? -mi : mi));
        mi /= 1LL << tz;  // exact: x = mi 2^(e - 53 + tz), e - 53 + tz >= low
        z = static_cast<long>(mi);
        z <<= static_cast<unsigned long>(e - 53 + tz - low);
      }
      v.push_back(std::move(z));
    }
  for (int axis = 0; axis < 2 && !v.empty(); ++axis) {
    mpz_class lo = v[axis], hi = v[axis];
    for (std::size_t i = axis; i < v.size(); i += 2) {
      if (v[i] < lo) lo = v[i];
      if (v[i] > hi) hi = v[i];
    }
    mpz_class c = lo + hi;
    mpz_fdiv_q_2exp(c.get_mpz_t(), c.get_mpz_t(), 1);
    for (std::size_t i = axis; i < v.size(); i += 2) v[i] -= c;
  }
  return v;
}

int bits_of(const std::vector<mpz_class>& v) {
  std::size_t b = 0;
  for (const mpz_class& z : v)
    if (z != 0) b = std::max(b, mpz_sizeinbase(z.get_mpz_t(), 2));
  return static_cast<int>(b);
}

__int128 to_int(const mpz_class& z, __int128*) {
  const bool neg = z < 0;
  mpz_class a = abs(z);
  const mpz_class hi = a >> 64;
  const mpz_class lo = a - (hi << 64);
  unsigned __int128 u = (static_cast<unsigned __int128>(mpz_get_ui(hi.get_mpz_t())) << 64) | mpz_get_ui(lo.get_mpz_t());
  const __int128 s = static_cast<__int128>(u);
  return neg ? -s : s;
}

boost_mp::Gmp to_int(const mpz_class& z, boost_mp::Gmp*) { return boost_mp::Gmp(z.get_mpz_t()); }

template <class Traits, class Predicates = bp::detail::voronoi_predicates<Traits>>
VoronoiTopology construct(const PolygonSites& sites, const std::vector<mpz_class>& v, BoostReader reader) {
  using Int = typename Traits::int_type;
  using F = typename Traits::fpt_type;
  std::vector<Int> c;
  c.reserve(v.size());
  for (const mpz_class& z : v) c.push_back(to_int(z, static_cast<Int*>(nullptr)));
  using Diagram = bp::voronoi_diagram<F, NoMergeTraits<F>>;
  return boost_interior_topology<Diagram>(
      sites,
      [&](auto* output) {
        bp::voronoi_builder<Int, Traits, Predicates> builder;
        for (std::uint32_t i = 0; i < sites.vertex_count(); ++i) {
          const std::uint32_t j = sites.next[i];
          builder.insert_segment(c[2 * i], c[2 * i + 1], c[2 * j], c[2 * j + 1]);
        }
        builder.construct(output);
      },
      reader == BoostReader::Diagram);
}

}  // namespace

VoronoiTopology boost_segment_voronoi_mp(const PolygonSites& sites, MpTier* tier, bool filter, bool verify,
                                         BoostReader reader) {
  const std::vector<mpz_class> v = exact_integers(sites);
  const int bits = bits_of(v);
  MpTier t;
  t.input_bits = bits;
  VoronoiTopology out;
  if (bits <= boost_mp::Tier128::kInputBits && !filter) {
    t.float_bits = static_cast<int>(boost_mp::precision_bits<60>());
    out = construct<boost_mp::Tier128>(sites, v, reader);
  } else if (bits <= boost_mp::Tier128::kInputBits) {
    t.float_bits = static_cast<int>(boost_mp::precision_bits<60>());
    boost_mp::fallbacks = boost_mp::verified = boost_mp::verify_mismatches = 0;
    boost_mp::CircleOrigins origins;
    struct Scope {
      Scope(boost_mp::CircleOrigins* o, bool verify) {
        boost_mp::circle_origins = o;
        boost_mp::verify = verify;
      }
      ~Scope() {
        boost_mp::circle_origins = nullptr;
        boost_mp::verify = false;
      }
    } scope(&origins, verify);
    try {
      out = construct<boost_mp::Tier128Filter, boost_mp::FilterPredicates>(sites, v, reader);
      t.filtered = true;
      t.fallbacks = boost_mp::fallbacks;
      t.verified = boost_mp::verified;
      t.verify_mismatches = boost_mp::verify_mismatches;
    } catch (const FilterUndecided&) {
      out = construct<boost_mp::Tier128>(sites, v, reader);
    }
  } else if (bits + boost_mp::kGuardBits <= boost_mp::precision_bits<200>()) {
    t.float_bits = static_cast<int>(boost_mp::precision_bits<200>());
    out = construct<boost_mp::TierGmp<200>>(sites, v, reader);
  } else if (bits + boost_mp::kGuardBits <= boost_mp::precision_bits<700>()) {
    t.float_bits = static_cast<int>(boost_mp::precision_bits<700>());
    out = construct<boost_mp::TierGmp<700>>(sites, v, reader);
  } else {
    throw std::invalid_argument("boost_segment_voronoi_mp: the frame's integers need " + std::to_string(bits) +
                                " bits, more than any pair of finite doubles");
  }
  if (tier) *tier = t;
  return out;
}

}  // namespace grassfire

#include "io/hybrid_io.hpp"

#include <set>

#include "float/mpfr.hpp"

namespace splinex {

HybridPatch<Rational> hybrid_from_json(const Json& doc, const Limits& limits) {
  check_document_bits(doc, "patch", limits);
  if (!doc.is_object()) throw ParseError("document", "is not an object", "give {\"type\": \"hybrid_patch\", ...}");
  static const std::set<std::string> known{"type", "domain", "degree", "sides", "ribbon_factor"};
  for (auto it = doc.begin(); it != doc.end(); ++it)
    if (!known.count(it.key())) throw ParseError(it.key(), "is not a field of a hybrid patch", "use type, domain, degree, sides, ribbon_factor");
  if (!doc.contains("type") || doc["type"] != "hybrid_patch")
    throw ParseError("type", "must be \"hybrid_patch\"", "set \"type\": \"hybrid_patch\"");
  for (const char* f : {"domain", "degree", "sides"})
    if (!doc.contains(f)) throw ParseError(f, "is missing", "give domain, degree and sides");
  HybridPatch<Rational> P;
  const Json& dom = doc["domain"];
  if (!dom.is_array()) throw ParseError("domain", "is not an array of points", "give [[x, y], ...]");
  if (dom.size() > 10000) throw SizeLimitError("domain", "has " + std::to_string(dom.size()) + " vertices", "give at most 10000");
  for (std::size_t i = 0; i < dom.size(); ++i) {
    const std::string f = "domain[" + std::to_string(i) + "]";
    if (!dom[i].is_array() || dom[i].size() != 2) throw ParseError(f, "must be [x, y]", "give two numbers");
    P.vertices.push_back({json_number(dom[i][0], f + "[0]"), json_number(dom[i][1], f + "[1]")});
  }
  P.d = json_int(doc["degree"], "degree", 0, limits.max_degree);
  if (doc.contains("ribbon_factor")) {
    const Json& r = doc["ribbon_factor"];
    if (r == "side_interpolant")
      P.ribbon = RibbonFactor::side_interpolant;
    else if (r == "eq-2.11")
      P.ribbon = RibbonFactor::eq_2_11;
    else
      throw ParseError("ribbon_factor", "must be \"side_interpolant\" or \"eq-2.11\"", "choose one of the two");
  }
  const Json& sides = doc["sides"];
  if (!sides.is_array()) throw ParseError("sides", "is not an array", "give one object per domain side");
  const int l = (P.d + 1) / 2;
  P.q = -1;
  std::vector<std::vector<std::vector<std::vector<Rational>>>> pts;  // side, layer, column, coordinate
  for (std::size_t i = 0; i < sides.size(); ++i) {
    const std::string f = "sides[" + std::to_string(i) + "]";
    const Json& s = sides[i];
    if (!s.is_object()) throw ParseError(f, "is not an object", "give {\"degree\": p, \"knots\": [...], \"layers\": [...]}");
    for (auto it = s.begin(); it != s.end(); ++it)
      if (it.key() != "degree" && it.key() != "knots" && it.key() != "layers")
        throw ParseError(f + "." + it.key(), "is not a field of a side", "use degree, knots, layers");
    for (const char* g : {"degree", "knots", "layers"})
      if (!s.contains(g)) throw ParseError(f + "." + g, "is missing", "give degree, knots and layers");
    P.p.push_back(json_int(s["degree"], f + ".degree", 0, limits.max_degree));
    if (!s["knots"].is_array()) throw ParseError(f + ".knots", "is not an array", "give the knots as an array");
    std::vector<Rational> U;
    for (std::size_t k = 0; k < s["knots"].size() && k < 100000; ++k)
      U.push_back(json_number(s["knots"][k], f + ".knots[" + std::to_string(k) + "]"));
    P.knots.push_back(std::move(U));
    const Json& L = s["layers"];
    if (!L.is_array() || L.size() != static_cast<std::size_t>(l))
      throw ValidationError(f + ".layers", "must hold l = ceil(d/2) = " + std::to_string(l) + " layers",
                            "give " + std::to_string(l) + " layers of d + 1 = " + std::to_string(P.d + 1) + " points");
    pts.emplace_back();
    for (int k = 0; k < l; ++k) {
      const std::string fk = f + ".layers[" + std::to_string(k) + "]";
      if (!L[k].is_array() || L[k].size() != static_cast<std::size_t>(P.d + 1))
        throw ValidationError(fk, "must hold d + 1 = " + std::to_string(P.d + 1) + " points", "give one point per column j = 0..d");
      pts.back().emplace_back();
      for (int j = 0; j <= P.d; ++j) {
        const std::string fj = fk + "[" + std::to_string(j) + "]";
        const Json& c = L[k][j];
        if (!c.is_array() || c.empty() || c.size() > 16) throw ParseError(fj, "must be a point [x, y, z]", "give 1 to 16 coordinates");
        if (P.q < 0) P.q = static_cast<int>(c.size());
        if (c.size() != static_cast<std::size_t>(P.q))
          throw ValidationError(fj, "has " + std::to_string(c.size()) + " coordinates, the first point has " + std::to_string(P.q),
                                "give every point the same number of coordinates");
        std::vector<Rational> v;
        for (int a = 0; a < P.q; ++a) v.push_back(json_number(c[a], fj + "[" + std::to_string(a) + "]"));
        pts.back().back().push_back(std::move(v));
      }
    }
  }
  if (P.q < 0) P.q = 3;
  if (sides.size() != P.vertices.size())
    throw ValidationError("sides", "has " + std::to_string(sides.size()) + " entries for " + std::to_string(P.vertices.size()) +
                                       " domain sides",
                          "give one side per domain edge (side i from domain[i] to domain[i + 1])");
  P.points.assign(P.vertices.size() * l * (P.d + 1) * P.q, Rational(0));
  for (std::size_t i = 0; i < pts.size(); ++i)
    for (int k = 0; k < l; ++k)
      for (int j = 0; j <= P.d; ++j)
        for (int a = 0; a < P.q; ++a) P.points[P.index(i, j, k) + a] = pts[i][k][j][a];
  validate(P);
  return P;
}

template <class T>
Json hybrid_to_json(const HybridPatch<T>& P) {
  Json doc{{"type", "hybrid_patch"}, {"degree", P.d}};
  doc["ribbon_factor"] = P.ribbon == RibbonFactor::side_interpolant ? "side_interpolant" : "eq-2.11";
  Json dom = Json::array();
  for (const auto& v : P.vertices) dom.push_back({ArithTraits<T>::to_json(v[0]), ArithTraits<T>::to_json(v[1])});
  doc["domain"] = dom;
  Json sides = Json::array();
  for (std::size_t i = 0; i < P.sides(); ++i) {
    Json U = Json::array(), L = Json::array();
    for (const auto& u : P.knots[i]) U.push_back(ArithTraits<T>::to_json(u));
    for (int k = 0; k < P.layers(); ++k) {
      Json row = Json::array();
      for (int j = 0; j <= P.d; ++j) {
        Json c = Json::array();
        for (int a = 0; a < P.q; ++a) c.push_back(ArithTraits<T>::to_json(P.points[P.index(i, j, k) + a]));
        row.push_back(c);
      }
      L.push_back(row);
    }
    sides.push_back({{"degree", P.p[i]}, {"knots", U}, {"layers", L}});
  }
  doc["sides"] = sides;
  return doc;
}

template Json hybrid_to_json(const HybridPatch<Rational>&);

template <class F>
Json hybrid_points_document(const HybridPatch<Rational>& P, const std::vector<std::array<Rational, 2>>& xs) {
  using Tr = ArithTraits<F>;
  const auto cv = [](const Rational& r) { return Tr::from_rational(r); };
  const auto Q = convert_hybrid<F>(P, cv);
  Json pts = Json::array();
  for (const auto& x : xs) {
    const std::array<F, 2> xf{cv(x[0]), cv(x[1])};
    const auto L = hybrid_local(Q, xf);
    Json row{{"at", {ArithTraits<Rational>::to_json(x[0]), ArithTraits<Rational>::to_json(x[1])}},
             {"point", point_to_json(hybrid_evaluate(Q, xf))},
             {"wachspress", point_to_json(L.lambda)},
             {"s", point_to_json(L.s)},
             {"h", point_to_json(L.h)}};
    bool corner = false;
    for (const auto& v : Q.vertices) corner = corner || (v[0] == xf[0] && v[1] == xf[1]);
    if (corner) {
      row["derivatives"] = "none at a corner (alpha_i, beta_(i-1) are 0/0 there; see README)";
    } else {
      const auto D = hybrid_derivatives(Q, xf);
      row["du"] = point_to_json(D.du);
      row["dv"] = point_to_json(D.dv);
    }
    pts.push_back(row);
  }
  return Json{{"points", pts}, {"arith", Tr::name()}};
}

template Json hybrid_points_document<Rational>(const HybridPatch<Rational>&, const std::vector<std::array<Rational, 2>>&);
template Json hybrid_points_document<double>(const HybridPatch<Rational>&, const std::vector<std::array<Rational, 2>>&);
template Json hybrid_points_document<Mpfr>(const HybridPatch<Rational>&, const std::vector<std::array<Rational, 2>>&);

}  // namespace splinex

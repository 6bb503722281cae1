#include "io/trimmed_domain_io.hpp"

#include <string>

#include "base/errors.hpp"
#include "float/mpfr.hpp"
#include "io/result_json.hpp"

namespace splinex {

TrimmedDomain trimmed_domain_from_json(const Json& doc) {
  if (!doc.is_object()) throw ParseError("document", "is not an object", "give {\"type\": \"trimmed_domain\", ...}");
  for (auto it = doc.begin(); it != doc.end(); ++it)
    if (it.key() != "type" && it.key() != "domain" && it.key() != "loops")
      throw ParseError(it.key(), "is not a field of a trimmed domain", "use type, domain, loops");
  if (!doc.contains("type") || doc["type"] != "trimmed_domain")
    throw ParseError("type", "must be \"trimmed_domain\"", "set \"type\": \"trimmed_domain\"");
  if (!doc.contains("domain") || !doc["domain"].is_array() || doc["domain"].size() != 2)
    throw ParseError("domain", "must be [[x0, x1], [y0, y1]]", "give the parameter box");
  TrimmedDomain D;
  for (int d = 0; d < 2; ++d) {
    const auto& iv = doc["domain"][d];
    const std::string f = "domain[" + std::to_string(d) + "]";
    if (!iv.is_array() || iv.size() != 2) throw ParseError(f, "must be [lo, hi]", "give two numbers");
    D.lo[d] = json_number(iv[0], f + "[0]");
    D.hi[d] = json_number(iv[1], f + "[1]");
  }
  if (!doc.contains("loops") || !doc["loops"].is_array())
    throw ParseError("loops", "must be an array of loops", "give [[[x, y], ...], ...]");
  for (std::size_t l = 0; l < doc["loops"].size(); ++l) {
    const auto& L = doc["loops"][l];
    if (!L.is_array()) throw ParseError(loop_field(l), "is not an array of points", "give [[x, y], ...]");
    Polygon P;
    std::vector<Polygon> C;
    for (std::size_t i = 0; i < L.size(); ++i) {
      if (L[i].is_object()) {
        const std::string f = vertex_field(l, i);
        if (L[i].size() != 1 || !L[i].contains("controls") || !L[i]["controls"].is_array())
          throw ParseError(f, "is an object but not {\"controls\": [[x, y], ...]}", "give a vertex [x, y] or an edge's inner control points");
        if (P.empty() || C.back().size() > 0)
          throw ParseError(f, "has no vertex before it (or follows another controls item)",
                           "write the controls of edge i right after vertex i");
        for (std::size_t j = 0; j < L[i]["controls"].size(); ++j) {
          const auto& q = L[i]["controls"][j];
          const std::string fq = f + ".controls[" + std::to_string(j) + "]";
          if (!q.is_array() || q.size() != 2) throw ParseError(fq, "must be [x, y]", "give two numbers");
          C.back().push_back({json_number(q[0], fq + "[0]"), json_number(q[1], fq + "[1]")});
        }
        if (C.back().empty()) throw ParseError(f, "has no control points", "drop the item for a straight edge");
        continue;
      }
      if (!L[i].is_array() || L[i].size() != 2) throw ParseError(vertex_field(l, i), "must be [x, y]", "give two numbers");
      P.push_back({json_number(L[i][0], vertex_field(l, i) + "[0]"), json_number(L[i][1], vertex_field(l, i) + "[1]")});
      C.emplace_back();
    }
    D.controls.push_back(std::move(C));
    D.loops.push_back(std::move(P));
  }
  validate_domain(D);
  return D;
}

template <class F>
Json untrim_document(const UntrimRun<F>& run) {
  using Tr = ArithTraits<F>;
  Json out_tiles = Json::array();
  for (const auto& u : run.tiles) {
    Json tj{{"tile", tile_to_json(u.tile)}, {"area", Tr::to_json(u.area)}, {"coons_patch", spline_to_json(u.coons)}};
    if (u.patch) tj["patch"] = spline_to_json(*u.patch);
    if (u.integral) tj["integral"] = Tr::to_json(*u.integral);
    out_tiles.push_back(tj);
  }
  const auto error_of = [](const F& value, const Rational& exact) {
    return to_double(Rational(abs(Rational(Tr::to_rational(value) - exact))));
  };
  Json out{{"tiles", out_tiles},
           {"area", Tr::to_json(run.area)},
           {"area_check", {{run.curved ? "green_exact_area" : "cgal_exact_area", ArithTraits<Rational>::to_json(run.exact_area)},
                           {"abs_error", error_of(run.area, run.exact_area)}}},
           {"tile_rule", "a tile is {(x, y): x in [x_0, x_m], y_bottom(x) <= y <= y_top(x)}; its Coons patch Q(x, l) "
                         "= (x, y_bottom(x) + l (y_top(x) - y_bottom(x))) on [x_0, x_m] x [0, 1]; patch = surface(Q). "
                         "y_bottom is linear between the samples, or on [x_i, x_i+1] the Bernstein polynomial with "
                         "ordinates bottom_pieces[i] when given (likewise y_top)"}};
  if (run.cover) {
    const auto& cc = *run.cover;
    out["cover_certificate"] = {{"proved", cc.ok},
                                {"checks", "tiles pairwise interior-disjoint, no loop edge enters a tile, a point of "
                                           "every part of every tile inside the region, tile areas add up to the region's"},
                                {"pair_checks", cc.pair_checks},
                                {"edge_checks", cc.edge_checks},
                                {"samples", cc.samples}};
    if (!cc.ok) out["cover_certificate"]["failure"] = cc.failure;
  }
  if (run.integral) {
    out["integral"] = Tr::to_json(*run.integral);
    out["integral_check"] = {{"green_exact_integral", ArithTraits<Rational>::to_json(*run.exact_integral)},
                             {"abs_error", error_of(*run.integral, *run.exact_integral)}};
  }
  return out;
}

template Json untrim_document(const UntrimRun<Rational>&);
template Json untrim_document(const UntrimRun<double>&);
template Json untrim_document(const UntrimRun<Mpfr>&);

}  // namespace splinex

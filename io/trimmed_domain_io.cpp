#include "io/trimmed_domain_io.hpp"

#include <string>

#include "base/errors.hpp"

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

}  // namespace splinex

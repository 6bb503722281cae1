#include "io/trimmed_io.hpp"

#include "io/vmodel_io.hpp"

#include "float/mpfr.hpp"

namespace splinex {

namespace {

Region<Rational> region_at(const Json& j, const std::string& where, int depth, std::size_t& leaves) {
  if (depth > 64) throw SizeLimitError(where, "nests regions deeper than 64 levels", "flatten the formula");
  if (!j.is_object() || j.size() < 1)
    throw ValidationError(where, "is not a region", "give {\"leaf\": [[c, a, b, e], ...]}, {\"all\": [...]}, {\"any\": [...]}, {\"not\": {...}} or {\"cases\": [...]}");
  for (auto it = j.begin(); it != j.end(); ++it)
    if (it.key() != "leaf" && it.key() != "all" && it.key() != "any" && it.key() != "not" && it.key() != "cases" && it.key() != "label")
      throw ValidationError(where + "." + it.key(), "is not a field of a region", "remove it (fields: leaf, all, any, not, cases, label)");
  int kinds = 0;
  for (const char* k : {"leaf", "all", "any", "not", "cases"}) kinds += j.contains(k) ? 1 : 0;
  if (kinds > 1) throw ValidationError(where, "has more than one of leaf, all, any, not, cases", "give one per region object");
  const std::string label = j.contains("label") && j["label"].is_string() ? j["label"].get<std::string>() : std::string();
  if (j.contains("leaf")) {
    if (++leaves > 4096) throw SizeLimitError(where, "has more than 4096 leaves", "give a smaller formula");
    const Json& t = j["leaf"];
    if (!t.is_array() || t.empty()) throw ValidationError(where + ".leaf", "is not a non-empty list of terms", "give [[c, a, b, e], ...] for sum c x^a y^b z^e");
    Poly3<Rational> g;
    for (std::size_t k = 0; k < t.size(); ++k) {
      const std::string w = where + ".leaf[" + std::to_string(k) + "]";
      if (!t[k].is_array() || t[k].size() != 4) throw ValidationError(w, "is not a term [c, a, b, e]", "give the coefficient and the three exponents");
      const std::array<int, 3> e{json_int(t[k][1], w + "[1]", 0, 8), json_int(t[k][2], w + "[2]", 0, 8), json_int(t[k][3], w + "[3]", 0, 8)};
      if (e[0] + e[1] + e[2] > 8) throw SizeLimitError(w, "has total degree above 8", "give polynomials of degree <= 8");
      g.terms[e] += json_number(t[k][0], w + "[0]");
    }
    return region_leaf(std::move(g), label.empty() ? where : label);
  }
  if (j.contains("not")) return region_not(region_at(j["not"], where + ".not", depth + 1, leaves));
  if (j.contains("cases")) {
    // [{"piece": region, "then": region}, ...]: pieces that cover space, a formula on each.
    const Json& c = j["cases"];
    const std::string w = where + ".cases";
    if (!c.is_array() || c.empty()) throw ValidationError(w, "is not a non-empty list of cases", "give [{\"piece\": region, \"then\": region}, ...]");
    std::vector<std::pair<Region<Rational>, Region<Rational>>> cases;
    for (std::size_t k = 0; k < c.size(); ++k) {
      const std::string wk = w + "[" + std::to_string(k) + "]";
      if (!c[k].is_object() || c[k].size() != 2 || !c[k].contains("piece") || !c[k].contains("then"))
        throw ValidationError(wk, "is not a case", "give {\"piece\": region, \"then\": region}");
      Region<Rational> piece = region_at(c[k]["piece"], wk + ".piece", depth + 1, leaves);
      cases.emplace_back(std::move(piece), region_at(c[k]["then"], wk + ".then", depth + 1, leaves));
    }
    Region<Rational> r = region_cases(std::move(cases));
    r.label = label;
    return r;
  }
  const char* key = j.contains("all") ? "all" : "any";
  if (!j.contains(key)) throw ValidationError(where, "has none of leaf, all, any, not, cases", "give one of them");
  const Json& p = j[key];
  if (!p.is_array()) throw ValidationError(where + "." + key, "is not a list of regions", "give [region, ...]");
  std::vector<Region<Rational>> parts;
  for (std::size_t k = 0; k < p.size(); ++k) parts.push_back(region_at(p[k], where + "." + key + "[" + std::to_string(k) + "]", depth + 1, leaves));
  Region<Rational> r = std::string(key) == "all" ? region_and(std::move(parts)) : region_or(std::move(parts));
  r.label = label;
  return r;
}

}  // namespace

Region<Rational> region_from_json(const Json& j, const std::string& where) {
  std::size_t leaves = 0;
  return region_at(j, where, 0, leaves);
}

template <class T>
Json region_to_json(const Region<T>& R) {
  Json out = Json::object();
  if (!R.label.empty()) out["label"] = R.label;
  switch (R.kind) {
    case Region<T>::leaf: {
      if (R.alias >= 0) throw std::logic_error("region_to_json: an internal alias leaf cannot be written");
      Json t = Json::array();
      for (const auto& [e, c] : R.g.terms) t.push_back({ArithTraits<T>::to_json(c), e[0], e[1], e[2]});
      out["leaf"] = t;
      return out;
    }
    case Region<T>::complement: out["not"] = region_to_json(R.parts.front()); return out;
    case Region<T>::cases: {
      Json c = Json::array();
      for (std::size_t i = 0; i + 1 < R.parts.size(); i += 2)
        c.push_back({{"piece", region_to_json(R.parts[i])}, {"then", region_to_json(R.parts[i + 1])}});
      out["cases"] = c;
      return out;
    }
    default: {
      Json p = Json::array();
      for (const auto& x : R.parts) p.push_back(region_to_json(x));
      out[R.kind == Region<T>::all_of ? "all" : "any"] = p;
      return out;
    }
  }
}

TrimmedModel<Rational> trimmed_from_json(const Json& doc, const Limits& limits, const std::string& where) {
  check_document_bits(doc, where, limits);
  if (!doc.is_object() || !doc.contains("type") || doc["type"] != "trimmed_vmodel")
    throw ValidationError(where, "is not a trimmed V-model document", "give {\"type\": \"trimmed_vmodel\", ...} (vrep boolean writes them)");
  for (auto it = doc.begin(); it != doc.end(); ++it)
    if (it.key() != "type" && it.key() != "region" && it.key() != "cells" && it.key() != "inherited_trivariates" && it.key() != "summary")
      throw ValidationError(where + "." + it.key(), "is not a field of a trimmed V-model document",
                            "remove it (fields: type, region, cells, inherited_trivariates, summary)");
  if (!doc.contains("region")) throw ValidationError(where + ".region", "is missing", "give the model's region");
  TrimmedModel<Rational> M;
  M.region = region_from_json(doc["region"], where + ".region");
  std::vector<BSpline<Rational>> inherited;
  if (doc.contains("inherited_trivariates")) {
    const Json& inh = doc["inherited_trivariates"];
    if (!inh.is_array()) throw ValidationError(where + ".inherited_trivariates", "is not a list", "give a list of trivariate documents");
    for (std::size_t k = 0; k < inh.size(); ++k)
      inherited.push_back(spline_from_json(inh[k], limits, where + ".inherited_trivariates[" + std::to_string(k) + "]"));
  }
  if (!doc.contains("cells") || !doc["cells"].is_array() || doc["cells"].empty())
    throw ValidationError(where + ".cells", "is missing or empty", "give a list of cells");
  const std::size_t n = doc["cells"].size();
  M.trivariates.reserve(n + inherited.size());
  for (std::size_t i = 0; i < n; ++i) {
    const Json& c = doc["cells"][i];
    const std::string w = where + ".cells[" + std::to_string(i) + "]";
    if (!c.is_object() || !c.contains("trivariate")) throw ValidationError(w, "has no \"trivariate\"", "give {\"trivariate\": {...}, \"trim\": region}");
    for (auto it = c.begin(); it != c.end(); ++it)
      if (it.key() != "name" && it.key() != "category" && it.key() != "status" && it.key() != "trivariate" && it.key() != "trim" &&
          it.key() != "inherited" && it.key() != "constants" && it.key() != "fields" && it.key() != "fields_not_carried")
        throw ValidationError(w + "." + it.key(), "is not a field of a trimmed cell",
                              "remove it (fields: name, category, status, trivariate, trim, inherited, constants, fields, fields_not_carried)");
    typename TrimmedModel<Rational>::Cell x;
    x.trivariate = M.trivariates.size();
    M.trivariates.push_back(spline_from_json(c["trivariate"], limits, w + ".trivariate"));
    x.trim = c.contains("trim") ? region_from_json(c["trim"], w + ".trim") : region_and<Rational>({});
    x.name = c.contains("name") && c["name"].is_string() ? c["name"].get<std::string>() : "cell " + std::to_string(i);
    if (c.contains("category") && (!c["category"].is_string() ||
                                   (c["category"] != "A" && c["category"] != "B" && c["category"] != "both" && c["category"] != "")))
      throw ValidationError(w + ".category", c["category"].dump() + " is not a category",
                            "give \"A\", \"B\", \"both\" or \"\" (the operand the cell comes from)");
    x.category = c.contains("category") ? c["category"].get<std::string>() : std::string();
    // The status is recomputed by whoever needs it (vrep volume); a given one is not trusted.
    x.status = Truth::mixed;
    if (c.contains("inherited")) {
      if (!c["inherited"].is_array()) throw ValidationError(w + ".inherited", "is not a list", "give indices into inherited_trivariates");
      for (std::size_t k = 0; k < c["inherited"].size(); ++k)
        x.inherited.push_back(n + static_cast<std::size_t>(json_int(c["inherited"][k], w + ".inherited[" + std::to_string(k) + "]", 0,
                                                                    static_cast<int>(inherited.size()) - 1)));
    }
    if (c.contains("constants")) {
      const Json& k = c["constants"];
      if (!k.is_object()) throw ValidationError(w + ".constants", "is not an object", "give {\"NAME\": [numbers]}");
      for (auto it = k.begin(); it != k.end(); ++it) {
        if (!it.value().is_array()) throw ValidationError(w + ".constants." + it.key(), "is not a list of numbers", "give [numbers]");
        std::vector<Rational> v;
        for (std::size_t e = 0; e < it.value().size(); ++e) v.push_back(json_number(it.value()[e], w + ".constants." + it.key()));
        x.constants[it.key()] = v;
      }
    }
    if (c.contains("fields")) {
      const Json& f = c["fields"];
      if (!f.is_object()) throw ValidationError(w + ".fields", "is not an object", "give {\"NAME\": {trivariate on the cell's domain}}");
      for (auto it = f.begin(); it != f.end(); ++it) {
        auto F = spline_from_json(it.value(), limits, w + ".fields." + it.key());
        require_field_on(M.trivariates[x.trivariate], F, w + ".fields." + it.key(), limits);
        x.fields.emplace(it.key(), std::move(F));
      }
    }
    if (c.contains("fields_not_carried")) x.not_carried = names_from_json(c["fields_not_carried"], w + ".fields_not_carried");
    M.cells.push_back(std::move(x));
  }
  M.trivariates.insert(M.trivariates.end(), inherited.begin(), inherited.end());
  // The cover that piecewise regions (`cases`) claim, at a grid of points over the cells (sampled).
  auto cover = [&](const Region<Rational>& R, const std::string& field) {
    if (const auto gap = cases_cover_gap(R, M.trivariates, 8))
      throw ValidationError(field, "has cases whose pieces do not cover the point (" + to_fraction_string((*gap)[0]) + ", " +
                                       to_fraction_string((*gap)[1]) + ", " + to_fraction_string((*gap)[2]) + ")",
                            "give pieces that cover space (checked at 729 points over the cells)");
  };
  cover(M.region, where + ".region");
  for (std::size_t i = 0; i < M.cells.size(); ++i) cover(M.cells[i].trim, where + ".cells[" + std::to_string(i) + "].trim");
  return M;
}

template <class T>
Json trimmed_to_json(const TrimmedModel<T>& M) {
  Json cells = Json::array(), inherited = Json::array();
  std::map<std::size_t, std::size_t> index;
  std::size_t whole = 0, cut = 0;
  std::map<std::string, std::size_t> categories;
  for (const auto& c : M.cells) {
    Json j{{"name", c.name}, {"category", c.category}, {"status", c.status == Truth::in ? "whole" : "cut"},
           {"trivariate", spline_to_json(M.trivariates[c.trivariate])}, {"trim", region_to_json(c.trim)}};
    (c.status == Truth::in ? whole : cut) += 1;
    categories[c.category.empty() ? "input" : c.category] += 1;
    if (!c.inherited.empty()) {
      Json list = Json::array();
      for (std::size_t t : c.inherited) {
        auto it = index.find(t);
        if (it == index.end()) {
          it = index.emplace(t, inherited.size()).first;
          inherited.push_back(spline_to_json(M.trivariates[t]));
        }
        list.push_back(it->second);
      }
      j["inherited"] = list;
    }
    if (!c.constants.empty()) j["constants"] = constants_to_json(c.constants);
    if (!c.fields.empty()) {
      Json f = Json::object();
      for (const auto& [n, F] : c.fields) f[n] = spline_to_json(F);
      j["fields"] = f;
    }
    if (!c.not_carried.empty()) j["fields_not_carried"] = c.not_carried;
    cells.push_back(j);
  }
  Json out{{"type", "trimmed_vmodel"},
           {"summary", {{"cells", M.cells.size()}, {"whole", whole}, {"cut", cut}, {"categories", categories},
                        {"topology", "not stored: vrep topology computes the cells' V-points, V-curves and half-V-surfaces, vrep topology --glue their gluing into V-surfaces"}}},
           {"region", region_to_json(M.region)},
           {"cells", cells}};
  if (!inherited.empty()) out["inherited_trivariates"] = inherited;
  return out;
}

template Json region_to_json(const Region<Rational>&);
template Json region_to_json(const Region<double>&);
template Json region_to_json(const Region<Mpfr>&);
template Json trimmed_to_json(const TrimmedModel<Rational>&);
template Json trimmed_to_json(const TrimmedModel<double>&);

}  // namespace splinex

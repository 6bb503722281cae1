#include "io/vmodel_io.hpp"

#include <algorithm>
#include <optional>
#include <map>

#include "float/mpfr.hpp"
#include "io/trimmed_io.hpp"

namespace splinex {

VModelCells vmodel_cells_from_json(const Json& doc, const Limits& limits, const std::string& where) {
  check_document_bits(doc, where, limits);
  VModelCells out;
  if (!doc.is_object()) throw ValidationError(where, "is not a JSON object", "give a V-model or trivariate document");
  if (doc.contains("type") && doc["type"] == "trimmed_vmodel")
    throw ValidationError(where, "is a trimmed V-model (cells cut along curved surfaces)",
                          "give it to vrep boolean, volume, classify, export or topology (--glue: its gluing); glue, info and eval need a V-model");
  if (!doc.contains("type") || doc["type"] != "vmodel") {
    out.trivariates.push_back(spline_from_json(doc, limits, where));
    out.names.push_back(where);
    out.inherits.emplace_back();
    return out;
  }
  for (auto it = doc.begin(); it != doc.end(); ++it)
    if (it.key() != "type" && it.key() != "cells" && it.key() != "topology" && it.key() != "surface_attributes" &&
        it.key() != "curve_attributes" && it.key() != "point_attributes" && it.key() != "inherited_trivariates" && it.key() != "implicit")
      throw ValidationError(where + "." + it.key(), "is not a field of a V-model document",
                            "remove it (fields: type, cells, inherited_trivariates, surface_attributes, curve_attributes, point_attributes, "
                            "implicit, topology)");
  if (doc.contains("implicit")) out.region = region_from_json(doc["implicit"], where + ".implicit");
  if (doc.contains("inherited_trivariates")) {
    const Json& inh = doc["inherited_trivariates"];
    if (!inh.is_array()) throw ValidationError(where + ".inherited_trivariates", "is not a list", "give a list of trivariate documents");
    for (std::size_t k = 0; k < inh.size(); ++k)
      out.inherited.push_back(spline_from_json(inh[k], limits, where + ".inherited_trivariates[" + std::to_string(k) + "]"));
  }
  if (!doc.contains("cells") || !doc["cells"].is_array() || doc["cells"].empty())
    throw ValidationError(where + ".cells", "is missing or empty", "give a list of cells {\"name\": ..., \"trivariate\": {...}}");
  for (std::size_t i = 0; i < doc["cells"].size(); ++i) {
    const Json& c = doc["cells"][i];
    const std::string w = where + ".cells[" + std::to_string(i) + "]";
    if (!c.is_object() || !c.contains("trivariate"))
      throw ValidationError(w, "has no \"trivariate\"", "give {\"name\": ..., \"trivariate\": {spline document}}");
    for (auto it = c.begin(); it != c.end(); ++it)
      if (it.key() != "name" && it.key() != "trivariate" && it.key() != "attributes" && it.key() != "inherited" && it.key() != "fields_not_carried")
        throw ValidationError(w + "." + it.key(), "is not a field of a cell",
                              "remove it (fields: name, trivariate, inherited, attributes, fields_not_carried)");
    out.trivariates.push_back(spline_from_json(c["trivariate"], limits, w + ".trivariate"));
    std::vector<std::size_t> inh;
    if (c.contains("inherited")) {
      if (!c["inherited"].is_array()) throw ValidationError(w + ".inherited", "is not a list", "give indices into inherited_trivariates");
      for (std::size_t k = 0; k < c["inherited"].size(); ++k) {
        const int i = json_int(c["inherited"][k], w + ".inherited[" + std::to_string(k) + "]", 0, static_cast<int>(out.inherited.size()) - 1);
        inh.push_back(static_cast<std::size_t>(i));
      }
    }
    out.inherits.push_back(inh);
    out.names.push_back(c.contains("name") && c["name"].is_string() ? c["name"].get<std::string>() : "cell " + std::to_string(i));
  }
  out.attribute_docs.push_back({doc, 0});
  return out;
}

void append_cells(VModelCells& into, VModelCells more) {
  // The union of the documents' regions, known only when every document has one.
  if (into.trivariates.empty()) into.region = std::move(more.region);
  else if (into.region && more.region) into.region = region_or<Rational>({*into.region, *more.region});
  else into.region.reset();
  const std::size_t shift = into.trivariates.size(), ishift = into.inherited.size();
  for (auto& list : more.inherits)
    for (auto& i : list) i += ishift;
  into.inherits.insert(into.inherits.end(), more.inherits.begin(), more.inherits.end());
  into.inherited.insert(into.inherited.end(), more.inherited.begin(), more.inherited.end());
  for (auto& [d, first] : more.attribute_docs) into.attribute_docs.push_back({std::move(d), first + shift});
  into.trivariates.insert(into.trivariates.end(), more.trivariates.begin(), more.trivariates.end());
  into.names.insert(into.names.end(), more.names.begin(), more.names.end());
}

namespace {

std::vector<Rational> numbers(const Json& j, const std::string& where) {
  if (!j.is_array()) throw ValidationError(where, "is not a list of numbers", "give a constant attribute as [numbers]");
  std::vector<Rational> v;
  for (std::size_t i = 0; i < j.size(); ++i) v.push_back(json_number(j[i], where + "[" + std::to_string(i) + "]"));
  return v;
}

std::map<std::string, std::vector<Rational>> constants(const Json& j, const std::string& where) {
  if (!j.is_object()) throw ValidationError(where, "is not an object", "give {\"NAME\": [numbers], ...}");
  std::map<std::string, std::vector<Rational>> out;
  for (auto it = j.begin(); it != j.end(); ++it) out[it.key()] = numbers(it.value(), where + "." + it.key());
  return out;
}

int side_value(const Json& j, const std::string& where) {
  const int s = json_int(j, where, 0, 2);
  if (s > 1) throw ValidationError(where, "must be 0 or 1", "give the side: 0 (start) or 1 (end)");
  return s;
}

std::size_t cell_index(const Json& e, std::size_t first, const VModel<Rational>& M, const std::string& where) {
  if (!e.is_object() || !e.contains("cell")) throw ValidationError(where + ".cell", "is missing", "give the index of the cell");
  const std::size_t c = first + static_cast<std::size_t>(json_int(e["cell"], where + ".cell", 0, 1 << 30));
  if (c >= M.cells.size()) throw ValidationError(where + ".cell", "is not a cell of the document", "give a cell index of this document");
  return c;
}

}  // namespace

std::vector<std::string> names_from_json(const Json& j, const std::string& where) {
  if (!j.is_array()) throw ValidationError(where, "is not a list", "give a list of names");
  std::vector<std::string> out;
  for (const auto& n : j) {
    if (!n.is_string()) throw ValidationError(where, "has an entry that is not a name", "give a list of names");
    out.push_back(n.get<std::string>());
  }
  return out;
}

void apply_attributes(VModel<Rational>& M, const VModelCells& cells, const Limits& limits) {
  // Inherited trivariates (the sources of a Boolean's cells) after the cells' own.
  const std::size_t base = M.trivariates.size();
  M.trivariates.insert(M.trivariates.end(), cells.inherited.begin(), cells.inherited.end());
  for (std::size_t c = 0; c < cells.inherits.size() && c < M.cells.size(); ++c)
    for (std::size_t i : cells.inherits[c]) M.cells[c].trivariates.push_back(base + i);
  for (const auto& [doc, first] : cells.attribute_docs) {
    if (!doc.is_object() || !doc.contains("type") || doc["type"] != "vmodel") continue;
    for (std::size_t i = 0; i < doc["cells"].size(); ++i) {
      const Json& c = doc["cells"][i];
      if (c.contains("fields_not_carried"))
        M.cells[first + i].attributes.not_carried = names_from_json(c["fields_not_carried"], "vmodel.cells[" + std::to_string(i) + "].fields_not_carried");
      if (!c.contains("attributes")) continue;
      const std::string w = "vmodel.cells[" + std::to_string(i) + "].attributes";
      if (!c["attributes"].is_object()) throw ValidationError(w, "is not an object", "give {\"NAME\": [numbers] | {spline}}");
      for (auto it = c["attributes"].begin(); it != c["attributes"].end(); ++it) {
        if (it.value().is_object()) attach_field(M, first + i, it.key(), spline_from_json(it.value(), limits, w + "." + it.key()), limits);
        else M.cells[first + i].attributes.constants[it.key()] = numbers(it.value(), w + "." + it.key());
      }
    }
    auto list = [&](const char* key) -> const Json& {
      static const Json empty = Json::array();
      if (!doc.contains(key)) return empty;
      if (!doc[key].is_array()) throw ValidationError(std::string("vmodel.") + key, "is not a list", "give a list of entries");
      return doc[key];
    };
    // Each entity entry: its cell, its address in the cell (resolved to the entity's attributes),
    // its constants.
    auto each = [&](const char* key, auto&& target) {
      const Json& entries = list(key);
      for (std::size_t k = 0; k < entries.size(); ++k) {
        const Json& e = entries[k];
        const std::string w = std::string("vmodel.") + key + "[" + std::to_string(k) + "]";
        Attributes<Rational>& a = target(e, w, cell_index(e, first, M, w));
        for (auto& [n, v] : constants(e.value("attributes", Json::object()), w + ".attributes")) a.constants[n] = v;
      }
    };
    each("surface_attributes", [&](const Json& e, const std::string& w, std::size_t c) -> Attributes<Rational>& {
      if (!e.contains("face") || !e["face"].is_array() || e["face"].size() != 2)
        throw ValidationError(w + ".face", "is not [direction, side]", "give the face as [0..2, 0|1]");
      return M.surfaces[surface_of_face(M, c, json_int(e["face"][0], w + ".face[0]", 0, 2), side_value(e["face"][1], w + ".face[1]"))]
          .attributes;
    });
    each("curve_attributes", [&](const Json& e, const std::string& w, std::size_t c) -> Attributes<Rational>& {
      if (!e.contains("sides") || !e["sides"].is_array() || e["sides"].size() != 3 || !e.contains("along"))
        throw ValidationError(w, "needs \"along\" and \"sides\": [s0, s1, s2]", "give the edge's direction and the sides of the others");
      std::array<int, 3> sides{};
      for (int d = 0; d < 3; ++d) sides[d] = side_value(e["sides"][d], w + ".sides");
      return M.curves[curve_of_edge(M, c, json_int(e["along"], w + ".along", 0, 2), sides)].attributes;
    });
    each("point_attributes", [&](const Json& e, const std::string& w, std::size_t c) -> Attributes<Rational>& {
      if (!e.contains("corner") || !e["corner"].is_array() || e["corner"].size() != 3)
        throw ValidationError(w + ".corner", "is not [s0, s1, s2]", "give the corner's sides");
      int idx = 0;
      for (int d = 0; d < 3; ++d) idx += side_value(e["corner"][d], w + ".corner") << d;
      return M.points[M.cells[c].corners[idx]].attributes;
    });
  }
}

template <class T>
Json vmodel_to_json(const VModel<T>& M) {
  auto consts = [](const std::map<std::string, std::vector<T>>& m) { return constants_to_json(m); };
  Json cells = Json::array(), inherited = Json::array();
  std::map<std::size_t, std::size_t> inherited_index;  // model trivariate -> position in "inherited_trivariates"
  for (const auto& c : M.cells) {
    Json j{{"name", c.name}, {"trivariate", spline_to_json(M.trivariates[c.trivariates.front()])}};
    if (c.trivariates.size() > 1) {
      Json list = Json::array();
      for (std::size_t k = 1; k < c.trivariates.size(); ++k) {
        auto it = inherited_index.find(c.trivariates[k]);
        if (it == inherited_index.end()) {
          it = inherited_index.emplace(c.trivariates[k], inherited.size()).first;
          inherited.push_back(spline_to_json(M.trivariates[c.trivariates[k]]));
        }
        list.push_back(it->second);
      }
      j["inherited"] = list;
    }
    if (!c.attributes.empty()) {
      Json a = consts(c.attributes.constants);
      for (const auto& [n, F] : c.attributes.fields) a[n] = spline_to_json(F);
      if (!a.empty()) j["attributes"] = a;
      if (!c.attributes.not_carried.empty()) j["fields_not_carried"] = c.attributes.not_carried;
    }
    cells.push_back(j);
  }
  // Entity attributes, addressed by the first cell whose face, edge or corner is the entity.
  Json sattr = Json::array(), cattr = Json::array(), pattr = Json::array();
  for (std::size_t s = 0; s < M.surfaces.size(); ++s)
    if (!M.surfaces[s].attributes.empty()) {
      const auto& h = M.half_surfaces[M.surfaces[s].halves.front()];
      sattr.push_back({{"cell", h.cell}, {"face", {h.dir, h.side}}, {"attributes", consts(M.surfaces[s].attributes.constants)}});
    }
  // The first cell whose edge (corner) is the entity, and which of its edges (corners) it is.
  auto first_in = [&](auto member, std::size_t id) -> std::optional<std::pair<std::size_t, int>> {
    for (std::size_t c = 0; c < M.cells.size(); ++c) {
      const auto& ids = M.cells[c].*member;
      const auto it = std::find(ids.begin(), ids.end(), id);
      if (it != ids.end()) return std::make_pair(c, static_cast<int>(it - ids.begin()));
    }
    return std::nullopt;
  };
  for (std::size_t e = 0; e < M.curves.size(); ++e)
    if (!M.curves[e].attributes.empty())
      if (const auto at = first_in(&VModel<T>::Cell::edges, e)) {
        const int k = at->second, along = k / 4, lo = along == 0 ? 1 : 0, hi = along == 2 ? 1 : 2;
        std::array<int, 3> sides{};
        sides[lo] = k & 1;
        sides[hi] = (k >> 1) & 1;
        cattr.push_back({{"cell", at->first}, {"along", along}, {"sides", sides}, {"attributes", consts(M.curves[e].attributes.constants)}});
      }
  for (std::size_t p = 0; p < M.points.size(); ++p)
    if (!M.points[p].attributes.empty())
      if (const auto at = first_in(&VModel<T>::Cell::corners, p)) {
        const int k = at->second;
        pattr.push_back({{"cell", at->first}, {"corner", {k & 1, (k >> 1) & 1, (k >> 2) & 1}}, {"attributes", consts(M.points[p].attributes.constants)}});
      }
  Json points = Json::array(), curves = Json::array(), surfaces = Json::array(), halves = Json::array();
  for (const auto& p : M.points) {
    Json at = Json::array();
    for (const auto& x : p.at) at.push_back(ArithTraits<T>::to_json(x));
    points.push_back({{"at", at}, {"curves", p.curves}});
  }
  for (const auto& c : M.curves) curves.push_back({{"ends", c.ends}, {"surfaces", c.surfaces}});
  for (const auto& s : M.surfaces) surfaces.push_back({{"halves", s.halves}});
  for (const auto& h : M.half_surfaces) {
    Json j{{"cell", h.cell}, {"face", {{"direction", h.dir}, {"side", h.side}}}, {"surface", h.surface}, {"loop", h.loop}};
    j["twin"] = h.twin ? Json(*h.twin) : Json(nullptr);
    halves.push_back(j);
  }
  const auto chk = check_invariants(M);
  Json out{{"type", "vmodel"},
              {"cells", cells},
              {"topology",
               {{"counts",
                 {{"cells", M.cells.size()},
                  {"half_surfaces", M.half_surfaces.size()},
                  {"surfaces", M.surfaces.size()},
                  {"internal_surfaces", M.internal_surfaces()},
                  {"curves", M.curves.size()},
                  {"points", M.points.size()}}},
                {"euler_characteristic", M.euler_characteristic()},
                {"invariants", chk.ok() ? Json("hold") : Json(chk.failures)},
                {"points", points},
                {"curves", curves},
                {"surfaces", surfaces},
                {"half_surfaces", halves}}}};
  if (!inherited.empty()) out["inherited_trivariates"] = inherited;
  if (!sattr.empty()) out["surface_attributes"] = sattr;
  if (!cattr.empty()) out["curve_attributes"] = cattr;
  if (!pattr.empty()) out["point_attributes"] = pattr;
  return out;
}

template Json vmodel_to_json(const VModel<Rational>&);
template Json vmodel_to_json(const VModel<double>&);
template Json vmodel_to_json(const VModel<Mpfr>&);

}  // namespace splinex

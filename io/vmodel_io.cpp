#include "io/vmodel_io.hpp"

#include "float/mpfr.hpp"

namespace splinex {

VModelCells vmodel_cells_from_json(const Json& doc, const Limits& limits, const std::string& where) {
  VModelCells out;
  if (!doc.is_object()) throw ValidationError(where, "is not a JSON object", "give a V-model or trivariate document");
  if (!doc.contains("type") || doc["type"] != "vmodel") {
    out.trivariates.push_back(spline_from_json(doc, limits, where));
    out.names.push_back(where);
    return out;
  }
  for (auto it = doc.begin(); it != doc.end(); ++it)
    if (it.key() != "type" && it.key() != "cells" && it.key() != "topology")
      throw ValidationError(where + "." + it.key(), "is not a field of a V-model document", "remove it (fields: type, cells, topology)");
  if (!doc.contains("cells") || !doc["cells"].is_array() || doc["cells"].empty())
    throw ValidationError(where + ".cells", "is missing or empty", "give a list of cells {\"name\": ..., \"trivariate\": {...}}");
  for (std::size_t i = 0; i < doc["cells"].size(); ++i) {
    const Json& c = doc["cells"][i];
    const std::string w = where + ".cells[" + std::to_string(i) + "]";
    if (!c.is_object() || !c.contains("trivariate"))
      throw ValidationError(w, "has no \"trivariate\"", "give {\"name\": ..., \"trivariate\": {spline document}}");
    for (auto it = c.begin(); it != c.end(); ++it)
      if (it.key() != "name" && it.key() != "trivariate")
        throw ValidationError(w + "." + it.key(), "is not a field of a cell", "remove it (fields: name, trivariate)");
    out.trivariates.push_back(spline_from_json(c["trivariate"], limits, w + ".trivariate"));
    out.names.push_back(c.contains("name") && c["name"].is_string() ? c["name"].get<std::string>() : "cell " + std::to_string(i));
  }
  return out;
}

template <class T>
Json vmodel_to_json(const VModel<T>& M) {
  Json cells = Json::array();
  for (const auto& c : M.cells) cells.push_back({{"name", c.name}, {"trivariate", spline_to_json(M.trivariates[c.trivariates.front()])}});
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
  return Json{{"type", "vmodel"},
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
}

template Json vmodel_to_json(const VModel<Rational>&);
template Json vmodel_to_json(const VModel<double>&);
template Json vmodel_to_json(const VModel<Mpfr>&);

}  // namespace splinex

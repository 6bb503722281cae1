#include "io/cut_io.hpp"

#include "spline/errors.hpp"

namespace splinex {

namespace {
void only_fields(const Json& doc, std::initializer_list<const char*> names, const std::string& where, const std::string& fix) {
  for (auto it = doc.begin(); it != doc.end(); ++it) {
    bool ok = false;
    for (const char* n : names) ok = ok || it.key() == n;
    if (!ok) throw ParseError(where + it.key(), "is not a field here", fix);
  }
}
}  // namespace

Solid2<Rational> solid2_from_json(const Json& doc, const Limits& limits) {
  if (!doc.is_object()) throw ParseError("document", "is not an object", "give {\"type\": \"solid2d\", \"facets\": [...]}");
  if (!doc.contains("type") || doc["type"] != "solid2d") throw ParseError("type", "must be \"solid2d\"", "set \"type\": \"solid2d\"");
  only_fields(doc, {"type", "facets", "description"}, "", "use type, facets (and description)");
  if (!doc.contains("facets") || !doc["facets"].is_array()) throw ParseError("facets", "must be an array of spline documents", "give the boundary curves in order");
  if (doc["facets"].size() > 100000) throw SizeLimitError("facets", "has more than 100000 facets", "give fewer facets");
  Solid2<Rational> S;
  for (std::size_t i = 0; i < doc["facets"].size(); ++i)
    S.facets.push_back(spline_from_json(doc["facets"][i], limits, "facets[" + std::to_string(i) + "]"));
  validate_solid(S);
  return S;
}

CutData2<Rational> cut2_from_json(const Json& doc) {
  if (!doc.is_object()) throw ParseError("document", "is not an object", "give {\"type\": \"cut2d\", \"points\": [...]}");
  if (!doc.contains("type") || doc["type"] != "cut2d") throw ParseError("type", "must be \"cut2d\"", "set \"type\": \"cut2d\"");
  only_fields(doc, {"type", "points", "description"}, "", "use type, points (and description)");
  if (!doc.contains("points") || !doc["points"].is_array() || doc["points"].size() != 2)
    throw ParseError("points", "must be an array of two points", "give the cutting curve's two end points");
  CutData2<Rational> C;
  for (int e = 0; e < 2; ++e) {
    const auto& p = doc["points"][e];
    const std::string f = "points[" + std::to_string(e) + "]";
    if (!p.is_object()) throw ParseError(f, "is not an object", "give {\"facet\": i, \"parameter\": s, \"tangent\": [tx, ty]}");
    only_fields(p, {"facet", "parameter", "tangent"}, f + ".", "use facet, parameter, tangent");
    if (!p.contains("facet") || !p.contains("parameter") || !p.contains("tangent"))
      throw ParseError(f, "lacks facet, parameter or tangent", "give {\"facet\": i, \"parameter\": s, \"tangent\": [tx, ty]}");
    C.ends[e].facet = static_cast<std::size_t>(json_int(p["facet"], f + ".facet", 0, 1 << 30));
    C.ends[e].param = json_number(p["parameter"], f + ".parameter");
    if (!p["tangent"].is_array() || p["tangent"].size() != 2) throw ParseError(f + ".tangent", "must be [tx, ty]", "give two numbers");
    C.ends[e].tangent = {json_number(p["tangent"][0], f + ".tangent[0]"), json_number(p["tangent"][1], f + ".tangent[1]")};
  }
  return C;
}

Json solid2_to_json(const Solid2<Rational>& S) {
  Json f = Json::array();
  for (const auto& F : S.facets) f.push_back(spline_to_json(F));
  return Json{{"type", "solid2d"}, {"facets", f}};
}

Json cut2_to_json(const CutData2<Rational>& C) {
  Json pts = Json::array();
  for (const auto& e : C.ends)
    pts.push_back(Json{{"facet", e.facet},
                       {"parameter", ArithTraits<Rational>::to_json(e.param)},
                       {"tangent", Json::array({ArithTraits<Rational>::to_json(e.tangent[0]), ArithTraits<Rational>::to_json(e.tangent[1])})}});
  return Json{{"type", "cut2d"}, {"points", pts}};
}

}  // namespace splinex

#include "io/cut_io.hpp"

#include <algorithm>
#include <iomanip>
#include <sstream>

#include "base/errors.hpp"
#include "spline/bezier.hpp"
#include "spline/evaluate.hpp"

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
  check_document_bits(doc, "solid", limits);
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


std::string solid_document_type(const Json& doc) {
  if (doc.is_object() && doc.contains("type") && (doc["type"] == "solid2d" || doc["type"] == "solid3d")) return doc["type"].get<std::string>();
  throw ParseError("type", "must be \"solid2d\" or \"solid3d\"", "give a solid document (splinex cut example writes both kinds)");
}

Solid3<Rational> solid3_from_json(const Json& doc, const Limits& limits) {
  check_document_bits(doc, "solid", limits);
  if (!doc.is_object()) throw ParseError("document", "is not an object", "give {\"type\": \"solid3d\", \"facets\": [...]}");
  if (!doc.contains("type") || doc["type"] != "solid3d") throw ParseError("type", "must be \"solid3d\"", "set \"type\": \"solid3d\"");
  only_fields(doc, {"type", "facets", "description"}, "", "use type, facets (and description)");
  if (!doc.contains("facets") || !doc["facets"].is_array()) throw ParseError("facets", "must be an array of spline documents", "give the boundary surfaces");
  if (doc["facets"].size() > 20000) throw SizeLimitError("facets", "has more than 20000 facets", "give fewer facets");
  Solid3<Rational> S;
  for (std::size_t i = 0; i < doc["facets"].size(); ++i)
    S.facets.push_back(spline_from_json(doc["facets"][i], limits, "facets[" + std::to_string(i) + "]"));
  validate_solid(S);
  return S;
}

CutData3 cut3_from_json(const Json& doc) {
  if (!doc.is_object()) throw ParseError("document", "is not an object", "give {\"type\": \"cut3d\", \"positive\": [...], \"tangents\": [...]}");
  if (!doc.contains("type") || doc["type"] != "cut3d") throw ParseError("type", "must be \"cut3d\"", "set \"type\": \"cut3d\" (a solid3d needs 3D cutting data)");
  only_fields(doc, {"type", "positive", "tangents", "description"}, "", "use type, positive, tangents (and description)");
  if (!doc.contains("positive") || !doc["positive"].is_array()) throw ParseError("positive", "must be an array of facet indices", "name the facets of b");
  if (!doc.contains("tangents") || !doc["tangents"].is_array()) throw ParseError("tangents", "must be an array", "give one tangent per loop side");
  if (doc["positive"].size() > 20000 || doc["tangents"].size() > 80000) throw SizeLimitError("positive", "is too long", "give fewer facets");
  CutData3 C;
  for (std::size_t k = 0; k < doc["positive"].size(); ++k)
    C.positive.push_back(static_cast<std::size_t>(json_int(doc["positive"][k], "positive[" + std::to_string(k) + "]", 0, 1 << 30)));
  for (std::size_t k = 0; k < doc["tangents"].size(); ++k) {
    const auto& t = doc["tangents"][k];
    const std::string f = "tangents[" + std::to_string(k) + "]";
    if (!t.is_object()) throw ParseError(f, "is not an object", "give {\"facet\": i, \"side\": s, \"tangent\": [tx, ty, tz]}");
    only_fields(t, {"facet", "side", "tangent"}, f + ".", "use facet, side, tangent");
    if (!t.contains("facet") || !t.contains("side") || !t.contains("tangent"))
      throw ParseError(f, "lacks facet, side or tangent", "give {\"facet\": i, \"side\": s, \"tangent\": [tx, ty, tz]}");
    LoopTangent3 L;
    L.facet = static_cast<std::size_t>(json_int(t["facet"], f + ".facet", 0, 1 << 30));
    L.side = static_cast<int>(json_int(t["side"], f + ".side", 0, 3));
    if (!t["tangent"].is_array() || t["tangent"].size() != 3) throw ParseError(f + ".tangent", "must be [tx, ty, tz]", "give three numbers");
    for (int c = 0; c < 3; ++c) L.tangent[c] = json_number(t["tangent"][c], f + ".tangent[" + std::to_string(c) + "]");
    C.tangents.push_back(L);
  }
  return C;
}

Json solid3_to_json(const Solid3<Rational>& S) {
  Json f = Json::array();
  for (const auto& F : S.facets) f.push_back(spline_to_json(F));
  return Json{{"type", "solid3d"}, {"facets", f}};
}

Json cut3_to_json(const CutData3& C) {
  Json t = Json::array();
  for (const auto& L : C.tangents) {
    Json v = Json::array();
    for (const auto& x : L.tangent) v.push_back(ArithTraits<Rational>::to_json(x));
    t.push_back(Json{{"facet", L.facet}, {"side", L.side}, {"tangent", v}});
  }
  return Json{{"type", "cut3d"}, {"positive", C.positive}, {"tangents", t}};
}


std::string solid3_vtk(const Solid3<Rational>& S) {
  constexpr int m = 8;
  std::ostringstream pts, polys;
  pts << std::setprecision(17);
  std::size_t np = 0, nq = 0;
  for (const auto& F : S.facets)
    for (const auto& piece : extract_bezier(F)) {
      const auto D = convert<double>(piece.spline, [](const Rational& x) { return to_double(x); });
      const std::size_t base = np;
      for (int j = 0; j <= m; ++j)
        for (int i = 0; i <= m; ++i) {
          const double u = D.domain_lo(0) + (D.domain_hi(0) - D.domain_lo(0)) * i / m, v = D.domain_lo(1) + (D.domain_hi(1) - D.domain_lo(1)) * j / m;
          const auto p = evaluate(D, std::vector<double>{u, v});
          pts << p[0] << " " << p[1] << " " << p[2] << "\n";
          ++np;
        }
      for (int j = 0; j < m; ++j)
        for (int i = 0; i < m; ++i) {
          const std::size_t a = base + i + (m + 1) * j;
          polys << "4 " << a << " " << a + 1 << " " << a + m + 2 << " " << a + m + 1 << "\n";
          ++nq;
        }
    }
  std::ostringstream o;
  o << "# vtk DataFile Version 3.0\nsplinex solid3d facets (tessellated in double)\nASCII\nDATASET POLYDATA\nPOINTS " << np << " double\n"
    << pts.str() << "POLYGONS " << nq << " " << 5 * nq << "\n" << polys.str();
  return o.str();
}

CuttingSurfaceDoc cutting_surface_from_json(const Json& doc, const Limits& limits) {
  check_document_bits(doc, "surface", limits);
  if (!doc.is_object() || !doc.contains("type") || doc["type"] != "cutting_surface")
    throw ParseError("type", "must be \"cutting_surface\"", "give {\"type\": \"cutting_surface\", \"patch\": {...}, \"domain\": [[u, v], ...]}");
  only_fields(doc, {"type", "patch", "domain", "description"}, "", "use type, patch, domain (and description)");
  if (!doc.contains("patch")) throw ParseError("patch", "is missing", "give the patch as a spline document");
  if (!doc.contains("domain") || !doc["domain"].is_array() || doc["domain"].size() < 3)
    throw ParseError("domain", "must be an array of 3 or more [u, v] vertices", "give Omega's vertices, one per loop side");
  if (doc["domain"].size() > 100000) throw SizeLimitError("domain", "has more than 100000 vertices", "give fewer");
  CuttingSurfaceDoc d;
  d.patch = spline_from_json(doc["patch"], limits, "patch");
  if (d.patch.dim() != 2 || d.patch.q != 3 || d.patch.is_rational())
    throw ParseError("patch", "must be a polynomial surface in R^3 (2 parameters, 3 coordinates, no weights)", "give a tensor-product B-spline surface");
  for (std::size_t k = 0; k < doc["domain"].size(); ++k) {
    const auto& v = doc["domain"][k];
    const std::string f = "domain[" + std::to_string(k) + "]";
    if (!v.is_array() || v.size() != 2) throw ParseError(f, "must be [u, v]", "give two numbers");
    d.domain.push_back({json_number(v[0], f + "[0]"), json_number(v[1], f + "[1]")});
  }
  return d;
}

Json cutting_surface_to_json(const BSpline<Rational>& patch, const std::vector<std::array<Rational, 2>>& domain) {
  Json v = Json::array();
  for (const auto& w : domain) v.push_back(Json::array({to_fraction_string(w[0]), to_fraction_string(w[1])}));
  return Json{{"type", "cutting_surface"}, {"patch", spline_to_json(patch)}, {"domain", v}};
}

std::string surface3_vtk(const BSpline<Rational>& patch, const std::vector<std::array<Rational, 2>>& domain, int n) {
  const auto D = convert<double>(patch, [](const Rational& x) { return to_double(x); });
  std::vector<std::array<double, 2>> poly;
  for (const auto& w : domain) poly.push_back({to_double(w[0]), to_double(w[1])});
  auto inside = [&](double u, double v) {  // crossing number (display only)
    bool in = false;
    for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++)
      if ((poly[i][1] > v) != (poly[j][1] > v) && u < (poly[j][0] - poly[i][0]) * (v - poly[i][1]) / (poly[j][1] - poly[i][1]) + poly[i][0]) in = !in;
    return in;
  };
  double lo[2] = {poly[0][0], poly[0][1]}, hi[2] = {poly[0][0], poly[0][1]};
  for (const auto& p : poly)
    for (int k = 0; k < 2; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
  std::ostringstream pts, polys, lines;
  pts << std::setprecision(17);
  std::size_t np = 0, nq = 0;
  std::vector<long> id((n + 1) * (n + 1), -1);
  auto point = [&](double u, double v) {
    const auto p = evaluate(D, std::vector<double>{u, v});
    pts << p[0] << " " << p[1] << " " << p[2] << "\n";
    return np++;
  };
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double u = lo[0] + (hi[0] - lo[0]) * i / n, v = lo[1] + (hi[1] - lo[1]) * j / n;
      if (inside(u, v)) id[i + (n + 1) * j] = static_cast<long>(point(u, v));
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const long a = id[i + (n + 1) * j], b = id[i + 1 + (n + 1) * j], c = id[i + 1 + (n + 1) * (j + 1)], d = id[i + (n + 1) * (j + 1)];
      if (a < 0 || b < 0 || c < 0 || d < 0) continue;
      polys << "4 " << a << " " << b << " " << c << " " << d << "\n";
      ++nq;
    }
  constexpr int m = 16;
  const std::size_t first = np;
  for (std::size_t e = 0; e < poly.size(); ++e)
    for (int k = 0; k < m; ++k) {
      const auto &a = poly[e], &b = poly[(e + 1) % poly.size()];
      point(a[0] + (b[0] - a[0]) * k / m, a[1] + (b[1] - a[1]) * k / m);
    }
  const std::size_t nl = np - first;
  lines << nl + 1;
  for (std::size_t k = 0; k < nl; ++k) lines << " " << first + k;
  lines << " " << first << "\n";
  std::ostringstream o;
  o << "# vtk DataFile Version 3.0\nsplinex cutting surface (trimmed patch, tessellated in double)\nASCII\nDATASET POLYDATA\nPOINTS " << np << " double\n"
    << pts.str() << "POLYGONS " << nq << " " << 5 * nq << "\n" << polys.str() << "LINES 1 " << nl + 2 << "\n" << lines.str();
  return o.str();
}

std::string guide3_vtk(const BSpline<Rational>& f, const std::array<Rational, 3>& lo, const Rational& scale, int n) {
  const auto D = convert<double>(f, [](const Rational& x) { return to_double(x); });
  std::ostringstream o;
  o << std::setprecision(17);
  const double h = to_double(scale) / n;
  o << "# vtk DataFile Version 3.0\nsplinex guiding surface f* (values in double; contour at 0)\nASCII\nDATASET STRUCTURED_POINTS\n"
    << "DIMENSIONS " << n + 1 << " " << n + 1 << " " << n + 1 << "\nORIGIN " << to_double(lo[0]) << " " << to_double(lo[1]) << " " << to_double(lo[2])
    << "\nSPACING " << h << " " << h << " " << h << "\nPOINT_DATA " << (n + 1) * (n + 1) * (n + 1) << "\nSCALARS f double 1\nLOOKUP_TABLE default\n";
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i)
        o << evaluate(D, std::vector<double>{double(i) / n, double(j) / n, double(k) / n})[0] << "\n";
  return o.str();
}

}  // namespace splinex

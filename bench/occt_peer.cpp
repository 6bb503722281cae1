// occt_peer: OpenCASCADE's B-spline operations as a candidate program for `splinex verify`
// (issue 16, part 3). One JSON object per line on stdin:
//   {"op": "insert" | "elevate" | "eval", "degree": p, "knots": [flat knot vector], "points": [[x, y, ...]],
//    "weights": [...] (optional: a rational curve), "u": knot to insert (insert), "xs": [parameters] (eval)}
// and one per line on stdout: {"degree": p, "knots": [...], "points": [[...]], "weights" when rational}
// (insert, elevate),
// {"values": [[...]]} (eval) or {"failure": "what OCCT said"}. Numbers are doubles printed with 17
// significant digits (they read back to the same double).
//
// OpenCASCADE (Geom_BSplineCurve, 7.6 in Debian 12) as a CAD kernel is used: the flat knot vector
// is grouped into distinct knots and multiplicities, points padded to 3D (more coordinates run in
// chunks of 3); InsertKnot(u) with its
// default tolerance 0, IncreaseDegree(p + 1), D0(x). Only in-place modifiers exist, so each
// operation works on a fresh curve.
#include <Geom_BSplineCurve.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

using Json = nlohmann::json;

namespace {

double num(const Json& j) { return j.is_string() ? std::stod(j.get<std::string>()) : j.get<double>(); }

std::string g17(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

/// The operation on coordinates [c0, c0 + q) of the points (q <= 3: OCCT's curves are in 3D).
Json run_chunk(const Json& in, int c0, int q) {
  const std::string op = in.at("op");
  const int p = in.at("degree");
  std::vector<double> flat;
  for (const auto& u : in.at("knots")) flat.push_back(num(u));
  const auto& P = in.at("points");
  const int n = static_cast<int>(P.size());
  std::vector<double> kv;
  std::vector<int> km;
  for (double u : flat) {
    if (!kv.empty() && kv.back() == u) ++km.back();
    else {
      kv.push_back(u);
      km.push_back(1);
    }
  }
  TColgp_Array1OfPnt poles(1, n);
  for (int i = 0; i < n; ++i) {
    double c[3] = {0, 0, 0};
    for (int k = 0; k < q; ++k) c[k] = num(P[i][c0 + k]);
    poles.SetValue(i + 1, gp_Pnt(c[0], c[1], c[2]));
  }
  TColStd_Array1OfReal knots(1, static_cast<int>(kv.size()));
  TColStd_Array1OfInteger mults(1, static_cast<int>(kv.size()));
  for (std::size_t i = 0; i < kv.size(); ++i) {
    knots.SetValue(static_cast<int>(i) + 1, kv[i]);
    mults.SetValue(static_cast<int>(i) + 1, km[i]);
  }
  Handle(Geom_BSplineCurve) c;
  if (in.contains("weights")) {
    TColStd_Array1OfReal weights(1, n);
    for (int i = 0; i < n; ++i) weights.SetValue(i + 1, num(in["weights"][i]));
    c = new Geom_BSplineCurve(poles, weights, knots, mults, p);
  } else {
    c = new Geom_BSplineCurve(poles, knots, mults, p);
  }
  auto coords = [q](const gp_Pnt& x) {
    Json r = Json::array();
    const double c3[3] = {x.X(), x.Y(), x.Z()};
    for (int k = 0; k < q; ++k) r.push_back(g17(c3[k]));
    return r;
  };
  if (op == "eval") {
    Json vals = Json::array();
    for (const auto& x : in.at("xs")) {
      gp_Pnt v;
      c->D0(num(x), v);
      vals.push_back(coords(v));
    }
    return Json{{"values", vals}};
  }
  if (op == "insert") c->InsertKnot(num(in.at("u")));
  else if (op == "elevate") c->IncreaseDegree(p + 1);
  else return Json{{"failure", "unknown op " + op}};
  Json out{{"degree", c->Degree()}};
  TColStd_Array1OfReal seq(1, c->NbPoles() + c->Degree() + 1);
  c->KnotSequence(seq);
  Json K = Json::array(), Pts = Json::array();
  for (int i = seq.Lower(); i <= seq.Upper(); ++i) K.push_back(g17(seq(i)));
  for (int i = 1; i <= c->NbPoles(); ++i) Pts.push_back(coords(c->Pole(i)));
  out["knots"] = K;
  out["points"] = Pts;
  if (in.contains("weights")) {  // also when OCCT found the weights all equal and dropped them (Weight(i) is 1 then)
    Json W = Json::array();
    for (int i = 1; i <= c->NbPoles(); ++i) W.push_back(g17(c->Weight(i)));
    out["weights"] = W;
  }
  return out;
}

/// Points with more than 3 coordinates run in chunks of 3 (the knot operations act on each
/// coordinate alike; the chunks' knots must agree) and are stitched back together.
Json run(const Json& in) {
  const int q = static_cast<int>(in.at("points").at(0).size());
  Json out;
  for (int c0 = 0; c0 < q; c0 += 3) {
    Json part = run_chunk(in, c0, std::min(3, q - c0));
    if (part.contains("failure")) return part;
    if (c0 == 0) {
      out = part;
      continue;
    }
    const char* rows = part.contains("values") ? "values" : "points";
    if (part.contains("knots") && part["knots"] != out["knots"]) return Json{{"failure", "coordinate chunks got different knots"}};
    for (std::size_t i = 0; i < part[rows].size(); ++i)
      for (const auto& v : part[rows][i]) out[rows][i].push_back(v);
  }
  return out;
}

}  // namespace

int main() {
  std::string line;
  while (std::getline(std::cin, line)) {
    if (line.empty()) continue;
    Json out;
    try {
      out = run(Json::parse(line));
    } catch (const Standard_Failure& e) {
      out = Json{{"failure", std::string(e.DynamicType()->Name()) + ": " + (e.GetMessageString() ? e.GetMessageString() : "")}};
    } catch (const std::exception& e) {
      out = Json{{"failure", e.what()}};
    }
    std::cout << out.dump() << std::endl;
  }
  return 0;
}

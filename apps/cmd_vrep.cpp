// splinex vrep: volumetric models of papers/002 - the trivariate constructors and certified
// regularity (vrep/). The V-model itself (cells, gluing, primitives, export) is not built yet.
#include <iostream>
#include <memory>

#include "apps/command.hpp"
#include "float/arith_spec.hpp"
#include "float/mpfr.hpp"
#include "float/rounding.hpp"
#include "vrep/regularity.hpp"
#include "vrep/trivariate.hpp"

namespace splinex::app {

namespace {

struct ConstructOptions {
  std::string kind, arith = "exact", surface, first, second, faces, surfaces, vector, at, axis = "z";
  int quarters = 4, degree = 3;
};

BSpline<Rational> read_spline(const std::string& path, const std::string& field, const Context& ctx) {
  return spline_from_json(read_json_file(path, ctx.read_limits), ctx.limits, field);
}

std::vector<std::string> split_list(const std::string& text) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = text.find(',', start);
    out.push_back(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

Json construct(const ConstructOptions& o, const Context& ctx) {
  const auto spec = ArithSpec::parse(o.arith);
  auto need = [](const std::string& value, const std::string& field, const std::string& kind) {
    if (value.empty()) throw UsageError(field, "vrep construct " + kind + " needs --" + field, "give --" + field);
  };
  if (o.kind == "extrude") {
    need(o.surface, "surface", o.kind);
    need(o.vector, "vector", o.kind);
    const auto S = read_spline(o.surface, "surface", ctx);
    const auto V = parse_number_list(o.vector, "vector");
    return with_arith_except_flint(spec, "vrep construct", [&](auto tag) {
      using F = typename decltype(tag)::type;
      std::vector<F> v;
      for (const auto& x : V) v.push_back(round_checked<F>(x, "vector"));
      return spline_to_json(extrude(round_spline<F>(S, "surface"), v, ctx.limits));
    });
  }
  if (o.kind == "ruled") {
    need(o.first, "first", o.kind);
    need(o.second, "second", o.kind);
    const auto A = read_spline(o.first, "first", ctx), B = read_spline(o.second, "second", ctx);
    return with_arith_except_flint(spec, "vrep construct", [&](auto tag) {
      using F = typename decltype(tag)::type;
      return spline_to_json(ruled(round_spline<F>(A, "first"), round_spline<F>(B, "second"), ctx.limits));
    });
  }
  if (o.kind == "revolve") {
    need(o.surface, "surface", o.kind);
    const auto S = read_spline(o.surface, "surface", ctx);
    const int axis = o.axis == "x" ? 0 : o.axis == "y" ? 1 : 2;
    return with_arith_except_flint(spec, "vrep construct", [&](auto tag) {
      using F = typename decltype(tag)::type;
      return spline_to_json(revolve(round_spline<F>(S, "surface"), axis, o.quarters, ctx.limits));
    });
  }
  if (o.kind == "boolean-sum") {
    need(o.faces, "faces", o.kind);
    const auto files = split_list(o.faces);
    if (files.size() != 6)
      throw UsageError("faces", "needs six files, got " + std::to_string(files.size()), "give --faces u0,u1,v0,v1,w0,w1");
    const char* names[6] = {"u0", "u1", "v0", "v1", "w0", "w1"};
    std::array<std::array<BSpline<Rational>, 2>, 3> F;
    for (int k = 0; k < 6; ++k) F[k / 2][k % 2] = read_spline(files[k], names[k], ctx);
    return with_arith_except_flint(spec, "vrep construct", [&](auto tag) {
      using T = typename decltype(tag)::type;
      std::array<std::array<BSpline<T>, 2>, 3> G;
      for (int k = 0; k < 6; ++k) G[k / 2][k % 2] = round_spline<T>(F[k / 2][k % 2], names[k]);
      return spline_to_json(boolean_sum(G, ctx.limits));
    });
  }
  // sweep
  need(o.surfaces, "surfaces", o.kind);
  need(o.at, "at", o.kind);
  std::vector<BSpline<Rational>> S;
  const auto files = split_list(o.surfaces);
  for (std::size_t k = 0; k < files.size(); ++k) S.push_back(read_spline(files[k], "surfaces[" + std::to_string(k) + "]", ctx));
  const auto at = parse_number_list(o.at, "at");
  return with_arith_except_flint(spec, "vrep construct", [&](auto tag) {
    using F = typename decltype(tag)::type;
    std::vector<BSpline<F>> s;
    for (std::size_t k = 0; k < S.size(); ++k) s.push_back(round_spline<F>(S[k], "surfaces[" + std::to_string(k) + "]"));
    std::vector<F> w;
    for (const auto& x : at) w.push_back(round_checked<F>(x, "at"));
    return spline_to_json(sweep(s, w, o.degree, ctx.limits));
  });
}

template <class F>
Json report_to_json(const RegularityReport<F>& r) {
  auto point = [](const std::vector<F>& x) {
    Json a = Json::array();
    for (const auto& v : x) a.push_back(ArithTraits<F>::to_json(v));
    return a;
  };
  Json j{{"verdict", to_string(r.verdict)}, {"reason", r.reason}, {"levels", r.levels}, {"boxes", r.boxes}};
  if (r.verdict == Regularity::regular) j["sign"] = r.sign;
  if (!r.point.empty()) j["point"] = point(r.point);
  if (r.verdict == Regularity::singular) {
    j["det_numerator_at_point"] = ArithTraits<F>::to_json(r.value);
    if (!r.other.empty()) {
      j["other"] = point(r.other);
      j["det_numerator_at_other"] = ArithTraits<F>::to_json(r.other_value);
    }
  }
  return j;
}

}  // namespace

Commands add_vrep(CLI::App& app) {
  auto* v = app.add_subcommand("vrep", "volumetric models (papers/002): trivariate constructors, certified regularity");
  v->require_subcommand(1);
  auto o = std::make_shared<ConstructOptions>();
  auto* c = v->add_subcommand("construct", "a trivariate from surfaces: extrude, ruled, revolve, boolean-sum or sweep");
  c->add_option("kind", o->kind, "extrude, ruled, revolve, boolean-sum or sweep")
      ->required()
      ->check(CLI::IsMember({"extrude", "ruled", "revolve", "boolean-sum", "sweep"}));
  add_arith_option(c, o->arith, "exact (GMP), double or mpfr:BITS");
  c->add_option("--surface", o->surface, "extrude, revolve: the surface document (points in R^3, attributes after)");
  c->add_option("--vector", o->vector, "extrude: the vector V, comma-separated (one entry per point coordinate)");
  c->add_option("--first", o->first, "ruled: the surface at w = 0");
  c->add_option("--second", o->second, "ruled: the surface at w = 1");
  c->add_option("--axis", o->axis, "revolve: the coordinate axis")->check(CLI::IsMember({"x", "y", "z"}))->capture_default_str();
  c->add_option("--quarters", o->quarters, "revolve: the angle in quarter turns (exact rational circle arcs)")
      ->check(CLI::Range(1, 4))
      ->capture_default_str();
  c->add_option("--faces", o->faces, "boolean-sum: six surface files u0,u1,v0,v1,w0,w1 (u faces in (v, w), v faces in (u, w), "
                                     "w faces in (u, v))");
  c->add_option("--surfaces", o->surfaces, "sweep: the surface files S_0,...,S_m");
  c->add_option("--at", o->at, "sweep: the parameters w_0 < ... < w_m, comma-separated");
  c->add_option("--degree", o->degree, "sweep: the degree in w (at most m)")->check(CLI::Range(1, 64))->capture_default_str();

  struct CertifyOptions {
    std::string arith = "exact", file;
    int levels = 6;
  };
  auto co = std::make_shared<CertifyOptions>();
  auto* cert = v->add_subcommand("certify", "certified regularity of a trivariate: the sign of det J from exact Bernstein coefficients");
  add_arith_option(cert, co->arith, "exact (GMP) decides exactly; double or mpfr:BITS run the same test in floats");
  cert->add_option("file", co->file, "the trivariate document")->required();
  cert->add_option("--levels", co->levels, "subdivision levels before \"undecided\"")->check(CLI::Range(0, 12))->capture_default_str();
  return {{c, [o](const Context& ctx) {
             std::cout << construct(*o, ctx).dump() << "\n";
             return 0;
           }},
          {cert, [co](const Context& ctx) {
             const auto V = read_spline(co->file, "trivariate", ctx);
             const auto spec = ArithSpec::parse(co->arith);
             const Json j = with_arith_except_flint(spec, "vrep certify", [&](auto tag) {
               using F = typename decltype(tag)::type;
               return report_to_json(certify_regularity(round_spline<F>(V, "trivariate"), co->levels, ctx.limits));
             });
             std::cout << j.dump(2) << "\n";
             return 0;
           }}};
}

}  // namespace splinex::app

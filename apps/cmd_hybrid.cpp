// splinex hybrid eval | example: the hybrid multi-sided patch with B-spline boundaries (papers/003).
#include <iostream>
#include <memory>

#include "apps/command.hpp"
#include "fixtures/hybrid_examples.hpp"
#include "float/arith_spec.hpp"
#include "hybrid/hybrid.hpp"
#include "io/hybrid_io.hpp"

namespace splinex::app {

namespace {

struct Options {
  std::string arith = "exact", file, example;
  std::vector<std::string> at;
};

int run_example(const Options& o) {
  HybridPatch<Rational> P;
  if (o.example == "2.1") P = hybrid_example_2_1();
  else if (o.example == "3.1-hexagon") P = hybrid_example_3_1_hexagon();
  else if (o.example == "3.1-octagon") P = hybrid_example_3_1_octagon();
  else throw UsageError("NAME", "is not an example: " + o.example, "use 2.1, 3.1-hexagon or 3.1-octagon");
  std::cout << hybrid_to_json(P).dump() << "\n";
  return 0;
}

template <class F>
Json evaluate_points(const HybridPatch<Rational>& P, const std::vector<std::array<Rational, 2>>& xs) {
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

int run_eval(const Options& o, const Context& ctx) {
  const auto P = hybrid_from_json(read_json_file(o.file, ctx.read_limits), ctx.limits);
  std::vector<std::array<Rational, 2>> xs;
  for (const auto& a : o.at) {
    const auto v = parse_number_list(a, "at");
    if (v.size() != 2) throw UsageError("at", "needs two numbers, got \"" + a + "\"", "write --at \"u,v\"");
    xs.push_back({v[0], v[1]});
  }
  const auto spec = ArithSpec::parse(o.arith);
  const Json out = with_arith_except_flint(spec, "hybrid eval", [&](auto tag) {
    return evaluate_points<typename decltype(tag)::type>(P, xs);
  });
  std::cout << out.dump() << "\n";
  return 0;
}

}  // namespace

Commands add_hybrid(CLI::App& app) {
  auto o = std::make_shared<Options>();
  auto* c = app.add_subcommand("hybrid", "the hybrid multi-sided patch with B-spline boundaries (papers/003)");
  c->require_subcommand(1);
  auto* eval = c->add_subcommand("eval", "evaluate the patch (and its local parameters) at domain points");
  add_arith_option(eval, o->arith, "exact, double or mpfr:BITS");
  eval->add_option("--at", o->at, "a domain point \"u,v\" (repeatable)")->required();
  eval->add_option("FILE", o->file, "hybrid patch document")->required();
  auto* example = c->add_subcommand("example", "print a paper example as a hybrid patch document (control points constructed)");
  example->add_option("NAME", o->example, "2.1, 3.1-hexagon or 3.1-octagon")->required();
  return {{eval, [o](const Context& ctx) { return run_eval(*o, ctx); }},
          {example, [o](const Context&) { return run_example(*o); }}};
}

}  // namespace splinex::app

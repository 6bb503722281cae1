// splinex hybrid eval | example: the hybrid multi-sided patch with B-spline boundaries (papers/003).
#include <iostream>
#include <memory>

#include "apps/command.hpp"
#include "fixtures/hybrid_examples.hpp"
#include "float/arith_spec.hpp"
#include "hybrid/hybrid.hpp"
#include "io/documents.hpp"
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
  print_document(document(P));
  return 0;
}

int run_eval(const Options& o, const Context& ctx) {
  const auto P = read_hybrid(o.file, ctx.limits, ctx.read_limits);
  std::vector<std::array<Rational, 2>> xs;
  for (const auto& a : o.at) {
    const auto v = parse_number_list(a, "at");
    if (v.size() != 2) throw UsageError("at", "needs two numbers, got \"" + a + "\"", "write --at \"u,v\"");
    xs.push_back({v[0], v[1]});
  }
  const auto spec = ArithSpec::parse(o.arith);
  print_document(with_arith<HybridArithmetics>(spec, "hybrid eval", [&](auto tag) {
    return hybrid_points_document<typename decltype(tag)::type>(P, xs);
  }));
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

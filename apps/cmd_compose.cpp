// splinex compose: functional composition T(S) (papers/000): Bezier/B-spline composition,
// Algorithm 1 (trimmed patches) and Algorithm 2 (untrimmed tensor-product tiles).
#include <iostream>
#include <memory>

#include "apps/command.hpp"
#include "compose/compose.hpp"
#include "float/arith_spec.hpp"
#include "float/rounding.hpp"

namespace splinex::app {

namespace {

struct Options {
  std::string arith = "exact", outer, inner, method = "symbolic";
  bool expand = false;
  double eps = 1e-9;
  CLI::Option* eps_option = nullptr;
};

auto run_compose(const Options& o, const Context& ctx) {
  const auto T = read_spline(o.outer, ctx.limits, ctx.read_limits, "outer");
  const auto S = read_spline(o.inner, ctx.limits, ctx.read_limits, "inner");
  const auto spec = ArithSpec::parse(o.arith);
  if (o.method == "tensor") {
    TensorOptions to;
    to.boundary = o.eps_option->count() > 0 ? TrimBoundary::polyline : TrimBoundary::exact;
    to.eps = o.eps;
    return with_arith<TensorArithmetics>(spec, "compose --method tensor", [&](auto tag) {
      using F = typename decltype(tag)::type;
      return document(
          compose_tensor(round_spline<F>(T, "outer"), round_spline<F>(S, "inner"), to, ctx.limits));
    });
  }
  if (o.method == "trimmed")
    return with_arith<ComposeArithmetics>(spec, "compose", [&](auto tag) {
      using F = typename decltype(tag)::type;
      return document(
          compose_trimmed(round_spline<F>(T, "outer"), round_spline<F>(S, "inner"), {}, ctx.limits), o.eps);
    });
  CompositionOptions co;
  co.method = o.method == "interpolation" ? CompositionMethod::interpolation : CompositionMethod::symbolic;
  co.expand = o.expand;
  return with_arith<ComposeArithmetics>(spec, "compose", [&](auto tag) {
    using F = typename decltype(tag)::type;
    return document(compose(round_spline<F>(T, "outer"), round_spline<F>(S, "inner"), co, ctx.limits));
  });
}

}  // namespace

Commands add_compose(CLI::App& app) {
  auto o = std::make_shared<Options>();
  auto* c = app.add_subcommand("compose", "functional composition T(S) of B-splines (S inside T's pieces)");
  add_arith_option(c, o->arith, "exact (GMP), flint (exact, FLINT), double or mpfr:BITS");
  c->add_option("--outer", o->outer, "outer spline document T")->required();
  c->add_option("--inner", o->inner, "inner spline document S (points in T's parameter space)")->required();
  c->add_option("--method", o->method,
                "symbolic (Elber's Bernstein products), interpolation, trimmed (Algorithm 1) or tensor "
                "(Algorithm 2: untrimmed tensor-product tiles)")
      ->check(CLI::IsMember({"symbolic", "interpolation", "trimmed", "tensor"}))
      ->capture_default_str();
  c->add_flag("--expand", o->expand, "use T's end pieces as polynomials on all of R^n where S leaves T's domain");
  o->eps_option = c->add_option("--eps", o->eps,
                                "trimming polylines' tolerance: trimmed with --arith double; tensor (any arith): untrim "
                                "curved trimming curves by polylines (without --eps, tensor is exact and needs straight ones)")
                      ->check(CLI::Range(1e-12, 1e-1))
                      ->capture_default_str();
  return {{c, [o](const Context& ctx) {
             print_document(run_compose(*o, ctx));
             return 0;
           }}};
}

}  // namespace splinex::app

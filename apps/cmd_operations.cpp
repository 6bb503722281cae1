// splinex insert-knots | elevate | extract-bezier | split | reparametrize | reverse | derivative: one
// operation of the kernel on a spline document, in any arithmetic (the rows of operation_table()).
#include <iostream>
#include <memory>

#include "apps/command.hpp"
#include "crosscheck/operations.hpp"
#include "crosscheck/operations_ff.hpp"
#include "float/arith_spec.hpp"
#include "float/rounding.hpp"

namespace splinex::app {

namespace {

void add_op_options(CLI::App* c, OpOptions& o, const std::string& kind) {
  if (kind != "extract-bezier") c->add_option("--dir", o.dir, "parametric direction (0-based)")->capture_default_str();
  if (kind == "insert-knots") {
    c->add_option("--knots", o.knots, "comma-separated knots, e.g. \"0.25,1/3\"")->required();
    c->add_option("--method", o.insert_method, "a54 (refinement in one pass) or boehm (A5.1 knot by knot)")
        ->check(CLI::IsMember({"a54", "boehm"}))
        ->capture_default_str();
  } else if (kind == "elevate") {
    c->add_option("--by", o.by, "elevate the degree by this amount")->required();
    c->add_option("--method", o.elevate_method,
                  "auto (a59 in exact arithmetic, blossom in floating point: fewer bits lost), a59 (NURBS Book, "
                  "via Bezier pieces) or blossom")
        ->check(CLI::IsMember({"auto", "a59", "blossom"}))
        ->capture_default_str();
  } else if (kind == "split") {
    c->add_option("--at", o.at, "split parameter")->required();
  } else if (kind == "reparametrize") {
    c->add_option("--interval", o.interval, "new domain \"lo,hi\" of the direction")->required();
  } else if (kind == "derivative") {
    c->add_option("--by", o.by, "the order of the derivative")->check(CLI::Range(1, 1000))->capture_default_str();
  }
}

auto run_op_document(const Operation& op, const BSpline<Rational>& S, const ArithSpec& spec, const Limits& limits) {
  return with_arith<KernelArithmetics>(spec, op.name(), [&](auto tag) {
    using T = typename decltype(tag)::type;
    if constexpr (std::is_same_v<T, ExactFF>) {
      if (op.kind == Operation::Kind::extract_bezier) return document(extract_bezier_exact(S, limits));
      return splines_document(run_operation_exact(op, S, limits));
    } else {
      const BSpline<T> in = round_spline<T>(S);
      if (op.kind == Operation::Kind::extract_bezier) return document(extract_bezier(in, limits));
      return splines_document(run_operation(op, in, limits));
    }
  });
}

}  // namespace

Commands add_operations(CLI::App& app) {
  Commands out;
  for (const auto& row : operation_table()) {
    struct Options {
      std::string arith = "exact", file;
      OpOptions op;
    };
    auto o = std::make_shared<Options>();
    const std::string kind = row.name;
    auto* c = app.add_subcommand(kind, "spline document -> " + kind + " result");
    add_arith_option(c, o->arith, kernel_arith_help);
    add_op_options(c, o->op, kind);
    c->add_option("file", o->file, "spline document, - for stdin")->required();
    out.push_back({c, [o, kind](const Context& ctx) {
                     const auto S = read_spline(o->file, ctx.limits, ctx.read_limits);
                     const auto spec = ArithSpec::parse(o->arith);
                     print_document(run_op_document(make_op(kind, o->op), S, spec, ctx.limits));
                     return 0;
                   }});
  }
  return out;
}

}  // namespace splinex::app

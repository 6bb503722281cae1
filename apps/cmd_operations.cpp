// splinex insert-knots | elevate | extract-bezier | split | reparametrize | reverse: one operation
// of the kernel on a spline document, in any arithmetic.
#include <iostream>
#include <memory>

#include "apps/command.hpp"
#include "crosscheck/operations_impl.hpp"
#include "float/arith_spec.hpp"
#include "float/rounding.hpp"
#include "io/result_json.hpp"

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

Json run_op_document(const Operation& op, const BSpline<Rational>& S, const ArithSpec& spec, const Limits& limits) {
  return with_arith(spec, [&](auto tag) {
    using T = typename decltype(tag)::type;
    const BSpline<T> in = round_spline<T>(S);
    if (op.kind == Operation::Kind::extract_bezier) return bezier_pieces_to_json(extract_bezier(in, limits));
    const auto R = run_operation(op, in, limits);
    if (R.size() == 1) return spline_to_json(R[0]);
    Json parts = Json::array();
    for (const auto& r : R) parts.push_back(spline_to_json(r));
    return Json{{"splines", parts}};
  });
}

}  // namespace

Commands add_operations(CLI::App& app) {
  Commands out;
  for (const char* k : {"insert-knots", "elevate", "extract-bezier", "split", "reparametrize", "reverse", "derivative"}) {
    struct Options {
      std::string arith = "exact", file;
      OpOptions op;
    };
    auto o = std::make_shared<Options>();
    const std::string kind = k;
    auto* c = app.add_subcommand(kind, "spline document -> " + kind + " result");
    add_arith_option(c, o->arith, "exact (GMP), flint (exact, FLINT), double or mpfr:BITS");
    add_op_options(c, o->op, kind);
    c->add_option("file", o->file, "spline document, - for stdin")->required();
    out.push_back({c, [o, kind](const Context& ctx) {
                     const auto S = spline_from_json(read_json_file(o->file, ctx.read_limits), ctx.limits);
                     const auto spec = ArithSpec::parse(o->arith);
                     std::cout << run_op_document(make_op(kind, o->op), S, spec, ctx.limits).dump() << "\n";
                     return 0;
                   }});
  }
  return out;
}

}  // namespace splinex::app

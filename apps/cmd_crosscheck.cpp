// splinex crosscheck: one operation exactly and in a float arithmetic; the exact errors.
#include <iostream>
#include <memory>

#include "apps/command.hpp"
#include "crosscheck/crosscheck.hpp"

namespace splinex::app {

Commands add_crosscheck(CLI::App& app) {
  struct Options {
    std::string op, float_arith = "double", file;
    int grid = 0;
    OpOptions op_options;
  };
  auto o = std::make_shared<Options>();
  auto* c = app.add_subcommand("crosscheck", "run an operation exactly and in float; report the exact errors");
  c->add_option("operation", o->op, operation_names() + " or identity")->required();
  // --arith as every other command; --float, its old name, still read.
  c->add_option("--arith,--float", o->float_arith, "the arithmetic compared with exact: double, mpfr:BITS or flint (flint must agree exactly)")
      ->capture_default_str();
  c->add_option("--grid", o->grid, "evaluation points per direction (0: 65/17/7 by dimension; at most 10000)")
      ->check(CLI::Range(0, 10000));
  c->add_option("--dir", o->op_options.dir, "parametric direction");
  c->add_option("--knots", o->op_options.knots, "insert-knots: knots");
  c->add_option("--by", o->op_options.by, "elevate: amount");
  c->add_option("--method", o->op_options.insert_method, "insert-knots: a54|boehm; elevate: a59|blossom");
  c->add_option("--at", o->op_options.at, "split: parameter");
  c->add_option("--interval", o->op_options.interval, "reparametrize: \"lo,hi\"");
  c->add_option("file", o->file, "spline document, - for stdin")->required();
  return {{c, [o](const Context& ctx) {
             const auto S = read_spline(o->file, ctx.limits, ctx.read_limits);
             OpOptions op = o->op_options;
             use_one_method(o->op, op, o->op);  // --method serves both operations
             const auto rep = crosscheck(make_op(o->op, op), S, ArithSpec::parse(o->float_arith, "arith"), o->grid, ctx.limits);
             print_document(rep.document(), 2);
             return 0;
           }}};
}

}  // namespace splinex::app

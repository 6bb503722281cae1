// splinex eval: a spline (or a partial derivative) at a parameter, in any arithmetic.
#include <iostream>
#include <memory>

#include "apps/command.hpp"
#include "crosscheck/operations_ff.hpp"
#include "float/arith_spec.hpp"
#include "float/rounding.hpp"
#include "spline/evaluate.hpp"

namespace splinex::app {

Commands add_eval(CLI::App& app) {
  struct Options {
    std::string arith = "exact", file, at, orders, method = "basis";
  };
  auto o = std::make_shared<Options>();
  auto* c = app.add_subcommand("eval", "evaluate a spline (or a partial derivative) at a parameter");
  add_arith_option(c, o->arith, kernel_arith_help);
  c->add_option("--at", o->at, "parameter \"x0,x1,...\"")->required();
  c->add_option("--derivative", o->orders, "derivative orders per direction, e.g. \"1,0\"");
  c->add_option("--method", o->method, "basis (A2.2 basis functions) or deboor (de Boor's algorithm)")
      ->check(CLI::IsMember({"basis", "deboor"}))
      ->capture_default_str();
  c->add_option("file", o->file, "spline document, - for stdin")->required();
  return {{c, [o](const Context& ctx) {
             const auto S = read_spline(o->file, ctx.limits, ctx.read_limits);
             const auto x = parse_number_list(o->at, "at");
             std::vector<int> ord;
             if (!o->orders.empty())
               ord = whole_numbers(parse_number_list(o->orders, "derivative"), "derivative", 1000,
                                   "orders must be whole numbers in [0, 1000]", "write e.g. --derivative \"1,0\"");
             const auto spec = ArithSpec::parse(o->arith);
             print_document(with_arith<KernelArithmetics>(spec, "eval", [&](auto tag) {
               using T = typename decltype(tag)::type;
               if constexpr (std::is_same_v<T, ExactFF>) {
                 if (!ord.empty() && o->method == "deboor")
                   throw UsageError("method", "de Boor evaluation gives values only", "use --method basis with --derivative");
                 // Derivatives are not written fraction-free: GMP, the same values.
                 return point_document(ord.empty() ? evaluate_exact(S, x) : derivative(S, x, ord));
               } else {
                 const auto Sf = round_spline<T>(S);
                 const std::vector<T> xf = round_values<T>(x, "at");
                 if (!ord.empty() && o->method == "deboor")
                   throw UsageError("method", "de Boor evaluation gives values only", "use --method basis with --derivative");
                 const auto p = !ord.empty()              ? derivative(Sf, xf, ord)
                                : o->method == "deboor" ? evaluate_de_boor(Sf, xf)
                                                        : evaluate(Sf, xf);
                 return point_document(p);
               }
             }));
             return 0;
           }}};
}

}  // namespace splinex::app

// The composed orders of the examples of papers/000 (Section 3), from exact inputs of the stated
// orders: the orders are read off the computed compositions and compared with the paper's.
#include <sstream>

#include "compose/compose.hpp"
#include "experiments/report_template.hpp"
#include "experiments/section.hpp"
#include "fixtures/random_spline.hpp"
#include "spline/evaluate.hpp"

namespace splinex {

void composition_orders_section(ReportContext& ctx) {
  std::mt19937_64& rng = ctx.rng;
  ctx.progress("composition orders");
  struct OrdersCase {
    std::string name;
    std::vector<int> inner_orders, outer_orders;
    std::string paper, remark;
  };
  const std::vector<OrdersCase> orders_cases{
      {"teapot star pattern (Fig. 4)", {3, 3}, {4, 4}, "(13, 13)", "matches"},
      {"cross into duck trivariate (Fig. 6)", {2, 3}, {3, 3, 4}, "(8, 25)",
       ReportTemplate("composition-orders.fig6-remark").render()},
      {"pipes into twisted torus (Fig. 7)", {4, 4}, {2, 2, 3}, "(13, 13)", "matches"},
      {"bushing (Fig. 8)", {2, 3}, {2, 3, 3}, "(11, 6)", ReportTemplate("composition-orders.fig8-remark").render()},
  };
  std::ostringstream orders_md;
  auto show_orders = [](const std::vector<int>& o) {
    std::string s = "(";
    for (std::size_t i = 0; i < o.size(); ++i) s += (i ? ", " : "") + std::to_string(o[i]);
    return s + ")";
  };
  for (const auto& oc : orders_cases) {
    RandomSplineSpec si, so;
    for (int o : oc.inner_orders) { si.degrees.push_back(o - 1); si.counts.push_back(o); }
    for (int o : oc.outer_orders) { so.degrees.push_back(o - 1); so.counts.push_back(o); }
    si.q = static_cast<int>(oc.outer_orders.size());
    so.q = 3;
    BSpline<Rational> S = random_spline(si, rng);
    const BSpline<Rational> T = random_spline(so, rng);
    for (auto& x : S.points) x = (x + 2) / 4;  // into the outer box [0, 1]^n
    const auto R = compose_bezier(T, S, CompositionMethod::symbolic);
    const auto R2 = compose_bezier(T, S, CompositionMethod::interpolation);
    std::vector<Rational> at;
    for (int l = 0; l < S.dim(); ++l) at.emplace_back(1, 3 + l);
    const bool ok = R.points == R2.points && evaluate(R, at) == evaluate(T, evaluate(S, at));
    ctx.ok = ctx.ok && ok;
    std::vector<int> ro;
    for (int d : R.degrees) ro.push_back(d + 1);
    orders_md << "| " << oc.name << " | " << show_orders(oc.inner_orders) << " | " << show_orders(oc.outer_orders) << " | "
              << show_orders(ro) << (ok ? "" : " (**check failed**)") << " | " << oc.paper << " | " << oc.remark << " |\n";
  }
  ctx.markdown["composition-orders"] = ReportTemplate("composition-orders").set("rows", orders_md.str()).render();
}

}  // namespace splinex

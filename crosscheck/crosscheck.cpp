#include "crosscheck/crosscheck.hpp"

#include <chrono>
#include <cmath>
#include <limits>

#include "crosscheck/operations_ff.hpp"
#include "crosscheck/operations_impl.hpp"
#include "io/json_io.hpp"
#include "spline/evaluate.hpp"

namespace splinex {

// ---- operations ------------------------------------------------------------------------------

const std::vector<OperationRow>& operation_table() {
  using K = Operation::Kind;
  static const std::vector<OperationRow> rows{{"insert-knots", K::insert_knots}, {"elevate", K::elevate},
                                              {"extract-bezier", K::extract_bezier}, {"split", K::split},
                                              {"reparametrize", K::reparametrize}, {"reverse", K::reverse},
                                              {"derivative", K::derivative}};
  return rows;
}

std::string operation_names(const std::string& sep) {
  std::string out;
  for (const auto& r : operation_table()) out += (out.empty() ? "" : sep) + r.name;
  return out;
}

std::string Operation::name() const {
  if (kind == Kind::insert_knots && boehm) return "insert-knots(boehm)";
  if (kind == Kind::elevate && method != ElevationMethod::bezier_pieces)
    return method == ElevationMethod::blossom ? "elevate(blossom)" : "elevate(auto)";
  for (const auto& r : operation_table())
    if (r.kind == kind) return r.name;
  return "identity";
}

Operation make_op(const std::string& kind, const OpOptions& o) {
  Operation op = Operation::parse_kind(kind);
  op.dir = o.dir;
  switch (op.kind) {
    case Operation::Kind::insert_knots:
      op.knots = parse_number_list(o.knots, "knots");
      op.boehm = o.insert_method == "boehm";
      break;
    case Operation::Kind::elevate:
      op.by = o.by;
      op.method = o.elevate_method == "blossom" ? ElevationMethod::blossom
                  : o.elevate_method == "a59"   ? ElevationMethod::bezier_pieces
                                                : ElevationMethod::automatic;
      break;
    case Operation::Kind::split: op.at = parse_number(o.at, "at"); break;
    case Operation::Kind::derivative: op.by = o.by; break;
    case Operation::Kind::reparametrize: {
      const auto v = parse_number_list(o.interval, "interval");
      if (v.size() != 2) throw UsageError("interval", "needs two numbers", "write --interval \"lo,hi\"");
      op.lo = v[0];
      op.hi = v[1];
      break;
    }
    default: break;
  }
  return op;
}

void use_one_method(const std::string& kind, OpOptions& o, const std::string& what) {
  const std::string& m = o.insert_method;
  if (kind == "elevate") o.elevate_method = m == "blossom" ? "blossom" : m == "a59" ? "a59" : "auto";
  if (kind == "insert-knots" && o.knots.empty()) throw UsageError("knots", what + " needs --knots", "add --knots \"k1,k2,...\"");
}

Operation Operation::parse_kind(const std::string& name) {
  Operation op;
  if (name == "identity") return op;
  for (const auto& r : operation_table())
    if (name == r.name) {
      op.kind = r.kind;
      return op;
    }
  throw UsageError("operation", "unknown operation \"" + name + "\"", "use " + operation_names() + " or identity");
}

template std::vector<BSpline<Rational>> run_operation(const Operation&, const BSpline<Rational>&, const Limits&);
template std::vector<BSpline<double>> run_operation(const Operation&, const BSpline<double>&, const Limits&);
template std::vector<BSpline<Mpfr>> run_operation(const Operation&, const BSpline<Mpfr>&, const Limits&);
template std::vector<BSpline<FlintRational>> run_operation(const Operation&, const BSpline<FlintRational>&, const Limits&);

// ---- error statistics ------------------------------------------------------------------------

void ErrorStat::add(const Rational& exact, const Rational& approx) {
  const Rational e = splinex::abs(Rational(approx - exact)), r = splinex::abs(exact);
  if (max_abs < e) max_abs = e;
  if (max_ref < r) max_ref = r;
  ++count;
}

double ErrorStat::abs() const { return to_double(max_abs); }

double ErrorStat::rel() const {
  if (max_abs == 0) return 0;
  if (max_ref == 0) return std::numeric_limits<double>::infinity();
  return to_double(Rational(max_abs / max_ref));
}

double ErrorStat::bits_lost(int precision) const {
  if (max_abs == 0 || precision == 0) return 0;
  if (max_ref == 0) return precision;
  const double b = precision + log2_abs(Rational(max_abs / max_ref));
  return b < 0 ? 0 : (b > precision ? precision : b);
}

Json ErrorStat::to_json(int precision) const {
  Json j;
  j["max_abs_error"] = approx_json(abs());
  j["max_abs_error_exact"] = to_fraction_string(max_abs);
  j["max_rel_error"] = approx_json(rel());
  j["bits_lost"] = bits_lost(precision);
  j["compared"] = count;
  return j;
}

Json CrossReport::document() const {
  Json j;
  j["operation"] = operation;
  j["arith"] = arith;
  // The field names of `splinex verify` (issue 48): "precision", "structure", "structure_notes".
  j["precision"] = precision;
  j["structure"] = structure_match ? "equal" : "different";
  j["structure_notes"] = structure_note.empty() ? Json::array() : Json::array({structure_note});
  j["results"] = results;
  j["control_point_count"] = control_point_count;
  j["control_points"] = control_points.to_json(precision);
  j["knots"] = knots.to_json(precision);
  j["grid"] = grid.to_json(precision);
  j["seconds_exact"] = seconds_exact;
  j["seconds_float"] = seconds_float;
  return j;
}

// ---- the crosscheck --------------------------------------------------------------------------

namespace {

template <class T>
void compare(const std::vector<BSpline<Rational>>& E, const std::vector<BSpline<T>>& F, int grid_per_dir,
             CrossReport& rep) {
  auto exact = [](const T& x) { return ArithTraits<T>::to_rational(x); };
  if (E.size() != F.size()) {
    rep.structure_match = false;
    rep.structure_note = "exact gave " + std::to_string(E.size()) + " results, float " + std::to_string(F.size());
    return;
  }
  for (std::size_t r = 0; r < E.size(); ++r) {
    const auto &e = E[r];
    const auto &f = F[r];
    rep.control_point_count += e.size();
    bool same = e.degrees == f.degrees && e.q == f.q && e.is_rational() == f.is_rational();
    for (int d = 0; same && d < e.dim(); ++d) same = e.knots[d].size() == f.knots[d].size();
    if (!same) {
      rep.structure_match = false;
      rep.structure_note = "result " + std::to_string(r) + " differs in degree or knot count";
      continue;
    }
    if (!is_finite_spline(f)) {
      rep.structure_match = false;
      rep.structure_note = "result " + std::to_string(r) + " has infinite or NaN values in " + ArithTraits<T>::name();
      continue;
    }
    for (int d = 0; d < e.dim(); ++d)
      for (std::size_t i = 0; i < e.knots[d].size(); ++i) rep.knots.add(e.knots[d][i], exact(f.knots[d][i]));
    for (std::size_t i = 0; i < e.points.size(); ++i) rep.control_points.add(e.points[i], exact(f.points[i]));
    // Grid: G points per direction over the exact result's domain, ends included.
    const int k = e.dim();
    const int G = grid_per_dir > 0 ? grid_per_dir : (k == 1 ? 65 : k == 2 ? 17 : 7);
    std::vector<int> idx(k, 0);
    std::vector<Rational> x(k);
    std::vector<T> xf(k);
    while (true) {
      for (int d = 0; d < k; ++d) {
        x[d] = e.domain_lo(d) + (e.domain_hi(d) - e.domain_lo(d)) * Rational(idx[d], G - 1);
        xf[d] = ArithTraits<T>::from_rational(x[d]);
        // The float domain may end a rounding error away; stay inside it.
        if (xf[d] < f.domain_lo(d)) xf[d] = f.domain_lo(d);
        if (f.domain_hi(d) < xf[d]) xf[d] = f.domain_hi(d);
      }
      const auto ve = evaluate(e, x);
      const auto vf = evaluate(f, xf);
      for (int c = 0; c < e.q; ++c) {
        if (!is_finite_value(vf[c])) {
          rep.structure_match = false;
          rep.structure_note = "result " + std::to_string(r) + " evaluates to an infinite or NaN value in " + ArithTraits<T>::name();
          return;
        }
        rep.grid.add(ve[c], exact(vf[c]));
      }
      int d = 0;
      while (d < k && ++idx[d] == G) { idx[d] = 0; ++d; }
      if (d == k) break;
    }
  }
}

}  // namespace

CrossReport crosscheck(const Operation& op, const BSpline<Rational>& input, const ArithSpec& fl, int grid_per_dir,
                       const Limits& limits) {
  // The reference is GMP mpq (an oracle independent of the fraction-free kernel): --float exact
  // compares the fraction-free kernel with it (zero error, or a bug), --float gmp is refused.
  if (fl.kind == ArithSpec::Kind::gmp)
    throw UsageError("float", "the crosscheck compares exact (GMP) with another arithmetic", "use --float exact, flint, double or mpfr:BITS");
  // The grid is checked before any work: G^k points per result, G >= 2 (both domain ends).
  if (grid_per_dir == 1 || grid_per_dir < 0)
    throw UsageError("grid", std::to_string(grid_per_dir) + " points per direction cannot span a domain", "use --grid 0 (automatic) or >= 2");
  if (grid_per_dir > 0) {
    double points = 1;
    for (int d = 0; d < input.dim(); ++d) points *= grid_per_dir;
    if (points > 1e6)
      throw UsageError("grid", std::to_string(grid_per_dir) + "^" + std::to_string(input.dim()) + " evaluation points exceed 10^6",
                       "use a smaller --grid");
  }
  using clock = std::chrono::steady_clock;
  CrossReport rep;
  rep.operation = op.name();
  rep.arith = fl.name();
  const auto t0 = clock::now();
  const auto E = run_operation(op, input, limits);
  rep.seconds_exact = std::chrono::duration<double>(clock::now() - t0).count();
  rep.results = E.size();
  with_arith<KernelArithmetics>(fl, "crosscheck", [&](auto tag) {
    using T = typename decltype(tag)::type;
    constexpr bool ff = std::is_same_v<T, ExactFF>;
    using V = std::conditional_t<ff, Rational, T>;  // the results' scalar
    rep.precision = ArithTraits<T>::precision_bits();
    const auto t1 = clock::now();
    std::vector<BSpline<V>> F;
    try {
      if constexpr (ff) {
        F = run_operation_exact(op, input, limits);
      } else {
        const BSpline<T> in = round_spline<T>(input);
        F = run_operation(op, in, limits);
      }
    } catch (const Error& e) {
      // Rounding can merge knots that differ exactly (round_spline refuses that), overflow, or
      // push a parameter out of the domain: the float run fails where the exact one succeeds.
      rep.structure_match = false;
      rep.structure_note = std::string("the float run failed: ") + e.what();
      return;
    }
    rep.seconds_float = std::chrono::duration<double>(clock::now() - t1).count();
    compare(E, F, grid_per_dir, rep);
  });
  return rep;
}

}  // namespace splinex

// splinex verify: a result computed elsewhere judged exactly against splinex's exact reference
// (crosscheck/verify.hpp).
#include <chrono>
#include <iostream>
#include <memory>

#include "apps/command.hpp"
#include "compose/compose.hpp"
#include "hybrid/hybrid.hpp"
#include "crosscheck/verify.hpp"

namespace splinex::app {

namespace {

/// What verify judges: every kernel operation (refine: insert-knots by A5.4, after it), eval,
/// compose and hybrid-eval.
std::vector<std::string> verify_operations() {
  std::vector<std::string> out;
  for (const auto& r : operation_table()) {
    out.push_back(r.name);
    if (r.kind == Operation::Kind::insert_knots) out.push_back("refine");
  }
  for (const char* extra : {"eval", "compose", "hybrid-eval"}) out.push_back(extra);
  return out;
}

/// 1 when --max-bits-lost is given and the candidate loses more or its structure differs.
/// A line on stderr says which metric failed.
int verdict_status(const VerifyReport& rep, double max_bits) {
  if (max_bits < 0) return 0;
  const auto [part, bits] = rep.worst_part();
  if (rep.structure == "different") {
    std::cerr << "splinex: verify: the structure differs (" << (rep.structure_notes.empty() ? "see structure_notes" : rep.structure_notes.front())
              << "), so --max-bits-lost fails\n";
    return 1;
  }
  if (bits > max_bits) {
    std::cerr << "splinex: verify: " << (part == "function" ? "the function-level error bound" : part == "values" ? "the values" : "the control points")
              << " lose " << bits << " bits, over --max-bits-lost " << max_bits << "\n";
    return 1;
  }
  return 0;
}

}  // namespace

Commands add_verify(CLI::App& app) {
  struct Options {
    std::string operation, input, candidate, read_as = "double", outer, inner, patch;
    bool expand = false;
    OpOptions op;
    int precision = 53, rounds = 24;
    std::string factor = "2";
    double max_bits = -1;
  };
  auto o = std::make_shared<Options>();
  auto* c = app.add_subcommand("verify", "judge a result computed elsewhere exactly against the exact reference");
  c->add_option("operation", o->operation,
                "insert-knots, refine (insert-knots by A5.4), elevate, extract-bezier, split, reparametrize, reverse, derivative "
                "(the derivative spline, --by its order), eval, "
                "compose (--method symbolic|interpolation: T(S) as one spline; trimmed: Algorithm 1's patches; "
                "tensor: Algorithm 2's tiles) or hybrid-eval (the hybrid patch's values)")
      ->required()
      ->check(CLI::IsMember(verify_operations()));
  c->add_option("--patch", o->patch, "hybrid-eval: the hybrid patch document");
  c->add_option("--input", o->input, "the input spline document (every operation but compose)");
  c->add_option("--outer", o->outer, "compose: the outer spline T");
  c->add_option("--inner", o->inner, "compose: the inner spline S (points in T's parameter space)");
  c->add_flag("--expand", o->expand, "compose: T's end pieces as polynomials where S leaves T's domain (as compose --expand)");
  c->add_option("--candidate", o->candidate,
                "the candidate: a spline document, {\"splines\": [...]}, {\"pieces\": [...]}; for eval {\"at\": [[...]], "
                "\"values\": [[...]]}")
      ->required();
  c->add_option("--read-as", o->read_as,
                "double: a decimal in the candidate is the double nearest to it (what a float program printed); "
                "exact: decimals read exactly. Fractions p/q are exact either way")
      ->check(CLI::IsMember({"double", "exact"}))
      ->capture_default_str();
  c->add_option("--precision", o->precision, "the candidate's significand bits, for bits lost")->check(CLI::Range(2, 100000))->capture_default_str();
  c->add_option("--factor", o->factor, "refine the function-level bound until it is within this factor of the witness (> 1)")
      ->capture_default_str();
  c->add_option("--rounds", o->rounds, "refinement rounds at most")->check(CLI::Range(0, 64))->capture_default_str();
  c->add_option("--max-bits-lost", o->max_bits, "exit 1 when the candidate loses more bits than this (coefficients, values or "
                                                 "the function-level error) or its structure differs");
  c->add_option("--dir", o->op.dir, "parametric direction (0-based)")->capture_default_str();
  c->add_option("--knots", o->op.knots, "insert-knots: comma-separated knots");
  c->add_option("--method", o->op.insert_method,
                "insert-knots: a54|boehm; elevate: auto|a59|blossom (the same exact result); compose: the method the candidate "
                "ran: symbolic|interpolation (one spline), trimmed (Algorithm 1, {\"pieces\": ...}) or tensor (Algorithm 2, "
                "{\"tiles\": ...})");
  c->add_option("--by", o->op.by, "elevate: amount; derivative: order");
  c->add_option("--at", o->op.at, "split: parameter");
  c->add_option("--interval", o->op.interval, "reparametrize: \"lo,hi\"");
  return {{c, [o](const Context& ctx) {
             VerifyOptions vo;
             vo.precision = o->precision;
             vo.max_rounds = o->rounds;
             vo.factor = parse_number(o->factor, "factor");
             // Progress on stderr once a run takes longer than two seconds (compositions of many tiles).
             vo.progress = [start = std::chrono::steady_clock::now()](const std::string& s) {
               if (std::chrono::steady_clock::now() - start > std::chrono::seconds(2)) std::cerr << "splinex verify: " << s << std::endl;
             };
             if (!(vo.factor > 1)) throw UsageError("factor", "must be greater than 1", "give e.g. --factor 2");
             const auto cand = read_candidate(o->candidate, o->read_as == "double", ctx.read_limits);
             VerifyReport rep;
             if (o->operation == "compose") {
               if (o->outer.empty() || o->inner.empty())
                 throw UsageError("outer", "verify compose needs --outer and --inner", "give both spline documents");
               const auto T = read_spline(o->outer, ctx.limits, ctx.read_limits, "outer");
               const auto Sin = read_spline(o->inner, ctx.limits, ctx.read_limits, "inner");
               const std::string method = o->op.insert_method == "a54" ? "symbolic" : o->op.insert_method;
               if (method != "symbolic" && method != "interpolation" && method != "trimmed" && method != "tensor")
                 throw UsageError("method", "verify compose --method " + method + " is not a composition method",
                                  "give symbolic, interpolation, trimmed or tensor");
               if (method == "trimmed") {
                 rep = verify_trimmed_composition(T, Sin, cand, vo, ctx.limits);
               } else if (method == "tensor") {
                 rep = verify_tensor_composition(T, Sin, cand, vo, ctx.limits);
               } else {
                 // T(S) as one spline: the symbolic and interpolation methods give the same exact result.
                 CompositionOptions co;
                 co.expand = o->expand;
                 rep = verify_splines("compose", {compose(T, Sin, co, ctx.limits)}, verify_candidate_splines(cand, ctx.limits), vo, ctx.limits);
               }
               print_document(rep.document(), 2);
               return verdict_status(rep, o->max_bits);
             }
             if (o->operation == "hybrid-eval") {
               if (o->patch.empty()) throw UsageError("patch", "verify hybrid-eval needs --patch", "give the hybrid patch document");
               const auto P = read_hybrid(o->patch, ctx.limits, ctx.read_limits);
               const auto cv = hybrid_candidate_values(cand);
               rep = verify_point_values("hybrid-eval", cv.at, cv.values,
                                         [&](const std::vector<Rational>& x) {
                                           if (x.size() != 2)
                                             throw ValidationError("candidate.at", "a hybrid patch point has two parameters", "write [u, v]");
                                           return hybrid_evaluate(P, Point2<Rational>{x[0], x[1]});
                                         },
                                         vo);
               print_document(rep.document(), 2);
               return verdict_status(rep, o->max_bits);
             }
             if (o->input.empty()) throw UsageError("input", "verify " + o->operation + " needs --input", "give the input spline document");
             const auto S = read_spline(o->input, ctx.limits, ctx.read_limits, "input");
             if (o->operation == "eval") {
               const auto cv = candidate_values(cand);
               rep = verify_values(S, cv.at, cv.values, vo);
             } else {
               OpOptions op = o->op;
               std::string kind = o->operation;
               if (kind == "refine") {  // knot refinement: insert-knots by A5.4
                 kind = "insert-knots";
                 op.insert_method = "a54";
               }
               use_one_method(kind, op, o->operation);
               rep = verify(make_op(kind, op), S, verify_candidate_splines(cand, ctx.limits), vo, ctx.limits);
             }
             print_document(rep.document(), 2);
             return verdict_status(rep, o->max_bits);
           }}};
}

}  // namespace splinex::app

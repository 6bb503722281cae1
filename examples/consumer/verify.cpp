// Uses an installed splinex::crosscheck to judge a double computation against the exact reference:
// a rational quadratic arc (a quarter circle) degree-elevated by 2 in double, then measured exactly
// (splinex verify's C++ API). Prints the structure finding, the certified function-level error
// bound and the worst bits lost; exits 1 if the double result lost more than 8 bits.
#include <iostream>

#include "crosscheck/verify.hpp"
#include "spline/factories.hpp"

int main() {
  using namespace splinex;
  // The quarter circle x^2 + y^2 = 1 as a rational quadratic Bezier curve (weights 1, 1/sqrt2 ~ 7/10).
  const auto arc = make_spline<Rational>({2}, unit_bezier_knots<Rational>({2}), 2, {1, 0, 1, 1, 0, 1},
                                         {1, Rational(7, 10), 1});
  Operation op;
  op.kind = Operation::Kind::elevate;
  op.by = 2;
  // The candidate: the same operation run in double on the rounded input, read back exactly.
  const auto in_double = convert<double>(arc, [](const Rational& x) { return to_double(x); });
  const auto out_double = run_operation<double>(op, in_double, Limits{});
  std::vector<BSpline<Rational>> candidate;
  for (const auto& S : out_double)
    candidate.push_back(convert<Rational>(S, [](double x) { return exact_from_double(x); }));
  const VerifyReport r = verify(op, arc, candidate);
  std::cout << "structure: " << r.structure << "\n"
            << "function error: " << (r.function.certified ? "certified <= " : "measured ")
            << to_double(r.function.upper) << "\n"
            << "worst bits lost: " << r.worst_bits_lost() << "\n";
  return r.structure != "different" && r.function.certified && r.worst_bits_lost() <= 8 ? 0 : 1;
}

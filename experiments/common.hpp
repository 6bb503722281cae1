// Small helpers shared by the experiments of `splinex report`.
#pragma once
#include <ctime>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include "exact/rational.hpp"
#include "spline/bspline.hpp"
#include "fixtures/trimming_examples.hpp"
#include "spline/factories.hpp"

namespace splinex {

/// A number for Markdown tables: `precision` significant digits.
inline std::string fmt(double v, int precision = 3) {
  std::ostringstream o;
  o << std::setprecision(precision) << v;
  return o.str();
}

/// CPU time of the calling thread in seconds (CLOCK_THREAD_CPUTIME_ID): a job's cost that does
/// not depend on what else shares the machine (other jobs of a sweep, a build), unlike wall time.
inline double thread_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

/// The clamped knot vector of degree p on [0, 1] with the interior knot u0 of multiplicity m.
inline std::vector<Rational> knots_with(int p, const Rational& u0, int m) {
  return clamped_knots(p, Rational(0), Rational(1), std::vector<Rational>(m, u0));
}

}  // namespace splinex

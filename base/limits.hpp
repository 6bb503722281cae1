// Size limits that keep an operation from exhausting memory. Checked before any allocation.
#pragma once
#include <cstddef>
#include <string>

#include "base/errors.hpp"

namespace splinex {

struct Limits {
  std::size_t max_control_points = 10'000'000;  // per spline, all directions multiplied
  int max_degree = 100;                         // per direction
  /// Summed over the splines one operation returns (untrimming: every tile's net), so that many
  /// splines each under max_control_points cannot together exhaust memory.
  std::size_t max_total_control_points = 50'000'000;
  /// Bits of any one number (numerator or denominator) of a model read by an exact subdivision
  /// engine (V-rep, cutting, the hybrid patch): their work grows with the length of the numbers,
  /// which no box budget bounds, so longer numbers are refused when the model is read.
  std::size_t max_input_bits = 4096;

  void check_count(std::size_t count, const std::string& what) const {
    if (count > max_control_points)
      throw SizeLimitError(what,
                           "the result would have " + std::to_string(count) +
                               " control points, above the limit of " +
                               std::to_string(max_control_points),
                           "ask for less, or raise the limit with --max-control-points");
  }
  void check_total(std::size_t count, const std::string& what) const {
    if (count > max_total_control_points)
      throw SizeLimitError(what,
                           "the results would have at least " + std::to_string(count) +
                               " control points together, above the limit of " +
                               std::to_string(max_total_control_points),
                           "ask for less (e.g. a larger tolerance), or raise the limit with --max-total-control-points");
  }
  void check_bits(std::size_t bits, const std::string& what) const {
    if (bits > max_input_bits)
      throw SizeLimitError(what,
                           "has a number of " + std::to_string(bits) + " bits, over the exact limit of " +
                               std::to_string(max_input_bits),
                           "give the number with fewer digits, or raise the limit with --max-input-bits");
  }
  void check_degree(long degree, const std::string& what) const {
    if (degree > max_degree)
      throw SizeLimitError(what,
                           "degree " + std::to_string(degree) + " is above the limit of " +
                               std::to_string(max_degree),
                           "ask for a lower degree, or raise the limit with --max-degree");
  }
};

/// Multiply counts, throwing SizeLimitError instead of overflowing.
inline std::size_t checked_product(std::size_t a, std::size_t b, const Limits& limits,
                                   const std::string& what) {
  std::size_t r = 0;
  if (__builtin_mul_overflow(a, b, &r))
    throw SizeLimitError(what, "the result would have more control points than a machine word counts",
                         "ask for less");
  limits.check_count(r, what);
  return r;
}

}  // namespace splinex

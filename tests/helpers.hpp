#pragma once
#include <sstream>
#include <string>

#include "io/json_io.hpp"

namespace splinex::test {

inline Json doc(const std::string& text) {
  std::istringstream in(text);
  return read_json(in, "test");
}
inline BSpline<Rational> spline(const std::string& text, const Limits& limits = {}) {
  return spline_from_json(doc(text), limits);
}
inline Rational q(const char* s) { return parse_number(s, "test"); }

}  // namespace splinex::test

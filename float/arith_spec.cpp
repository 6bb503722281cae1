#include "float/arith_spec.hpp"

#include "base/errors.hpp"

namespace splinex {

ArithSpec ArithSpec::parse(const std::string& text, const std::string& field) {
  ArithSpec s;
  if (text == "exact") return s;
  if (text == "flint") { s.kind = Kind::flint; return s; }
  if (text == "double") { s.kind = Kind::dbl; return s; }
  if (text.rfind("mpfr:", 0) == 0) {
    const std::string b = text.substr(5);
    bool digits = !b.empty() && b.size() <= 7;
    for (char c : b) digits = digits && c >= '0' && c <= '9';
    if (digits) {
      s.kind = Kind::mpfr;
      s.bits = std::stol(b);
      if (s.bits >= 24 && s.bits <= 1'000'000) return s;
    }
  }
  throw UsageError(field, "unknown arithmetic \"" + text + "\"",
                   "use exact, flint, double, or mpfr:BITS with 24 <= BITS <= 1000000");
}

std::string ArithSpec::name() const {
  switch (kind) {
    case Kind::exact: return "exact";
    case Kind::flint: return "flint";
    case Kind::dbl: return "double";
    case Kind::mpfr: break;
  }
  return "mpfr:" + std::to_string(bits);
}

}  // namespace splinex

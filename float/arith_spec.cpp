#include "float/arith_spec.hpp"

#include <iterator>

#include "base/errors.hpp"

namespace splinex {

namespace {

/// The rows' names for a message: "exact, flint, double, or mpfr:BITS".
std::string all_names() {
  std::string out;
  const std::size_t n = std::size(arith_rows);
  for (std::size_t k = 0; k < n; ++k) out += (k == 0 ? "" : k + 1 == n ? ", or " : ", ") + std::string(arith_rows[k].name);
  return out;
}

}  // namespace

ArithSpec ArithSpec::parse(const std::string& text, const std::string& field) {
  ArithSpec s;
  for (const auto& row : arith_rows)
    if (row.kind != Kind::mpfr && text == row.name) {
      s.kind = row.kind;
      return s;
    }
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
  throw UsageError(field, "unknown arithmetic \"" + text + "\"", "use " + all_names() + " with 24 <= BITS <= 1000000");
}

std::string ArithSpec::name() const {
  if (kind == Kind::mpfr) return "mpfr:" + std::to_string(bits);
  for (const auto& row : arith_rows)
    if (row.kind == kind) return row.name;
  return "";  // not reached: every kind has a row
}

}  // namespace splinex

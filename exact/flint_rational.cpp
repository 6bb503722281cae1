#include "exact/flint_rational.hpp"

#include "base/errors.hpp"

namespace splinex {

void FlintRational::div_checked(fmpq_t r, const fmpq_t a, const fmpq_t b) {
  if (fmpq_is_zero(b)) throw DomainError("value", "division by zero in exact arithmetic", "check the input for coincident knots or zero weights");
  fmpq_div(r, a, b);
}

}  // namespace splinex

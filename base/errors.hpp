// Typed errors. Every error names the offending field and says how to fix it; the command line
// prints what() on stderr and exits with status 2.
#pragma once
#include <stdexcept>
#include <string>

namespace splinex {

class Error : public std::runtime_error {
 public:
  Error(std::string field, const std::string& problem, const std::string& fix)
      : std::runtime_error(field + ": " + problem + (fix.empty() ? "" : " (fix: " + fix + ")")),
        field_(std::move(field)) {}
  const std::string& field() const noexcept { return field_; }

 private:
  std::string field_;
};

/// Text that is not a document or not a number: malformed JSON, "abc" as a knot, NaN/Inf.
class ParseError : public Error { using Error::Error; };
/// A well-formed document that violates a rule: unknown field, non-monotone knots, counts.
class ValidationError : public Error { using Error::Error; };
/// A parameter outside the spline's domain, or an empty domain.
class DomainError : public Error { using Error::Error; };
/// A result that would exceed a configured size limit (control points, degree).
class SizeLimitError : public Error { using Error::Error; };
/// An unknown arithmetic, operation or option value.
class UsageError : public Error { using Error::Error; };
/// A value a floating arithmetic cannot hold (overflow, a weight underflowing to 0), or a rounding
/// that would change the input's structure (distinct knots becoming equal).
class RangeError : public Error { using Error::Error; };

}  // namespace splinex

// The kernel operations as data, so that one description runs in any arithmetic: the crosscheck
// runs it exactly and in floating point from the same exact input, the command line builds it
// from options.
#pragma once
#include <string>
#include <vector>

#include "exact/rational.hpp"
#include "spline/kernel.hpp"

namespace splinex {

struct Operation {
  enum class Kind { insert_knots, elevate, extract_bezier, split, reparametrize, reverse, derivative, identity };
  Kind kind = Kind::identity;
  int dir = 0;
  std::vector<Rational> knots;  // insert_knots
  bool boehm = false;           // insert_knots: A5.1 knot by knot instead of A5.4
  int by = 1;                   // elevate: the amount; derivative: the order
  /// A5.9 unless asked otherwise: the crosscheck suite measures what each method loses (the CLI's
  /// default, `auto`, is ElevationMethod::automatic).
  ElevationMethod method = ElevationMethod::bezier_pieces;
  Rational at;                  // split
  Rational lo, hi;              // reparametrize

  std::string name() const;
  static Operation parse_kind(const std::string& name);  // UsageError for unknown names
};

/// The kernel operations, one row each (issue 48: one table per extension point): the name is the
/// command (`splinex NAME`), crosscheck's and verify's OPERATION and what Operation::parse_kind,
/// Python and the fuzzers read. A new operation is its template, a case of run_operation
/// (crosscheck/operations_impl.hpp), its options in OpOptions/make_op and one row here.
struct OperationRow {
  const char* name;
  Operation::Kind kind;
};
/// In the order of --help (identity, crosscheck's baseline, is not a row).
const std::vector<OperationRow>& operation_table();
/// The rows' names joined by `sep` ("insert-knots, elevate, ...").
std::string operation_names(const std::string& sep = ", ");

/// An operation's options as text, as the command line, crosscheck and bench_document take them.
struct OpOptions {
  int dir = 0;
  std::string knots;                  // insert-knots: comma-separated
  std::string insert_method = "a54";  // insert-knots: a54 | boehm
  int by = 1;                         // elevate: the amount; derivative: the order
  std::string elevate_method = "auto";  // elevate: auto | a59 | blossom
  std::string at;                     // split
  std::string interval;               // reparametrize: "lo,hi"
};
/// The operation `kind` (insert-knots, elevate, ...) with those options, numbers read exactly
/// (ParseError / UsageError naming the option).
Operation make_op(const std::string& kind, const OpOptions& o);
/// For the commands whose one --method (in `insert_method`) serves both insert-knots (a54 | boehm)
/// and elevate (auto | a59 | blossom): elevate's method taken from it (a59 and blossom as named,
/// anything else auto), and insert-knots' knots required (UsageError "`what` needs --knots").
void use_one_method(const std::string& kind, OpOptions& o, const std::string& what);

/// The result splines (one for most operations; the pieces or the two halves otherwise).
template <class T>
std::vector<BSpline<T>> run_operation(const Operation& op, const BSpline<T>& S, const Limits& limits);

}  // namespace splinex

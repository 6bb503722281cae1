// Three-valued answers: the one form in which a claim's fate is given. A claim (det J has one sign
// on the cell; the cutting curve is injective; the loop is simple) is
//   proved     - the argument covers the whole claim and was checked (the reason says which);
//   refuted    - a witness shows it false (the witness is typed by the claim and lives beside the
//                verdict in the claim's report: a parameter point, two parameters with one image);
//   undecided  - neither, with the reason (which budget ran out, which case is not built).
// CGAL's Uncertain<T> is the model: an answer that may not be known, and make_certain() that
// refuses to guess. A decision among several values that may not be made is an Uncertain<E>. A
// rule checked by ctest (scripts/check_size.py, placement): a new enum with an `undecided` member
// outside base/ must not be added; use Verdict or Uncertain<E>.
#pragma once
#include <string>
#include <utility>

#include "base/errors.hpp"

namespace splinex {

enum class Status { proved, refuted, undecided };

/// "proved", "refuted" or "undecided": the one spelling in text and JSON.
inline const char* status_name(Status s) {
  return s == Status::proved ? "proved" : s == Status::refuted ? "refuted" : "undecided";
}

/// An undecided verdict asked to be certain: names the claim and why it is not decided.
class UndecidedError : public Error {
  using Error::Error;
};

/// A claim's answer: its status and the reason (the argument, what the witness shows, or why it
/// is not decided). Default: undecided, not examined.
class Verdict {
 public:
  Verdict() = default;
  static Verdict proved(std::string argument) { return {Status::proved, std::move(argument)}; }
  static Verdict refuted(std::string what_the_witness_shows) { return {Status::refuted, std::move(what_the_witness_shows)}; }
  static Verdict undecided(std::string reason) { return {Status::undecided, std::move(reason)}; }

  Status status() const { return status_; }
  bool is_proved() const { return status_ == Status::proved; }
  bool is_refuted() const { return status_ == Status::refuted; }
  bool is_undecided() const { return status_ == Status::undecided; }
  const std::string& reason() const { return reason_; }
  /// Text appended to the reason (what else was found while deciding).
  void add_to_reason(const std::string& more) { reason_ += more; }

  /// true when proved, false when refuted; an undecided verdict throws UndecidedError naming
  /// `claim` and the reason (CGAL's Uncertain<bool>::make_certain).
  bool make_certain(const std::string& claim) const {
    if (status_ == Status::undecided)
      throw UndecidedError(claim, "undecided: " + reason_, "raise the budget named in the reason, or decide it another way");
    return status_ == Status::proved;
  }

  friend bool operator==(const Verdict& a, const Verdict& b) { return a.status_ == b.status_ && a.reason_ == b.reason_; }

 private:
  Verdict(Status s, std::string r) : status_(s), reason_(std::move(r)) {}
  Status status_ = Status::undecided;
  std::string reason_ = "not examined";
};

/// A decision among the values of an enumeration E that may not be made: one value, or undecided
/// with the reason - CGAL's Uncertain<T> for an enumeration, as Verdict is for a yes/no claim (a
/// trimmed cell is whole, empty or cut; an edge is a curve or collapsed). Compare with a value:
/// an undecided one equals none.
template <class E>
class Uncertain {
 public:
  Uncertain(E value) : value_(value), certain_(true) {}  // NOLINT: a decided value converts implicitly
  static Uncertain undecided(std::string reason) {
    Uncertain u;
    u.reason_ = std::move(reason);
    return u;
  }

  bool is_certain() const { return certain_; }
  /// Why it is not decided (empty when it is).
  const std::string& reason() const { return reason_; }
  /// The value; an undecided one throws UndecidedError naming `what` and the reason.
  E make_certain(const std::string& what) const {
    if (!certain_) throw UndecidedError(what, "undecided: " + reason_, "raise the budget named in the reason, or decide it another way");
    return value_;
  }

  friend bool operator==(const Uncertain& u, E e) { return u.certain_ && u.value_ == e; }
  friend bool operator!=(const Uncertain& u, E e) { return !(u == e); }

 private:
  Uncertain() = default;
  E value_{};
  bool certain_ = false;
  std::string reason_;
};

}  // namespace splinex

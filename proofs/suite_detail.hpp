// Shared pieces of the proof registry (proofs/suite.cpp and the per-topic proof files).
#pragma once
#include <cstdint>
#include <functional>
#include <random>
#include <string>

#include "proofs/suite.hpp"

namespace splinex::proof_detail {

// Aggregates the identity checks of one named proof over its cases.
struct Accumulator {
  ProofReport rep;
  int max_bound = 0;
  void add(const IdentityCheck& c, std::size_t case_no);
  void fail(const std::string& why, std::size_t case_no);
  // Counts n coefficient (or value) comparisons that all held.
  void compared(std::size_t n) { rep.points += n; }
  // Marks the proof undecided (nothing to compare); a refutation still wins.
  void undecided(const std::string& why, std::size_t case_no);
  void structures(const std::vector<std::string>& tags);
};

// Compares two splines coefficient for coefficient (degrees, knots, points, weights); counts the
// comparisons, fails with `what` on the first difference.
void compare_nets(Accumulator& acc, const BSpline<Rational>& A, const BSpline<Rational>& B, const std::string& what,
                  std::size_t case_no);

// One case: (a random B-spline case, the seeded generator, the accumulator, the case number).
using CaseFn = std::function<void(const BSpline<Rational>&, std::mt19937_64&, Accumulator&, std::size_t)>;

// A named proof running fn on `cases` seeded cases. `uses_case`: fn reads the structured case it
// is handed (its structures are then listed in the report); false for proofs that build their
// own inputs. `sampled`: the claim is checked pointwise only ("checked at N points").
struct EntryOptions {
  bool expect_proved = true;
  bool uses_case = true;
  bool sampled = false;
};
ProofEntry entry(std::string name, std::string identity, std::string bound, CaseFn fn, std::uint64_t seed,
                 EntryOptions options = {});

// The hybrid-patch proofs (papers/003), proofs/hybrid_proofs.cpp.
std::vector<ProofEntry> hybrid_proofs();

}  // namespace splinex::proof_detail

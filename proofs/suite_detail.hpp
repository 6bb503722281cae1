// Shared pieces of the proof registry (proofs/registry.cpp) and the per-topic proof files
// (proofs/*_proofs.cpp: one function per proof, one list per topic).
#pragma once
#include <cstdint>
#include <functional>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "proofs/suite.hpp"

namespace splinex::proof_detail {

/// Aggregates the identity checks of one named proof over its cases.
struct Accumulator {
  ProofReport rep;
  int max_bound = 0;
  void add(const IdentityCheck& c, std::size_t case_no);
  void fail(const std::string& why, std::size_t case_no);
  /// Counts n coefficient (or value) comparisons that all held.
  void compared(std::size_t n) { rep.points += n; }
  /// Marks the proof undecided (nothing to compare); a refutation still wins.
  void undecided(const std::string& why, std::size_t case_no);
  void structures(const std::vector<std::string>& tags);
};

/// Compares two splines coefficient for coefficient (degrees, knots, points, weights); counts the
/// comparisons, fails with `what` on the first difference.
void compare_nets(Accumulator& acc, const BSpline<Rational>& A, const BSpline<Rational>& B, const std::string& what,
                  std::size_t case_no);

/// One case: (a random B-spline case, the seeded generator, the accumulator, the case number).
using CaseFn = std::function<void(const BSpline<Rational>&, std::mt19937_64&, Accumulator&, std::size_t)>;

/// A named proof running fn on `cases` seeded cases. `uses_case`: fn reads the structured case it
/// is handed (its structures are then listed in the report); false for proofs that build their
/// own inputs (the case is still drawn, so the seeded sequence stays as it was). `sampled`: the
/// claim is checked pointwise only ("checked at N points").
struct EntryOptions {
  bool expect_proved = true;
  bool uses_case = true;
  bool sampled = false;
};
inline constexpr EntryOptions own_inputs{true, false, false};
inline constexpr EntryOptions own_inputs_sampled{true, false, true};
/// A paper's claim that splinex shows false, checked pointwise: the run expects the refutation.
inline constexpr EntryOptions own_inputs_expected_refuted{false, false, true};

/// The proof `name` (its seed from the registry's seed table; a name without a seed is a
/// std::logic_error).
ProofEntry entry(std::string name, std::string identity, std::string bound, CaseFn fn, EntryOptions options = {});

/// The kernel's case helpers (proofs/kernel_proofs.cpp): a random direction; a random knot to
/// insert in direction d and how often it may go in (up to multiplicity p+1); the knots of X that
/// can go into direction d together, sorted.
int random_dir(const BSpline<Rational>& S, std::mt19937_64& rng);
std::pair<Rational, int> random_knot(const BSpline<Rational>& S, int d, std::mt19937_64& rng);
std::vector<Rational> legal_insertions(const BSpline<Rational>& S, int d, const std::vector<Rational>& X);

/// The topics, in the registry's order: proofs/kernel_proofs.cpp, compose_proofs.cpp (composition
/// and trimming end points), untrim_proofs.cpp, arith_proofs.cpp, fixture_proofs.cpp,
/// hybrid_proofs.cpp (papers/003).
std::vector<ProofEntry> kernel_proofs();
std::vector<ProofEntry> composition_proofs();
std::vector<ProofEntry> untrimming_proofs();
std::vector<ProofEntry> trimming_end_point_proofs();
std::vector<ProofEntry> arithmetic_proofs();
std::vector<ProofEntry> fixture_proofs();
std::vector<ProofEntry> hybrid_proofs();

}  // namespace splinex::proof_detail

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
};

// One case: (a random B-spline case, the seeded generator, the accumulator, the case number).
using CaseFn = std::function<void(const BSpline<Rational>&, std::mt19937_64&, Accumulator&, std::size_t)>;

// A named proof running fn on `cases` seeded cases.
ProofEntry entry(std::string name, std::string identity, std::string bound, CaseFn fn, std::uint64_t seed, bool expect_proved = true);

// The hybrid-patch proofs (papers/003), proofs/hybrid_proofs.cpp.
std::vector<ProofEntry> hybrid_proofs();

}  // namespace splinex::proof_detail

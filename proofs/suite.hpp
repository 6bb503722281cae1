// The named exact proofs of `splinex prove`. Each runs an identity check (proofs/identity.hpp)
// on a fixed, seeded set of random exact cases (curves, surfaces, trivariates; polynomial and
// rational; clamped and unclamped) and reports proved, or refuted with the exact counterexample.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "proofs/identity.hpp"

namespace splinex {

struct ProofReport {
  std::string name;
  std::string identity;
  std::string degree_bound;   // e.g. "max(p, p') per direction, up to 7"
  std::size_t cases = 0;
  std::size_t points = 0;     // exact evaluations compared, all cases
  std::size_t cells = 0;
  bool proved = true;
  std::string counterexample;  // first failing case, exact
  // A claim from a paper that splinex shows false (e.g. hybrid-thm-3.2 as stated) is expected to
  // be refuted: the run succeeds when every verdict is the expected one.
  bool expect_proved = true;
  bool as_expected() const { return proved == expect_proved; }
  std::string verdict() const {
    return std::string(proved ? "proved" : "refuted") + (as_expected() ? "" : expect_proved ? " (UNEXPECTED: should prove)" : " (UNEXPECTED: should refute)");
  }
};

struct ProofEntry {
  std::string name;
  std::string identity;
  std::function<ProofReport(std::size_t cases)> run;
};

const std::vector<ProofEntry>& proof_registry();

// Runs the named proofs (all when `names` is empty); unknown names throw UsageError.
std::vector<ProofReport> run_proofs(const std::vector<std::string>& names, std::size_t cases = 12);

}  // namespace splinex

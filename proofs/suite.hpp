// The named exact proofs of `splinex prove`. Each runs an identity check (proofs/identity.hpp)
// on a fixed, seeded set of random exact cases (curves, surfaces, trivariates; polynomial and
// rational; clamped and unclamped) and reports proved, or refuted with the exact counterexample.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "proofs/identity.hpp"

namespace splinex {

struct ProofReport {
  std::string name;
  std::string identity;
  std::string degree_bound;   // e.g. "max(p, p') per direction, up to 7"
  std::size_t cases = 0;
  std::size_t points = 0;     // exact evaluations (or coefficients) compared, all cases
  std::size_t cells = 0;
  bool holds = true;           // no counterexample found
  /// The claim is only checked pointwise (no degree bound and cells cover it): the verdict is then
  /// "checked at N points", never "proved".
  bool sampled = false;
  std::string undecided;       // non-empty: nothing (or not everything) could be decided, and why
  std::string counterexample;  // first failing case, exact
  std::vector<std::string> structures;  // input structures the cases contained (structured generator)
  int largest_degree = 0;      // the largest degree bound an identity check of the cases used
  /// A claim from a paper that splinex shows false (e.g. hybrid-thm-3.2 as stated) is expected to
  /// be refuted: the run succeeds when every verdict is the expected one.
  bool expect_proved = true;

  bool refuted() const { return !holds; }
  bool is_undecided() const { return holds && !undecided.empty(); }
  /// "proved", "checked at N points", "refuted" or "undecided".
  std::string verdict_word() const {
    if (!holds) return "refuted";
    if (!undecided.empty()) return "undecided";
    return sampled ? "checked at " + std::to_string(points) + " points" : "proved";
  }
  /// The JSON verdict: proved, checked, refuted or undecided.
  std::string verdict_key() const {
    if (!holds) return "refuted";
    if (!undecided.empty()) return "undecided";
    return sampled ? "checked" : "proved";
  }
  bool as_expected() const { return undecided.empty() ? holds == expect_proved : false; }
  /// One line: the verdict with the surprise marked ("refuted (expected)", "proved (UNEXPECTED:
  /// expected to be refuted)", "REFUTED", "undecided: why").
  std::string verdict() const {
    std::string v = verdict_word();
    if (is_undecided()) return v + ": " + undecided;
    if (!holds) return expect_proved ? "REFUTED" : "refuted (expected)";
    return expect_proved ? v : v + " (UNEXPECTED: expected to be refuted)";
  }
};

struct ProofEntry {
  std::string name;
  std::string identity;
  /// Cases first .. first + count - 1. Every case draws from a stream of its own (the proof's seed
  /// and the case number), so any range runs alone, on any machine: the sweep's ranges of cases.
  /// The report is raw: ranges merge (merge_proof_ranges), then `finish` gives the last words.
  std::function<ProofReport(std::size_t first, std::size_t count)> run_range;
  /// The last words of the report of all cases: undecided when no case ran or nothing was
  /// compared; the degree bound with the largest degree used.
  std::function<void(ProofReport&)> finish;
  /// The proof's cases are its own, not drawn (teapot-merge: the four teapot surfaces): it runs
  /// them all whatever the count, as one range.
  bool fixed_cases = false;
  bool expect_proved = true;  // as in ProofReport
  bool sampled = false;       // as in ProofReport

  /// Cases 0 .. cases - 1, finished.
  ProofReport run(std::size_t cases) const {
    ProofReport r = run_range(0, cases);
    finish(r);
    return r;
  }
};

/// The raw reports of consecutive ranges of one proof, in order from case 0, as one finished report:
/// equal to e.run(total cases). A gap or an overlap between the ranges is a std::logic_error.
ProofReport merge_proof_ranges(const ProofEntry& e, const std::vector<std::pair<std::size_t, ProofReport>>& ranges);

/// A raw range report as JSON and back (the proofs sweep's job results; exact counts, no timings).
nlohmann::json proof_range_json(const ProofReport& r);
ProofReport proof_range_from_json(const ProofEntry& e, const nlohmann::json& j);

const std::vector<ProofEntry>& proof_registry();

namespace proof_detail {
/// Test seam: a bug planted into every operation result the kernel and composition proofs check
/// (insertion, refinement, elevation, extraction, split, reparametrization, reversal, clamping,
/// hodograph, Bezier and B-spline composition), so tests can show that each proof refutes a
/// wrong result. Never set outside tests.
using PlantedBug = std::function<void(BSpline<Rational>&)>;
class ScopedPlantedBug {
 public:
  explicit ScopedPlantedBug(PlantedBug bug);
  ~ScopedPlantedBug();
  ScopedPlantedBug(const ScopedPlantedBug&) = delete;
  ScopedPlantedBug& operator=(const ScopedPlantedBug&) = delete;

 private:
  PlantedBug previous_;
};
BSpline<Rational> planted(BSpline<Rational> R);
/// The same for the hybrid-patch proofs (Theorems 3.1, 3.2 corrected, 4.1, 4.2): while alive, the
/// patch or form under test has the control points of side 0 moved ((k+1)(j+1)/7 for column j,
/// layer k; the form: by 1/7) (tests only).
class ScopedPlantedHybridBug {
 public:
  ScopedPlantedHybridBug();
  ~ScopedPlantedHybridBug();
  ScopedPlantedHybridBug(const ScopedPlantedHybridBug&) = delete;
  ScopedPlantedHybridBug& operator=(const ScopedPlantedHybridBug&) = delete;

 private:
  bool previous_;
};
}  // namespace proof_detail

/// The registry's entry named `name`, or nullptr when this splinex has no such proof.
const ProofEntry* find_proof(const std::string& name);

/// The named proofs (all when names is empty), in the order given (the registry's for all), each
/// on `cases` cases from its own seeded stream; `threads` run at once (the reports do not depend on
/// it: every proof is deterministic and the proofs share no mutable state). An unknown name throws
/// UsageError listing the proofs.
std::vector<ProofReport> run_proofs(const std::vector<std::string>& names, std::size_t cases = 12, std::size_t threads = 1);

/// The report as `splinex prove --json` prints it (no timings: the same on any machine).
nlohmann::json proof_report_json(const ProofReport& r);
/// `splinex prove --json`: the reports as one array.
nlohmann::json proof_reports_document(const std::vector<ProofReport>& reports);

}  // namespace splinex

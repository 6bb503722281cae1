// The registry of `splinex prove`: the proofs of every topic in one list (its order is the order of
// `splinex prove --list`), the seed of each proof's cases, the accumulator of identity checks, and
// the planted-bug seams the trust tests use.
#include <algorithm>
#include <exception>
#include <map>
#include <random>
#include <stdexcept>

#include "base/parallel.hpp"
#include "fixtures/random_spline.hpp"
#include "proofs/suite.hpp"
#include "proofs/suite_detail.hpp"

namespace splinex {

namespace proof_detail {

namespace {

// The seed of every proof's random cases (the numbers are historical: the proofs were numbered
// as they were written). A seed must never change: the counts and verdicts `splinex prove` prints
// depend on it, and scripts/behaviour_snapshot.py pins them. Case i of a proof draws from
// case_stream(seed, i), its own stream, so that a range of cases runs alone (issue 21: the proofs
// sweep splits a proof's cases into jobs); until then one stream ran through all cases.
const std::map<std::string, std::uint64_t>& seed_table() {
  static const std::map<std::string, std::uint64_t> seeds{
      {"knot-insertion-boehm", 101},
      {"knot-refinement-a54", 102},
      {"insertion-agreement", 103},
      {"degree-elevation-a59", 104},
      {"degree-elevation-blossom", 105},
      {"elevation-agreement", 106},
      {"bezier-extraction", 107},
      {"split", 108},
      {"reparametrize", 109},
      {"reverse", 110},
      {"clamp", 111},
      {"derivative-hodograph", 112},
      {"evaluation-deboor", 114},
      {"compose-methods-agree", 115},
      {"compose-identity", 116},
      {"compose-bspline", 117},
      {"compose-trimmed", 118},
      {"untrim-cover", 120},
      {"untrim-curved-cover", 121},
      {"trimming-endpoints", 119},
      {"flint-agreement", 113},
      {"ff-agreement", 122},
      {"hybrid-thm-3.1", 131},
      {"hybrid-thm-3.2", 132},
      {"hybrid-thm-3.2-corrected", 133},
      {"hybrid-thm-4.1", 141},
      {"hybrid-thm-4.2", 142},
      {"hybrid-salvi-elevation", 143},
  };
  return seeds;
}

// Case i's generator: the proof's seed and the case number through std::seed_seq, whose
// algorithm the standard fixes (the same cases on every platform and library).
std::mt19937_64 case_stream(std::uint64_t seed, std::size_t i) {
  const std::uint64_t n = i;
  std::seed_seq s{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32), static_cast<std::uint32_t>(n),
                  static_cast<std::uint32_t>(n >> 32)};
  return std::mt19937_64(s);
}

PlantedBug& planted_bug() {
  static PlantedBug bug;
  return bug;
}
}  // namespace

ScopedPlantedBug::ScopedPlantedBug(PlantedBug bug) : previous_(std::move(planted_bug())) { planted_bug() = std::move(bug); }
ScopedPlantedBug::~ScopedPlantedBug() { planted_bug() = std::move(previous_); }

BSpline<Rational> planted(BSpline<Rational> R) {
  if (planted_bug()) planted_bug()(R);
  return R;
}

// Aggregates the identity checks of one named proof over its cases.
void Accumulator::add(const IdentityCheck& c, std::size_t case_no) {
  rep.points += c.points;
  rep.cells += c.cells;
  for (int b : c.degree_bound) max_bound = std::max(max_bound, b);
  if (!c.holds && rep.holds) {
    rep.holds = false;
    rep.counterexample = "case " + std::to_string(case_no) + ": " + c.counterexample;
  }
  if (!c.decided()) undecided("an identity check had no cell to compare (an empty or inverted box)", case_no);
}

void Accumulator::fail(const std::string& why, std::size_t case_no) {
  if (rep.holds) {
    rep.holds = false;
    rep.counterexample = "case " + std::to_string(case_no) + ": " + why;
  }
}

void Accumulator::undecided(const std::string& why, std::size_t case_no) {
  if (rep.undecided.empty()) rep.undecided = "case " + std::to_string(case_no) + ": " + why;
}

void Accumulator::structures(const std::vector<std::string>& tags) {
  for (const auto& t : tags)
    if (std::find(rep.structures.begin(), rep.structures.end(), t) == rep.structures.end()) rep.structures.push_back(t);
}

void compare_nets(Accumulator& acc, const BSpline<Rational>& A, const BSpline<Rational>& B, const std::string& what,
                  std::size_t case_no) {
  if (!same_net(A, B)) return acc.fail(what, case_no);
  std::size_t n = A.points.size() + A.weights.size();
  for (const auto& K : A.knots) n += K.size();
  acc.compared(n);
}

ProofEntry entry(std::string name, std::string identity, std::string bound, CaseFn fn, EntryOptions options) {
  const auto found = seed_table().find(name);
  if (found == seed_table().end()) throw std::logic_error("proof " + name + " has no seed in the seed table");
  const std::uint64_t seed = found->second;
  ProofEntry e;
  e.name = name;
  e.identity = identity;
  e.expect_proved = options.expect_proved;
  e.sampled = options.sampled;
  e.run_range = [=](std::size_t first, std::size_t count) {
    Accumulator acc;
    acc.rep.name = name;
    acc.rep.identity = identity;
    acc.rep.expect_proved = options.expect_proved;
    acc.rep.sampled = options.sampled;
    for (std::size_t i = first; i < first + count; ++i) {
      std::mt19937_64 rng = case_stream(seed, i);
      const StructuredCase c = structured_case(rng);
      if (options.uses_case) acc.structures(c.structures);
      fn(c.spline, rng, acc, i);
      ++acc.rep.cases;
    }
    acc.rep.largest_degree = acc.max_bound;
    return acc.rep;
  };
  e.finish = [bound](ProofReport& r) {
    if (r.cases == 0) r.undecided = "no case was run (--cases 0)";
    else if (r.points == 0) r.undecided = "nothing was compared";
    r.degree_bound = bound + ", largest used: " + std::to_string(r.largest_degree);
  };
  return e;
}

}  // namespace proof_detail

namespace {

// Every topic's proofs, in the order of `splinex prove --list`.
std::vector<ProofEntry> make_registry() {
  std::vector<ProofEntry> r;
  for (auto topic : {proof_detail::kernel_proofs, proof_detail::composition_proofs, proof_detail::untrimming_proofs,
                     proof_detail::trimming_end_point_proofs, proof_detail::arithmetic_proofs,
                     proof_detail::fixture_proofs, proof_detail::hybrid_proofs})
    for (auto& e : topic()) r.push_back(std::move(e));
  return r;
}

}  // namespace

const std::vector<ProofEntry>& proof_registry() {
  static const std::vector<ProofEntry> registry = make_registry();
  return registry;
}

const ProofEntry* find_proof(const std::string& name) {
  for (const auto& e : proof_registry())
    if (e.name == name) return &e;
  return nullptr;
}

std::vector<ProofReport> run_proofs(const std::vector<std::string>& names, std::size_t cases, std::size_t threads) {
  const auto& reg = proof_registry();
  std::vector<const ProofEntry*> todo;
  if (names.empty()) {
    for (const auto& e : reg) todo.push_back(&e);
  } else {
    for (const auto& n : names) {
      const ProofEntry* e = find_proof(n);
      if (!e) {
        std::string all;
        for (const auto& x : reg) all += (all.empty() ? "" : ", ") + x.name;
        throw UsageError("prove", "unknown proof \"" + n + "\"", "use one of: " + all);
      }
      todo.push_back(e);
    }
  }
  std::vector<ProofReport> out(todo.size());
  parallel_for(todo.size(), threads, [&](std::size_t k) { out[k] = todo[k]->run(cases); });
  return out;
}

ProofReport merge_proof_ranges(const ProofEntry& e, const std::vector<std::pair<std::size_t, ProofReport>>& ranges) {
  if (ranges.empty()) throw std::logic_error("merge_proof_ranges: no range of " + e.name);
  ProofReport r = ranges.front().second;
  if (ranges.front().first != 0) throw std::logic_error("merge_proof_ranges: " + e.name + " does not start at case 0");
  std::size_t next = r.cases;
  for (std::size_t k = 1; k < ranges.size(); ++k) {
    const auto& [first, p] = ranges[k];
    if (e.fixed_cases || first != next)
      throw std::logic_error("merge_proof_ranges: " + e.name + " has a gap or an overlap at case " + std::to_string(first));
    next += p.cases;
    r.cases += p.cases;
    r.points += p.points;
    r.cells += p.cells;
    if (r.holds && !p.holds) {  // the first counterexample in case order, as one run finds it
      r.holds = false;
      r.counterexample = p.counterexample;
    }
    if (r.undecided.empty()) r.undecided = p.undecided;
    for (const auto& t : p.structures)
      if (std::find(r.structures.begin(), r.structures.end(), t) == r.structures.end()) r.structures.push_back(t);
    r.largest_degree = std::max(r.largest_degree, p.largest_degree);
  }
  e.finish(r);
  return r;
}

nlohmann::json proof_range_json(const ProofReport& r) {
  return {{"name", r.name}, {"cases", r.cases}, {"points", r.points}, {"cells", r.cells}, {"holds", r.holds},
          {"counterexample", r.counterexample}, {"undecided", r.undecided}, {"structures", r.structures},
          {"largest_degree", r.largest_degree}};
}

ProofReport proof_range_from_json(const ProofEntry& e, const nlohmann::json& j) {
  if (j.at("name").get<std::string>() != e.name) throw std::logic_error("proof_range_from_json: not a range of " + e.name);
  ProofReport r;
  r.name = e.name;
  r.identity = e.identity;
  r.expect_proved = e.expect_proved;
  r.sampled = e.sampled;
  r.cases = j.at("cases").get<std::size_t>();
  r.points = j.at("points").get<std::size_t>();
  r.cells = j.at("cells").get<std::size_t>();
  r.holds = j.at("holds").get<bool>();
  r.counterexample = j.at("counterexample").get<std::string>();
  r.undecided = j.at("undecided").get<std::string>();
  r.structures = j.at("structures").get<std::vector<std::string>>();
  r.largest_degree = j.at("largest_degree").get<int>();
  return r;
}

nlohmann::json proof_report_json(const ProofReport& r) {
  return {{"name", r.name}, {"identity", r.identity}, {"degree_bound", r.degree_bound}, {"cases", r.cases},
          {"cells", r.cells}, {"points", r.points}, {"verdict", r.verdict_key()},
          {"expected", r.expect_proved ? "holds" : "refuted"}, {"as_expected", r.as_expected()},
          {"structures", r.structures}, {"undecided", r.undecided}, {"counterexample", r.counterexample}};
}

nlohmann::json proof_reports_document(const std::vector<ProofReport>& reports) {
  nlohmann::json j = nlohmann::json::array();
  for (const auto& r : reports) j.push_back(proof_report_json(r));
  return j;
}

}  // namespace splinex

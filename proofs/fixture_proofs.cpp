// The fixtures are what they claim: the merged teapot surfaces equal their Bezier patches.
#include "fixtures/teapot.hpp"
#include "proofs/suite_detail.hpp"

namespace splinex::proof_detail {

namespace {

ProofEntry teapot_merge() {
  ProofEntry e;
  e.name = "teapot-merge";
  e.identity = "each merged teapot surface (body, handle, spout, lid) equals its Bezier patches, shifted to their cells";
  e.fixed_cases = true;  // the four surfaces, whatever the count
  e.run_range = [identity = e.identity](std::size_t, std::size_t) {
    Accumulator acc;
    acc.rep.name = "teapot-merge";
    acc.rep.identity = identity;
    const auto patches = read_bpt(data_path("teapot.bpt"));
    std::size_t case_no = 0;
    for (const auto& t : teapot_surfaces(patches)) {
      for (std::size_t J = 0; J < t.grid.size(); ++J)
        for (std::size_t I = 0; I < t.grid[J].size(); ++I) {
          std::vector<AffineMap1> phi(2);
          phi[0].shift = -Rational(static_cast<long>(I));
          phi[1].shift = -Rational(static_cast<long>(J));
          const std::vector<std::pair<Rational, Rational>> box{{Rational(static_cast<long>(I)), Rational(static_cast<long>(I + 1))},
                                                              {Rational(static_cast<long>(J)), Rational(static_cast<long>(J + 1))}};
          acc.add(prove_equal_on_box(planted(t.surface), patches[t.grid[J][I]], box, phi, ""), case_no);
        }
      ++acc.rep.cases;
      ++case_no;
    }
    acc.rep.largest_degree = acc.max_bound;
    return acc.rep;
  };
  e.finish = [](ProofReport& r) { r.degree_bound = "3 per direction (bicubic), largest used: " + std::to_string(r.largest_degree); };
  return e;
}

}  // namespace

std::vector<ProofEntry> fixture_proofs() { return {teapot_merge()}; }

}  // namespace splinex::proof_detail

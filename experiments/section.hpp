// A section of `splinex report`: one function with one signature, writing its files into the
// output folder and its part(s) of report.md into the context. experiments/report.cpp holds the
// list of sections (the order they run in) and the order of report.md's parts.
#pragma once
#include <algorithm>
#include <cstddef>
#include <functional>
#include <map>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "experiments/report.hpp"

namespace splinex {

struct ReportContext {
  ReportContext(const ReportOptions& o, std::function<void(const std::string&)> p) : options(o), progress(std::move(p)) {}
  const ReportOptions& options;
  std::function<void(const std::string&)> progress;  // "[report 12.3s] ..." on stderr
  /// One seeded stream for the sections that draw random inputs, in the order they run (the
  /// crosscheck suite, then the composition orders).
  std::mt19937_64 rng{20261121};
  std::map<std::string, std::string> markdown;  // report.md's parts by name
  /// Whether the section NAME runs in this report: text that refers to another section's results
  /// says so only then ({{?ran:NAME}} in a template, experiments/report_template.hpp).
  bool ran(const std::string& name) const {
    return options.sections.empty() || std::find(options.sections.begin(), options.sections.end(), name) != options.sections.end();
  }
  bool ok = true;                                // every section's own checks held
  /// For the closing progress line.
  std::size_t crosschecks = 0;
  bool float_structures_match = true;
  bool proofs_as_expected = true;
};

using Section = void (*)(ReportContext&);

/// The crosscheck suite: random, refinement, adversarial and teapot cases, exactly against every
/// float arithmetic; parts crosscheck.intro, crosscheck.figures, crosscheck.tables.
void crosscheck_section(ReportContext& ctx);
/// The composed orders of papers/000's examples (Section 3); part composition-orders.
void composition_orders_section(ReportContext& ctx);
/// The teapot star pattern (papers/000 Figure 4, Algorithm 1); part teapot-stars.
void teapot_stars_section(ReportContext& ctx);
/// The price of a trimming tolerance, measured exactly; part tolerance.
void tolerance_section(ReportContext& ctx);
/// Algorithm 2 on the star pattern (papers/000 Figure 5); part algorithm2-stars.
void algorithm2_stars_section(ReportContext& ctx);
/// The tolerance of untrimming (eps, continuity, precision); part untrim-tolerance.
void untrim_tolerance_section(ReportContext& ctx);
/// The checkerboard texture of Definition 1; part checkerboard.
void checkerboard_section(ReportContext& ctx);
/// Untrimming with curved tile sides; part curved-untrim.
void curved_untrim_section(ReportContext& ctx);
/// What A5.9 and the blossom lose when elevating in double; part elevation-accuracy.
void elevation_accuracy_section(ReportContext& ctx);
/// The hybrid patch (papers/003); part hybrid.
void hybrid_section(ReportContext& ctx);
/// V-rep: the gluing tolerance and float regularity, measured exactly; part vrep.
void vrep_section(ReportContext& ctx);
// V-rep Booleans (issue 18): Figure 3's counts against CGAL's Nef polyhedra, Figure 5's colour
// blend, the price of a tolerance in Booleans of nearly touching boxes.
void vrep_boolean_section(ReportContext& ctx);
/// Certified solving (issue 19): projection and contact, float solvers measured; part solve.
void solve_section(ReportContext& ctx);
/// Cutting curves (papers/004, issue 20): Table 1's examples, sampling density, Figure 10; part cut.
void cut_section(ReportContext& ctx);
/// papers/004 for d = 3: guiding surfaces, certified separation, coarse sampling; part cut3.
void cut3_section(ReportContext& ctx);
/// Freeform boundaries: the float SSI of the teapot's handle and spout with its body, judged exactly; part vrep-ssi.
void vrep_ssi_section(ReportContext& ctx);
/// The teapot's V-model (papers/002 Figure 14, Table 1) from freeform solids; part vrep-teapot.
void vrep_teapot_section(ReportContext& ctx);
/// The peers' results judged by verify, from ReportOptions::peers_dir; part peers.
void peers_section(ReportContext& ctx);
/// What exactness costs, from a scripts/run.sh bench run in ReportOptions::bench_dir; part exactness.
void exactness_section(ReportContext& ctx);
/// The exact proofs of `splinex prove`; part proofs.
void proofs_section(ReportContext& ctx);

}  // namespace splinex

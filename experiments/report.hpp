// `splinex report`: the crosscheck suite over bundled cases, written to DIR as report.md, CSV,
// JSON and SVG figures.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

namespace splinex {

struct ReportOptions {
  std::string out_dir = "results";
  bool full = false;  // the long sweep: larger cases, more precisions, longer refinements
  std::string peers_dir;  // the peers' judged results (scripts/run.sh peers); empty: not included
  /// Only these sections (names as in report_section_names()), in the report's order; empty: all.
  /// A part of the report lets a test run split the report over the cores; every section computes
  /// the same numbers alone as in the whole run (composition-orders shares crosscheck's seeded
  /// stream, so it needs crosscheck with it).
  std::vector<std::string> sections;
  /// Sections run at once on threads (0: every core). Each section (crosscheck with
  /// composition-orders, which draw from one seeded stream) computes in a context of its own, and
  /// the contexts are merged in the sections' order, so the files and report.md do not depend on
  /// it (times aside).
  std::size_t jobs = 0;
};

/// The sections' names in the order they run.
std::vector<std::string> report_section_names();

/// Returns the process exit status (0 when every proof held and every run finished).
int run_report(const ReportOptions& options);

}  // namespace splinex

// `splinex report`: the crosscheck suite over bundled cases, written to DIR as report.md, CSV,
// JSON and SVG figures.
#pragma once
#include <string>

namespace splinex {

struct ReportOptions {
  std::string out_dir = "results";
  bool full = false;  // the long sweep: larger cases, more precisions, longer refinements
  std::string peers_dir;  // the peers' judged results (scripts/run.sh peers); empty: not included
};

/// Returns the process exit status (0 when every proof held and every run finished).
int run_report(const ReportOptions& options);

}  // namespace splinex

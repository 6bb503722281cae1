// Report section `exactness`: what exactness costs, from one `scripts/run.sh bench` run (issue
// 49). The benchmarks run outside this process (Google Benchmark executables, Python's Fraction,
// SISL, OpenCASCADE) and write bench/results/exactness.md (scripts/bench_table.py); the section
// includes that table, which names its date, machine and library versions, from the folder given
// with `splinex report --bench DIR`, or says that it was not included and how to make it.
#include <filesystem>
#include <fstream>
#include <sstream>

#include "experiments/report_template.hpp"
#include "experiments/section.hpp"

namespace splinex {

void exactness_section(ReportContext& ctx) {
  namespace fs = std::filesystem;
  const std::string& dir = ctx.options.bench_dir;
  if (dir.empty()) {
    ctx.markdown["exactness"] = ReportTemplate("exactness").when("included", false).set("body", "").render();
    return;
  }
  ctx.progress("exactness from " + dir);
  std::ifstream in(fs::path(dir) / "exactness.md");
  std::ostringstream md;
  std::string line;
  bool title = true, start = true;
  while (std::getline(in, line)) {
    if (title && line.rfind("# ", 0) == 0) {  // the file's title: the template has the section's own
      title = false;
      continue;
    }
    if (start && line.empty()) continue;  // the blank lines after it: the template has one
    start = false;
    md << (!line.empty() && line.front() == '#' ? "#" : "") << line << "\n";  // headings one level down
  }
  ctx.markdown["exactness"] = ReportTemplate("exactness").when("included", true).set("body", md.str()).render();
}

}  // namespace splinex

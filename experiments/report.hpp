// `splinex report`: the crosscheck suite over bundled cases, written to DIR as report.md, CSV,
// JSON and SVG figures.
#pragma once
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace splinex {

struct ReportOptions {
  std::string out_dir = "results";
  bool full = false;  // the long sweep: larger cases, more precisions, longer refinements
  std::string peers_dir;  // the peers' judged results (scripts/run.sh peers); empty: not included
  std::string bench_dir;  // a scripts/run.sh bench run's tables (bench/results); empty: not included
  std::string command;    // the command report.md names; empty: the `splinex report` these options are
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
/// Every section with what it reproduces and its measured time: plain text for `report --help`,
/// or the Markdown table of docs/papers.md (`report --list-sections`; the test docs_generated
/// keeps the page equal to it).
std::string report_section_table(bool markdown);

/// Returns the process exit status (0 when every proof held and every run finished).
int run_report(const ReportOptions& options);

/// The report as independent tasks (the `report` sweep, issue 21): every chosen section alone,
/// crosscheck with composition-orders (one seeded stream), longest first. Empty: all sections.
std::vector<std::vector<std::string>> report_tasks(const std::vector<std::string>& sections);

/// One task's sections run into options.out_dir (a folder of its own); the result names its
/// markdown parts, its checks and the files it wrote.
nlohmann::json run_report_task(const ReportOptions& options, const std::vector<std::string>& task,
                               const std::function<void(const std::string&)>& progress);

/// The tasks' results (their files in task_dirs) merged into options.out_dir: the files copied,
/// report.md and MANIFEST.json written as run_report writes them. Returns the exit status.
int merge_report_tasks(const ReportOptions& options, const std::vector<nlohmann::json>& results,
                       const std::vector<std::string>& task_dirs, const std::function<void(const std::string&)>& progress);

}  // namespace splinex

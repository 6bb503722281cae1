// splinex report: the main job (experiments/): crosscheck suite, paper reproductions, figures.
#include <iostream>
#include <memory>

#include "apps/command.hpp"
#include "experiments/report.hpp"

namespace splinex::app {

Commands add_report(CLI::App& app) {
  auto o = std::make_shared<ReportOptions>();
  auto* c = app.add_subcommand("report", "the main job: crosscheck suite, figures, report.md");
  c->add_option("--out", o->out_dir, "output folder")->check(output_folder())->capture_default_str();
  c->add_flag("--full", o->full, "the long sweep (larger cases, more precisions)");
  c->add_option("--peers", o->peers_dir, "include the peers' judged results from this folder (scripts/run.sh peers writes "
                                         "results/peers)");
  c->add_option("--bench", o->bench_dir, "include what exactness costs from this folder (scripts/run.sh bench writes "
                                         "bench/results)");
  std::string names;
  for (const auto& n : report_section_names()) names += (names.empty() ? "" : ", ") + n;
  c->add_option("--sections", o->sections, "only these sections (comma-separated), for splitting the run: " + names)->delimiter(',');
  c->add_option("--jobs", o->jobs,
                 "sections run at once on threads (default 0: every core); the results do not depend on it, only the "
                 "order of the progress lines and the times do")
      ->check(CLI::Range(0, 1024))
      ->capture_default_str();
  auto list = std::make_shared<bool>(false);
  c->add_flag("--list-sections", *list, "print the sections as a Markdown table (what each reproduces, its time) and exit");
  c->footer(report_section_table(false));
  return {{c, [o, list](const Context&) {
             if (*list) {
               std::cout << report_section_table(true);
               return 0;
             }
             return run_report(*o);
           }}};
}

}  // namespace splinex::app

// splinex prove: the exact proofs by identity (proofs/), as text or JSON.
#include <algorithm>
#include <iostream>
#include <thread>
#include <memory>

#include "apps/command.hpp"
#include "base/parallel.hpp"
#include "proofs/suite.hpp"

namespace splinex::app {

namespace {

void print_text(const ProofReport& r) {
  std::cout << r.name << ": " << r.verdict() << "\n  identity: " << r.identity << "\n  degree bound: " << r.degree_bound
            << "\n  points: " << r.points << " exact comparisons in " << r.cells << " cells over " << r.cases << " cases\n";
  if (!r.structures.empty()) {
    std::cout << "  structures:";
    for (std::size_t k = 0; k < r.structures.size(); ++k) std::cout << (k ? ", " : " ") << r.structures[k];
    std::cout << "\n";
  }
  if (r.refuted()) std::cout << "  counterexample: " << r.counterexample << "\n";
}

}  // namespace

Commands add_prove(CLI::App& app) {
  struct Options {
    std::vector<std::string> names;
    bool as_document = false, list = false;
    long cases = 12;
    int jobs = 0;  // 0: every core
  };
  auto o = std::make_shared<Options>();
  auto* c = app.add_subcommand("prove", "run the exact proofs (proof by identity)");
  c->add_option("names", o->names, "proof names (default: all)");
  c->add_flag("--json", o->as_document, "JSON output");
  c->add_option("--cases", o->cases, "random exact cases per proof")->capture_default_str();
  c->add_flag("--list", o->list, "list the proof names");
  c->add_option("--jobs", o->jobs, "proofs run at once on threads (default 0: every core); the output does not depend on it")
      ->check(CLI::Range(0, 1024))
      ->capture_default_str();
  return {{c, [o](const Context&) {
             if (o->list) {
               for (const auto& e : proof_registry()) std::cout << e.name << "\t" << e.identity << "\n";
               return 0;
             }
             if (o->cases < 1 || o->cases > 100000)
               throw UsageError("cases", std::to_string(o->cases) + " is outside [1, 100000] (0 cases would check nothing)",
                                "give --cases N with 1 <= N <= 100000");
             bool all = true;
             std::vector<ProofReport> reports;
             const std::size_t threads = o->jobs > 0 ? static_cast<std::size_t>(o->jobs) : hardware_threads();
             for (const auto& r : run_proofs(o->names, static_cast<std::size_t>(o->cases), threads)) {
               all = all && r.as_expected();
               if (o->as_document) reports.push_back(r);
               else print_text(r);
             }
             if (o->as_document) print_document(proof_reports_document(reports), 2);
             return all ? 0 : 1;
           }}};
}

}  // namespace splinex::app

// `splinex report`: the sections (experiments/section.hpp) in the order they run, report.md
// assembled from their parts in the order it is read, and a manifest that only a finished run marks
// complete.
#include "experiments/report.hpp"
#include "io/output_path.hpp"

#include <algorithm>
#include <chrono>
#include <ctime>
#include <string_view>
#include <iterator>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <sstream>

#include "base/errors.hpp"
#include "base/parallel.hpp"
#include "experiments/common.hpp"
#include "experiments/report_template.hpp"
#include "experiments/section.hpp"
#include "experiments/svg_plot.hpp"
#include "proofs/suite.hpp"

namespace splinex {

void proofs_section(ReportContext& ctx) {
  ctx.progress("exact proofs");
  const auto proofs = run_proofs({}, ctx.options.full ? 40 : 12);
  std::ostringstream md;
  for (const auto& p : proofs) {
    ctx.proofs_as_expected = ctx.proofs_as_expected && p.as_expected();
    std::string structures;
    for (const auto& t : p.structures) structures += (structures.empty() ? "" : ", ") + t;
    md << "| " << p.name << " | " << (p.refuted() ? "**" + p.verdict() + "**: " + p.counterexample : p.verdict())
       << (p.as_expected() ? "" : " **UNEXPECTED**") << " | " << p.cases << " | "
       << p.points << " | " << p.degree_bound << " | " << structures << " |\n";
  }
  ctx.markdown["proofs"] = ReportTemplate("proofs").set("rows", md.str()).render();
  ctx.ok = ctx.ok && ctx.proofs_as_expected;
}

namespace {

// The one table of the report's sections (issue 48: a new section is one line here, its part in
// kDocument and its function in section.hpp). In the order they run when nothing reorders them (the
// crosscheck suite and the composition orders share one seeded stream, in this order).
//   seconds: the measured cost - each section alone, `splinex report --sections NAME --jobs 1`
//     on the 2-core development machine under a load of about 3, 2026-12-06 (wall clock) - so
//     that the longest start first when sections run on threads or as sweep jobs, and shown by
//     `report --help` and in docs/papers.md (generated: `splinex report --list-sections`). Only
//     the order of the work depends on it, never a result.
//   reproduces: the papers' figures and tables it reproduces (docs/papers.md has the details).
struct SectionInfo {
  const char* name;
  Section run;
  double seconds;
  const char* reproduces;
};
constexpr SectionInfo kSectionTable[] = {
    {"crosscheck", crosscheck_section, 47, "exact-vs-float errors of the kernel (no paper figure)"},
    {"composition-orders", composition_orders_section, 0.2, "papers/000 Figures 6-8: composed orders (runs with crosscheck)"},
    {"teapot-stars", teapot_stars_section, 51, "papers/000 Figure 4: the teapot's star pattern by Algorithm 1"},
    {"tolerance", tolerance_section, 35, "papers/000 Figure 9's kind: the price of a trimming tolerance"},
    {"algorithm2-stars", algorithm2_stars_section, 27, "papers/000 Figure 5: the star pattern by Algorithm 2"},
    {"untrim-tolerance", untrim_tolerance_section, 11, "the tolerance of untrimming (no paper figure)"},
    {"checkerboard", checkerboard_section, 2.2, "papers/000 Figure 3: the checkerboard texture"},
    {"curved-untrim", curved_untrim_section, 0.1, "papers/002 Figure 11's kind: tiles with curved sides"},
    {"hybrid", hybrid_section, 22, "papers/003 Figures 2.1, 3.2, 4.1, 4.2"},
    {"elevation-accuracy", elevation_accuracy_section, 5.7, "degree elevation in double (no paper figure)"},
    {"vrep", vrep_section, 2.1, "papers/002 Figures 1b, 7, 8, 9"},
    {"vrep-boolean", vrep_boolean_section, 46, "papers/002 Figures 3, 4, 5, 6, 15; Table 1's gluing times"},
    {"vrep-ssi", vrep_ssi_section, 19, "papers/002 Figure 10"},
    {"vrep-teapot", vrep_teapot_section, 59, "papers/002 Figure 14; Table 1's teapot row"},
    {"solve", solve_section, 51, "papers/002 Figure 12; Eq. 3 and 4"},
    {"cut", cut_section, 45, "papers/004 Figures 6, 8, 9; Table 1"},
    {"cut3", cut3_section, 156, "papers/004 Figures 1 and 6 (d = 3)"},
    {"peers", peers_section, 1, "SciPy, Octave NURBS and OpenCASCADE judged (needs --peers; no figure)"},
    {"exactness", exactness_section, 1, "what exactness costs: exact kernels, double, MPFR and peers in one benchmark run (needs --bench; no figure)"},
    {"proofs", proofs_section, 108, "the exact proofs of splinex prove"},
};
constexpr std::size_t kSectionCount = std::size(kSectionTable);
static_assert(std::string_view(kSectionTable[kSectionCount - 1].name) == "proofs", "the proofs run last (report.md's closing line reads it)");

double section_weight(std::size_t k) { return kSectionTable[k].seconds; }

// Sections that copy another program's results from a folder (--peers, --bench): no time of their own.
bool reads_folder(std::string_view name) { return name == "peers" || name == "exactness"; }

// report.md's parts in the order they are read.
const char* const kDocument[] = {
    "crosscheck.intro", "proofs",         "crosscheck.figures", "composition-orders", "teapot-stars",
    "tolerance",        "algorithm2-stars", "checkerboard",     "curved-untrim",      "untrim-tolerance",
    "hybrid",           "elevation-accuracy", "vrep", "vrep-boolean", "vrep-ssi", "vrep-teapot", "solve", "cut", "cut3", "peers", "exactness", "crosscheck.tables",
};

// Which sections run (every one when none is named); typed errors for unknown names and for
// composition-orders without crosscheck.
std::vector<char> chosen_sections(const std::vector<std::string>& sections) {
  std::vector<char> chosen(kSectionCount, sections.empty() ? 1 : 0);
  for (const auto& name : sections) {
    const auto it = std::find_if(std::begin(kSectionTable), std::end(kSectionTable), [&](const SectionInfo& x) { return name == x.name; });
    if (it == std::end(kSectionTable)) {
      std::string all;
      for (const auto& x : kSectionTable) all += (all.empty() ? "" : ", ") + std::string(x.name);
      throw UsageError("sections", "'" + name + "' is not a section", "give some of " + all);
    }
    chosen[static_cast<std::size_t>(it - std::begin(kSectionTable))] = 1;
  }
  if (chosen[1] && !chosen[0])
    throw UsageError("sections", "composition-orders draws from the crosscheck suite's seeded stream", "give crosscheck with it");
  return chosen;
}

// The tasks: every chosen section alone, but crosscheck and composition-orders together (one
// seeded stream, in this order). Longest first where known, so that cores finish together.
std::vector<std::vector<std::size_t>> report_task_list(const std::vector<char>& chosen) {
  std::vector<std::vector<std::size_t>> tasks;
  for (std::size_t k = 0; k < kSectionCount; ++k)
    if (chosen[k]) {
      if (k == 1 && chosen[0]) tasks.front().push_back(k);
      else tasks.push_back({k});
    }
  std::stable_sort(tasks.begin(), tasks.end(), [](const auto& a, const auto& b) { return section_weight(a.front()) > section_weight(b.front()); });
  return tasks;
}

// Runs one task's sections in a context of its own.
void run_task(const std::vector<std::size_t>& task, ReportContext& ctx) {
  for (std::size_t k : task) {
    const auto s0 = std::chrono::steady_clock::now();
    kSectionTable[k].run(ctx);
    ctx.progress(std::string("section ") + kSectionTable[k].name + " finished in " +
                 fmt(std::chrono::duration<double>(std::chrono::steady_clock::now() - s0).count(), 4) + " s");
  }
}

// Adds a task's context into the whole run's (the sections write distinct parts).
void absorb(ReportContext& into, ReportContext& c) {
  for (auto& [part, text] : c.markdown) into.markdown[part] = std::move(text);
  into.ok = into.ok && c.ok;
  into.crosschecks += c.crosschecks;
  into.float_structures_match = into.float_structures_match && c.float_structures_match;
  into.proofs_as_expected = into.proofs_as_expected && c.proofs_as_expected;
}

// report.md from the parts in reading order, and the manifest marked complete; the exit status.
int write_report(const ReportOptions& opt, ReportContext& ctx) {
  namespace fs = std::filesystem;
  const std::string manifest = opt.out_dir + "/MANIFEST.json";
  ctx.progress("writing " + opt.out_dir);
  // The title, the version, when and how it ran (the line "Run: ..." is the only one that differs
  // between two runs of the same sections: the comparisons of report.md drop it), then the parts
  // in reading order, then what ran.
  std::vector<std::string> ran;
  const auto chosen = chosen_sections(opt.sections);
  for (std::size_t k = 0; k < kSectionCount; ++k)
    if (chosen[k]) ran.emplace_back(kSectionTable[k].name);
  std::string command = opt.command.empty() ? "splinex report --out " + opt.out_dir : opt.command;
  if (opt.command.empty() && opt.full) command += " --full";
  if (opt.command.empty() && !opt.peers_dir.empty()) command += " --peers " + opt.peers_dir;
  if (opt.command.empty() && !opt.bench_dir.empty()) command += " --bench " + opt.bench_dir;
  if (opt.command.empty() && !opt.sections.empty()) {
    command += " --sections ";
    for (std::size_t i = 0; i < opt.sections.size(); ++i) command += (i ? "," : "") + opt.sections[i];
  }
  const std::time_t now = std::time(nullptr);
  char when[32];
  std::strftime(when, sizeof when, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
  std::string md = ReportTemplate("report.title").set("version", SPLINEX_VERSION).set("when", when).set("command", command).render();
  // Parts join with a blank line between them (one is added where a part ends and the next begins
  // without one: which parts meet depends on the sections chosen).
  const auto append = [&md](const std::string& text) {
    if (!text.empty() && text.front() != '\n' && md.size() >= 2 && md.compare(md.size() - 2, 2, "\n\n") != 0) md += "\n";
    md += text;
  };
  for (const char* part : kDocument)
    if (ctx.markdown.count(part)) append(ctx.markdown.at(part));
  std::string list;
  for (std::size_t i = 0; i < ran.size(); ++i) list += (i ? ", " : "") + ran[i];
  append(ReportTemplate("report.closing")
            .set("ran", ran.size())
            .set("sections", kSectionCount)
            .set("list", list)
            .when("ok", ctx.ok)
            .when("ran:proofs", chosen[kSectionCount - 1] != 0)
            .when("proofs_as_expected", ctx.proofs_as_expected)
            .set("crosschecks", ctx.crosschecks)
            .render());
  write_file_atomically(opt.out_dir + "/report.md", md);
  {
    std::ostringstream mf;
    mf << "{\"status\": \"complete\", \"files\": [";
    bool first = true;
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(opt.out_dir))
      if (e.is_regular_file() && e.path().filename() != "MANIFEST.json") names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    for (const auto& n : names) {
      mf << (first ? "" : ", ") << "\"" << n << "\"";
      first = false;
    }
    mf << "]}\n";
    write_file_atomically(manifest, mf.str());
  }
  ctx.progress(std::string("done: ") + std::to_string(ctx.crosschecks) + " crosschecks, proofs " +
               (ctx.proofs_as_expected ? "all verdicts as expected" : "UNEXPECTED VERDICT") +
               (ctx.float_structures_match ? "" : ", some float runs differ in structure (see report.md)"));
  return ctx.ok ? 0 : 1;
}

}  // namespace

std::vector<std::string> report_section_names() {
  std::vector<std::string> out;
  for (const auto& x : kSectionTable) out.emplace_back(x.name);
  return out;
}

std::string report_section_table(bool markdown) {
  std::ostringstream o;
  const auto time = [](double s) {
    std::ostringstream t;
    if (s >= 100) t << std::fixed << std::setprecision(1) << s / 60 << " min";
    else t << s << " s";
    return t.str();
  };
  double total = 0;
  for (const auto& x : kSectionTable)
    if (!reads_folder(x.name)) total += x.seconds;
  if (markdown) {
    std::ostringstream rows;
    for (const auto& x : kSectionTable) rows << "| " << x.name << " | " << x.reproduces << " | " << (reads_folder(x.name) ? "-" : time(x.seconds)) << " |\n";
    o << ReportTemplate("report.sections").set("rows", rows.str()).set("total", time(total)).render();
  } else {
    o << "Sections (what each reproduces; time alone with --jobs 1 on 2 cores under load, 2026-12-06):\n";
    for (const auto& x : kSectionTable)
      o << "  " << std::left << std::setw(20) << x.name << x.reproduces << (reads_folder(x.name) ? "" : "; " + time(x.seconds)) << "\n";
    o << "  all sections one after another (--jobs 1, without peers and exactness): " << time(total) << "; the default runs them on every core\n";
  }
  return o.str();
}

int run_report(const ReportOptions& opt) {
  namespace fs = std::filesystem;
  using clock = std::chrono::steady_clock;
  const auto t_start = clock::now();
  const auto chosen = chosen_sections(opt.sections);
  // The peers' folder is checked before minutes of work, not after.
  if (!opt.peers_dir.empty()) {
    if (!fs::is_directory(opt.peers_dir))
      throw UsageError("peers", opt.peers_dir + " is not a folder", "give the folder scripts/run.sh peers wrote (results/peers)");
    if (!fs::exists(fs::path(opt.peers_dir) / "scipy.md") && !fs::exists(fs::path(opt.peers_dir) / "octave.md") &&
        !fs::exists(fs::path(opt.peers_dir) / "occt.md"))
      throw UsageError("peers", opt.peers_dir + " holds no scipy.md, octave.md or occt.md", "run scripts/run.sh peers first");
  }
  if (!opt.bench_dir.empty() && !fs::exists(fs::path(opt.bench_dir) / "exactness.md"))
    throw UsageError("bench", opt.bench_dir + (fs::is_directory(opt.bench_dir) ? " holds no exactness.md" : " is not a folder"),
                     "give the folder scripts/run.sh bench wrote (bench/results), or run it first");
  prepare_output_folder(opt.out_dir, "out");
  // A manifest marked incomplete first: an interrupted run (Ctrl-C) leaves it so, and its files
  // cannot pass for a finished report. (prepare_output_folder has checked the folder is writable.)
  const std::string manifest = opt.out_dir + "/MANIFEST.json";
  write_file_atomically(manifest, "{\"status\": \"incomplete\", \"note\": \"a run started here and has not finished; "
                                  "files in this folder may be from it or from an older run\"}\n");
  std::mutex progress_lock;
  const std::function<void(const std::string&)> progress = [&](const std::string& s) {
    std::lock_guard<std::mutex> g(progress_lock);
    std::cerr << "[report " << std::fixed << std::setprecision(1) << std::chrono::duration<double>(clock::now() - t_start).count()
              << "s] " << s << std::endl;
  };
  const auto tasks = report_task_list(chosen);
  std::vector<std::unique_ptr<ReportContext>> contexts(tasks.size());
  const std::size_t threads = opt.jobs > 0 ? opt.jobs : hardware_threads();
  if (threads > 1) progress("sections on " + std::to_string(std::min(threads, tasks.size())) + " threads");
  parallel_for(tasks.size(), threads, [&](std::size_t t) {
    contexts[t] = std::make_unique<ReportContext>(opt, progress);
    run_task(tasks[t], *contexts[t]);  // (MPFR's per-thread caches: freed as each worker ends, base/parallel.hpp)
  });
  // One context as if the sections had run in one thread, in their order.
  ReportContext ctx{opt, progress};
  for (auto& c : contexts) absorb(ctx, *c);
  return write_report(opt, ctx);
}

std::vector<std::vector<std::string>> report_tasks(const std::vector<std::string>& sections) {
  std::vector<std::vector<std::string>> out;
  for (const auto& t : report_task_list(chosen_sections(sections))) {
    out.emplace_back();
    for (std::size_t k : t) out.back().push_back(kSectionTable[k].name);
  }
  return out;
}

nlohmann::json run_report_task(const ReportOptions& opt, const std::vector<std::string>& task,
                               const std::function<void(const std::string&)>& progress) {
  const auto tasks = report_task_list(chosen_sections(task));
  std::vector<std::string> names;
  if (tasks.size() == 1)
    for (std::size_t k : tasks.front()) names.push_back(kSectionTable[k].name);
  if (names != task)
    throw UsageError("sections", "are not one task of the report (a section alone, or crosscheck with composition-orders)",
                     "give the sections of one line of sweep plan report");
  std::filesystem::create_directories(opt.out_dir);
  ReportContext ctx{opt, progress};
  run_task(tasks.front(), ctx);
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(opt.out_dir))
    if (e.is_regular_file()) files.push_back(e.path().filename().string());
  std::sort(files.begin(), files.end());
  return {{"markdown", ctx.markdown}, {"ok", ctx.ok}, {"crosschecks", ctx.crosschecks},
          {"float_structures_match", ctx.float_structures_match}, {"proofs_as_expected", ctx.proofs_as_expected},
          {"files", files}};
}

int merge_report_tasks(const ReportOptions& opt, const std::vector<nlohmann::json>& results,
                       const std::vector<std::string>& task_dirs, const std::function<void(const std::string&)>& progress) {
  namespace fs = std::filesystem;
  fs::create_directories(opt.out_dir);
  ReportContext ctx{opt, progress};
  std::set<std::string> seen;
  for (std::size_t t = 0; t < results.size(); ++t) {
    const auto& r = results[t];
    for (const auto& f : r.at("files")) {
      const std::string name = f.get<std::string>();
      if (!seen.insert(name).second)
        throw DomainError("jobs", "two tasks wrote " + name, "give the jobs of one sweep plan report");
      const fs::path from = fs::path(task_dirs[t]) / name;
      if (!fs::is_regular_file(from))
        throw DomainError("jobs", from.string() + " is missing (its task's result names it)", "run that task again: delete its .json and rerun sweep run");
      fs::copy_file(from, fs::path(opt.out_dir) / name, fs::copy_options::overwrite_existing);
    }
    ReportContext c{opt, progress};
    c.markdown = r.at("markdown").get<std::map<std::string, std::string>>();
    c.ok = r.at("ok").get<bool>();
    c.crosschecks = r.at("crosschecks").get<std::size_t>();
    c.float_structures_match = r.at("float_structures_match").get<bool>();
    c.proofs_as_expected = r.at("proofs_as_expected").get<bool>();
    absorb(ctx, c);
  }
  return write_report(opt, ctx);
}
}  // namespace splinex

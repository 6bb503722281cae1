// Report section `peers`: the peers' results judged by verify (scripts/peers/judge_*.py, run by
// `scripts/run.sh peers`), included from the folder given with `splinex report --peers DIR`. The
// peers run outside this process (Python, Octave, OpenCASCADE); the section copies their tables
// and figures into the report and says where they came from, or that they were not run.
#include <filesystem>
#include <fstream>
#include <sstream>

#include "experiments/report_template.hpp"
#include "experiments/section.hpp"
#include "experiments/svg_plot.hpp"

namespace splinex {

void peers_section(ReportContext& ctx) {
  namespace fs = std::filesystem;
  const std::string& dir = ctx.options.peers_dir;
  if (dir.empty()) {
    ctx.markdown["peers"] = ReportTemplate("peers").when("included", false).set("peers", "").render();
    return;
  }
  std::ostringstream md;
  ctx.progress("peers from " + dir);
  for (const char* name : {"scipy", "octave", "occt"}) {
    const fs::path table = fs::path(dir) / (std::string(name) + ".md");
    if (!fs::exists(table)) {
      md << ReportTemplate("peers.missing").set("peer", name).set("dir", dir).render();
      continue;
    }
    std::ifstream in(table);
    std::string line;
    while (std::getline(in, line)) md << (line.rfind("# ", 0) == 0 ? "##" : "") << line << "\n";  // titles one level down
    md << "\n";
    for (const char* fig : {"_bits_vs_degree.svg", "_bits_vs_spacing.svg"}) {
      const fs::path src = fs::path(dir) / (std::string(name) + fig);
      if (fs::exists(src) && fs::path(ctx.options.out_dir) != fs::path(dir))
        fs::copy_file(src, fs::path(ctx.options.out_dir) / src.filename(), fs::copy_options::overwrite_existing);
    }
  }
  ctx.markdown["peers"] = ReportTemplate("peers").when("included", true).set("peers", md.str()).render();
}

}  // namespace splinex

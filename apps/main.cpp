// splinex: the command line, one thin layer over the libraries. Documents are read exactly,
// converted to the requested arithmetic by correct rounding, and written per arithmetic
// (fractions, round-trip doubles, all MPFR digits). Every splinex::Error exits with status 2.
// The commands live in apps/cmd_*.cpp; this file holds the global options and the error handling.
#include <CLI/CLI.hpp>

#include <filesystem>
#include <iostream>
#include <new>

#include "apps/command.hpp"
#include "exact/memory.hpp"

namespace sx = splinex;

namespace {

// A message on one line: input quoted in it may hold line breaks.
std::string one_line(std::string s) {
  std::string out;
  for (char c : s) {
    if (c == '\n') out += "\\n";
    else if (c == '\r') out += "\\r";
    else out += c;
  }
  while (!out.empty() && (out.back() == ' ')) out.pop_back();
  return out;
}

// The subcommands in the order of --help.
constexpr sx::app::Commands (*command_list[])(CLI::App&) = {
    sx::app::add_eval,  sx::app::add_operations, sx::app::add_compose, sx::app::add_crosscheck,
    sx::app::add_prove, sx::app::add_report,     sx::app::add_untrim,  sx::app::add_hybrid, sx::app::add_verify, sx::app::add_vrep,
    sx::app::add_project, sx::app::add_contact, sx::app::add_cut, sx::app::add_sweep,
};

}  // namespace

int main(int argc, char** argv) {
  // Memory exhaustion in GMP, MPFR or FLINT throws std::bad_alloc instead of aborting.
  sx::install_throwing_allocators();
  CLI::App app{"splinex: exact and floating B-spline algorithms, cross-checked exactly"};
  app.set_version_flag("--version", std::string("splinex ") + SPLINEX_VERSION, "print the version and exit");
  app.require_subcommand(1);
  sx::app::Context ctx;
  std::string max_memory = "auto";
  app.add_option("--max-memory", max_memory,
                 "memory budget (address space) of the whole run, e.g. 512M or 8G (at least 128M); auto: 3/4 of "
                 "physical memory (" + sx::format_bytes(sx::default_memory_budget()) + " here)")
      ->capture_default_str();
  app.add_option("--max-control-points", ctx.limits.max_control_points, "size limit per result spline (1 .. 10^9)")
      ->check(CLI::Range(1.0, 1e9))
      ->capture_default_str();
  app.add_option("--max-total-control-points", ctx.limits.max_total_control_points,
                 "size limit summed over the splines one command returns, e.g. untrimming's tiles (1 .. 10^10)")
      ->check(CLI::Range(1.0, 1e10))
      ->capture_default_str();
  app.add_option("--max-degree", ctx.limits.max_degree, "degree limit per direction (0 .. 10^8)")
      ->check(CLI::Range(0.0, 1e8))
      ->capture_default_str();
  app.add_option("--max-input-bits", ctx.limits.max_input_bits,
                 "the longest number (numerator or denominator, bits) of a model read by V-rep, cut or hybrid, checked "
                 "when it is read (64 .. 10^7)")
      ->check(CLI::Range(64.0, 1e7))
      ->capture_default_str();
  sx::app::Commands commands;
  for (auto add : command_list)
    for (auto& c : add(app)) commands.push_back(std::move(c));

  try {
    try {
      app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
      return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
      return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
      return app.exit(e);
    } catch (const CLI::ParseError& e) {
      // CLI11's own errors (missing, unknown or repeated option, value not in the set, failed
      // conversion) in the one-line format of every other user error.
      std::cerr << "splinex: error: options: " << one_line(e.what())
                << " (fix: see splinex --help, or splinex COMMAND --help)\n";
      return 2;
    }
    sx::set_memory_budget(max_memory == "auto" ? sx::default_memory_budget() : sx::parse_memory_size(max_memory, "max-memory"));
    ctx.read_limits = sx::ReadLimits::from(ctx.limits);
    for (const auto& c : commands)
      if (c.cli->parsed()) return c.run(ctx);
  } catch (const sx::Error& e) {
    std::cerr << "splinex: error: " << one_line(e.what()) << "\n";
    return 2;
  } catch (const std::filesystem::filesystem_error& e) {
    std::cerr << "splinex: error: " << one_line(e.path1().string()) << ": " << one_line(e.code().message())
              << " (fix: give a path that can be read or written)\n";
    return 2;
  } catch (const std::length_error&) {
    // A container asked for more elements than it can address: a size no budget can hold.
    std::cerr << "splinex: error: memory: a result too large to allocate (fix: ask for a smaller result, or lower "
                 "--max-control-points)\n";
    return 2;
  } catch (const std::bad_alloc&) {
    const auto& b = sx::current_memory_budget();
    std::cerr << "splinex: error: memory: out of memory"
              << (b.enforced ? " within the budget of " + sx::format_bytes(b.bytes) : std::string())
              << " (fix: ask for a smaller result, lower --max-control-points, or raise --max-memory)\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "splinex: internal error: " << one_line(e.what()) << " (please report this with the input)\n";
    return 1;
  }
  return 0;
}

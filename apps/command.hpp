// The command line's parts: every subcommand lives in a file of its own (apps/cmd_*.cpp) and is
// added to the main app by one function; main.cpp holds the global options, the list of those
// functions and the one-line error handling.
#pragma once
#include <CLI/CLI.hpp>

#include <functional>
#include <string>
#include <vector>

#include "base/limits.hpp"
#include "crosscheck/operations.hpp"
#include "io/documents.hpp"
#include "io/output_path.hpp"

namespace splinex::app {

/// CLI11 checks for options that name an output file or folder: a bad path is refused while the
/// options are read, before any work (`splinex: error: options: --obj: . is a folder, not a file`).
inline CLI::Validator output_file() {
  return CLI::Validator([](std::string& s) { return output_file_problem(s); }, "FILE");
}
inline CLI::Validator output_folder() {
  return CLI::Validator([](std::string& s) { return output_folder_problem(s); }, "DIR");
}

/// What a command sees when it runs: the global limits (--max-control-points, --max-degree).
struct Context {
  Limits limits;
  ReadLimits read_limits;
};

/// One subcommand as added to the main app; run is called when it was the one parsed, and returns
/// the exit status.
struct Command {
  CLI::App* cli = nullptr;
  std::function<int(const Context&)> run;
};
using Commands = std::vector<Command>;

// Each adds its subcommand(s) to app; main adds them in this order (the order of --help).
Commands add_eval(CLI::App& app);
Commands add_operations(CLI::App& app);  // one subcommand per row of operation_table()
Commands add_compose(CLI::App& app);
Commands add_crosscheck(CLI::App& app);
Commands add_prove(CLI::App& app);
Commands add_report(CLI::App& app);
Commands add_untrim(CLI::App& app);
Commands add_hybrid(CLI::App& app);
Commands add_verify(CLI::App& app);  // verify OPERATION --input --candidate
Commands add_vrep(CLI::App& app);  // vrep construct, vrep certify
Commands add_project(CLI::App& app);  // project --point (solve/projection.hpp)
Commands add_contact(CLI::App& app);  // contact (solve/contact.hpp)
Commands add_cut(CLI::App& app);  // cut example, cut guide (cut/)
Commands add_sweep(CLI::App& app);  // sweep plan, run, merge, single (experiments/sweep.hpp)

/// A surface argument: a spline document's path (- for stdin), or teapot:body|handle|spout|lid
/// (the merged surfaces of the Utah teapot).
BSpline<Rational> read_surface_argument(const std::string& what, const std::string& field, const Context& ctx);

// OpOptions and make_op (an operation from its text options) are in crosscheck/operations.hpp.

/// Parsed numbers that must be whole and in [0, hi] (derivative orders, exponents); else
/// UsageError(field, what, fix).
std::vector<int> whole_numbers(const std::vector<Rational>& numbers, const std::string& field, int hi,
                               const std::string& what, const std::string& fix);

/// --arith's help for the kernel's commands (KernelArithmetics).
inline const char* const kernel_arith_help =
    "exact (fraction-free integers; GMP where an operation is not written so), gmp (GMP mpq per coefficient), "
    "flint (FLINT fmpq per coefficient), double or mpfr:BITS";

/// The option every computing command has.
inline CLI::Option* add_arith_option(CLI::App* c, std::string& arith, const std::string& which) {
  return c->add_option("--arith", arith, which)->capture_default_str();
}

}  // namespace splinex::app

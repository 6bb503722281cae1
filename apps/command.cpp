// Helpers the commands share (apps/command.hpp).
#include "apps/command.hpp"

#include <boost/multiprecision/number.hpp>

#include "experiments/vrep_ssi.hpp"

namespace splinex::app {

std::vector<int> whole_numbers(const std::vector<Rational>& numbers, const std::string& field, int hi,
                               const std::string& what, const std::string& fix) {
  std::vector<int> out;
  for (const auto& r : numbers) {
    if (boost::multiprecision::denominator(r) != 1 || r < 0 || r > hi) throw UsageError(field, what, fix);
    out.push_back(static_cast<int>(boost::multiprecision::numerator(r).template convert_to<long>()));
  }
  return out;
}

BSpline<Rational> read_surface_argument(const std::string& what, const std::string& field, const Context& ctx) {
  if (what.rfind("teapot:", 0) == 0) return teapot_surface(what.substr(7));
  return read_spline(what, ctx.limits, ctx.read_limits, field);
}

}  // namespace splinex::app

#include "io/bpt.hpp"

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "base/errors.hpp"
#include "spline/factories.hpp"

namespace splinex {

std::vector<BSpline<Rational>> read_bpt(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw UsageError(path, "cannot open the file", "check the path (data/teapot.bpt)");
  std::string line;
  std::size_t lineno = 0;
  auto next = [&](const std::string& what) {
    while (std::getline(in, line)) {
      ++lineno;
      if (line.find_first_not_of(" \t\r") != std::string::npos) return;
    }
    throw ParseError(path, "ends early, expected " + what, "give the complete .bpt file");
  };
  auto field = [&]() { return path + ":" + std::to_string(lineno); };
  next("the patch count");
  const Rational count = parse_number(line, field());
  if (denominator(count) != 1 || count < 1 || count > 100000)
    throw ParseError(field(), "the patch count is not a whole number in [1, 100000]", "put the number of patches on line 1");
  std::vector<BSpline<Rational>> patches;
  for (long k = 0; k < count; ++k) {
    next("the degrees of patch " + std::to_string(k));
    std::istringstream ds(line);
    int du = -1, dv = -1;
    if (!(ds >> du >> dv) || du < 1 || dv < 1 || du > 30 || dv > 30)
      throw ParseError(field(), "expected two degrees in [1, 30]", "write \"du dv\", e.g. \"3 3\"");
    BSpline<Rational> P;
    P.degrees = {du, dv};
    P.q = 3;
    for (int d : {du, dv}) P.knots.push_back(clamped_knots(d, Rational(0), Rational(1)));
    for (int i = 0; i < (du + 1) * (dv + 1); ++i) {
      next("a control point of patch " + std::to_string(k));
      std::istringstream ps(line);
      std::string x[3], extra;
      if (!(ps >> x[0] >> x[1] >> x[2]) || (ps >> extra))
        throw ParseError(field(), "expected three coordinates", "write \"x y z\"");
      for (const auto& c : x) P.points.push_back(parse_number(c, field()));
    }
    validate(P);
    patches.push_back(std::move(P));
  }
  return patches;
}

BSpline<Rational> merge_bezier_grid(const std::vector<BSpline<Rational>>& patches,
                                    const std::vector<std::vector<int>>& rows, const std::string& name) {
  if (rows.empty() || rows[0].empty()) throw ValidationError(name, "the patch grid is empty", "list patch indices");
  const std::size_t nr = rows.size(), nc = rows[0].size();
  for (const auto& r : rows)
    if (r.size() != nc) throw ValidationError(name, "the patch grid is ragged", "give every row the same length");
  for (const auto& r : rows)
    for (int i : r)
      if (i < 0 || static_cast<std::size_t>(i) >= patches.size())
        throw ValidationError(name, "patch index " + std::to_string(i) + " does not exist", "use indices of the file");
  const auto& first = patches[rows[0][0]];
  const int du = first.degrees[0], dv = first.degrees[1], q = first.q;
  for (const auto& r : rows)
    for (int i : r)
      if (patches[i].degrees != first.degrees || patches[i].is_rational())
        throw ValidationError(name, "patch " + std::to_string(i) + " has other degrees", "merge patches of equal degrees");
  BSpline<Rational> S;
  S.degrees = {du, dv};
  S.q = q;
  for (auto [d, n] : {std::pair<int, std::size_t>{du, nc}, std::pair<int, std::size_t>{dv, nr}}) {
    std::vector<Rational> interior;  // the patch boundaries 1 .. n-1, each of multiplicity d (C^0)
    for (std::size_t j = 1; j < n; ++j) interior.insert(interior.end(), d, Rational(static_cast<long>(j)));
    S.knots.push_back(clamped_knots(d, Rational(0), Rational(static_cast<long>(n)), interior));
  }
  const std::size_t NU = nc * du + 1, NV = nr * dv + 1;
  S.points.assign(NU * NV * q, Rational(0));
  std::vector<int> owner(NU * NV, -1);
  for (std::size_t J = 0; J < nr; ++J)
    for (std::size_t I = 0; I < nc; ++I) {
      const int id = rows[J][I];
      const auto& P = patches[id];
      for (int j = 0; j <= dv; ++j)
        for (int i = 0; i <= du; ++i) {
          const std::size_t g = (J * dv + j) * NU + (I * du + i);
          const std::size_t l = static_cast<std::size_t>(j) * (du + 1) + i;
          for (int c = 0; c < q; ++c) {
            const Rational& v = P.points[l * q + c];
            if (owner[g] >= 0 && S.points[g * q + c] != v)
              throw ValidationError(name,
                                    "patches " + std::to_string(owner[g]) + " and " + std::to_string(id) +
                                        " do not share their common edge exactly",
                                    "merge only patches whose shared boundary control points are equal");
            S.points[g * q + c] = v;
          }
          owner[g] = id;
        }
    }
  validate(S);
  return S;
}

}  // namespace splinex

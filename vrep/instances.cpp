// The V-rep templates instantiated for the V-rep's arithmetics (SPLINEX_VREP_ARITHMETICS,
// float/arith_spec.hpp).
#include "float/arith_spec.hpp"
#include "float/mpfr.hpp"
#include "float/rounding.hpp"
#include "spline/bezier.hpp"
#include "spline/evaluate.hpp"
#include "vrep/boolean/boolean_impl.hpp"
#include "vrep/model/regularity_impl.hpp"
#include "vrep/model/trivariate_impl.hpp"
#include "vrep/model/vmodel_impl.hpp"
#include "vrep/primitives/primitives_impl.hpp"
#include "vrep/trimmed/enclosure_impl.hpp"
#include "vrep/trimmed/trimmed_impl.hpp"

namespace splinex {

SphereDeviation sphere_deviation(const BSpline<Rational>& S, const std::vector<Rational>& centre, const Rational& r, int samples) {
  validate(S);
  if (S.dim() != 2 || S.q < 3) throw ValidationError("surface", "is not a surface in R^3", "give a surface S(u, v)");
  if (centre.size() != 3) throw ValidationError("centre", "needs three coordinates", "give x,y,z");
  if (!(Rational(0) < r)) throw ValidationError("radius", "must be positive", "give a positive radius");
  if (samples < 2) throw ValidationError("samples", "needs at least 2 per direction", "give samples >= 2");
  SphereDeviation out;
  bool first = true;
  const Rational r2 = r * r;
  for (const auto& piece : extract_bezier(S)) {
    const auto& B = piece.spline;
    // Homogeneous W and W (x_a - c_a); E = sum_a (W (x_a - c_a))^2 - r^2 W^2 = W^2 (|x - c|^2 - r^2).
    Bernstein<Rational> w{B.degrees, {}}, e;
    for (std::size_t i = 0; i < B.size(); ++i) w.c.push_back(B.is_rational() ? B.weights[i] : Rational(1));
    const auto w2 = bern_product(w, w);
    e = w2;
    for (auto& x : e.c) x *= -r2;
    for (int a = 0; a < 3; ++a) {
      Bernstein<Rational> x{B.degrees, {}};
      for (std::size_t i = 0; i < B.size(); ++i) x.c.push_back(w.c[i] * (B.points[i * B.q + a] - centre[a]));
      const auto x2 = bern_product(x, x);
      for (std::size_t i = 0; i < e.c.size(); ++i) e.c[i] += x2.c[i];
    }
    Rational emax(0), wmin = w2.c.front();
    for (const auto& x : e.c) emax = std::max(emax, abs(x));
    for (const auto& x : w2.c) wmin = std::min(wmin, x);
    if (!(Rational(0) < wmin))
      throw ValidationError("surface.weights", "has a Bezier piece whose W^2 is not bounded away from 0 by its coefficients",
                            "give positive weights");
    const Rational b = emax / (r2 * wmin);
    if (first || out.bound < b) out.bound = b;
    first = false;
  }
  for (int j = 0; j < samples; ++j)
    for (int i = 0; i < samples; ++i) {
      std::vector<Rational> x(2);
      for (int d = 0; d < 2; ++d) {
        const Rational f = Rational(d == 0 ? i : j) / Rational(samples - 1);
        x[d] = S.domain_lo(d) + f * (S.domain_hi(d) - S.domain_lo(d));
      }
      const auto p = evaluate(S, x);
      Rational d2(0);
      for (int a = 0; a < 3; ++a) d2 += (p[a] - centre[a]) * (p[a] - centre[a]);
      const Rational dev = abs(d2 / r2 - Rational(1));
      if (out.at.empty() || out.witness < dev) {
        out.witness = dev;
        out.at = x;
      }
    }
  return out;
}

const char* to_string(BooleanOp op) {
  return op == BooleanOp::intersect ? "intersect" : op == BooleanOp::subtract ? "subtract" : "union";
}

BooleanOp parse_boolean_op(const std::string& name) {
  if (name == "intersect") return BooleanOp::intersect;
  if (name == "subtract") return BooleanOp::subtract;
  if (name == "union") return BooleanOp::unite;
  throw ValidationError("operation", "is \"" + name + "\"", "give intersect, subtract or union");
}

Blend parse_blend(const std::string& name) {
  if (name == "sum-clipped") return Blend::sum_clipped;
  if (name == "sum") return Blend::sum;
  if (name == "first") return Blend::first;
  throw ValidationError("blend", "is \"" + name + "\"", "give sum-clipped, sum or first");
}

Region<double> region_to_double(const Region<Rational>& R) {
  Region<double> out;
  out.kind = static_cast<Region<double>::Kind>(R.kind);
  out.label = R.label;
  for (const auto& [e, c] : R.g.terms) out.g.terms[e] = round_checked<double>(c, "region" + (R.label.empty() ? std::string() : " (" + R.label + ")"));
  for (const auto& p : R.parts) out.parts.push_back(region_to_double(p));
  return out;
}

TrimmedModel<double> trimmed_to_double(const TrimmedModel<Rational>& M) {
  TrimmedModel<double> out;
  for (std::size_t t = 0; t < M.trivariates.size(); ++t)
    out.trivariates.push_back(round_spline<double>(M.trivariates[t], "trivariates[" + std::to_string(t) + "]"));
  out.region = region_to_double(M.region);
  for (const auto& c : M.cells) {
    TrimmedModel<double>::Cell x;
    x.trivariate = c.trivariate;
    x.trim = region_to_double(c.trim);
    x.name = c.name;
    x.category = c.category;
    x.inherited = c.inherited;
    x.status = c.status;
    for (const auto& [n, v] : c.constants)
      for (const auto& y : v) x.constants[n].push_back(round_checked<double>(y, "constants." + n));
    for (const auto& [n, F] : c.fields) x.fields.emplace(n, round_spline<double>(F, "fields." + n));
    x.not_carried = c.not_carried;
    out.cells.push_back(std::move(x));
  }
  return out;
}

const char* to_string(Truth t) {
  return t == Truth::in ? "in" : t == Truth::out ? "out" : "mixed";
}

const char* regularity_name(const Verdict& v) {
  return v.is_proved() ? "regular" : v.is_refuted() ? "singular" : status_name(v.status());
}

#define SPLINEX_INSTANTIATE_VREP(T)                                                                                 \
  template BSpline<T> extrude(const BSpline<T>&, const std::vector<T>&, const Limits&);                              \
  template BSpline<T> ruled(const BSpline<T>&, const BSpline<T>&, const Limits&);                                    \
  template BSpline<T> revolve(const BSpline<T>&, int, int, const Limits&);                                           \
  template BSpline<T> rational_circle(int);                                                                          \
  template BSpline<T> boolean_sum(const std::array<std::array<BSpline<T>, 2>, 3>&, const Limits&);                   \
  template BSpline<T> coons_surface(const std::array<std::array<BSpline<T>, 2>, 2>&, const Limits&);                 \
  template BSpline<T> tube_boolean_sum(const BSpline<T>&, const Limits&);                                            \
  template BSpline<T> sweep(const std::vector<BSpline<T>>&, const std::vector<T>&, int, const Limits&);              \
  template BSpline<T> face(const BSpline<T>&, int, int);                                                             \
  template RegularityReport<T> certify_regularity(const BSpline<T>&, int, const Limits&);                            \
  template BSpline<T> jacobian_determinant(const BSpline<T>&, const Limits&);                                        \
  template struct VModel<T>;                                                                                         \
  template VModel<T> glue(const std::vector<BSpline<T>>&, const T&, const std::vector<std::string>&, const Limits&);   \
  template VModelCheck check_invariants(const VModel<T>&, const Limits&);                                            \
  template std::size_t surface_of_face(const VModel<T>&, std::size_t, int, int);                                     \
  template std::size_t curve_of_edge(const VModel<T>&, std::size_t, int, const std::array<int, 3>&);                 \
  template void attach_field(VModel<T>&, std::size_t, const std::string&, BSpline<T>, const Limits&);                \
  template void require_field_on(const BSpline<T>&, const BSpline<T>&, const std::string&, const Limits&); \
  template CellValue<T> evaluate_cell(const VModel<T>&, std::size_t, const std::vector<T>&);                        \
  template BSpline<T> edge_curve(const BSpline<T>&, int, const std::array<int, 3>&);                                 \
  template bool same_curve(const BSpline<T>&, const BSpline<T>&, const T&, bool, const Limits&);                     \
  template bool same_surface(const BSpline<T>&, const BSpline<T>&, const T&, const Limits&);                         \
  template std::vector<BSpline<T>> disk_cells(const T&);                                                             \
  template std::vector<BSpline<T>> cylinder_cells(const T&, const T&);                                               \
  template std::vector<BSpline<T>> cone_cells(const T&, const T&, const T&);                                         \
  template std::vector<BSpline<T>> torus_cells(const T&, const T&);                                                  \
  template std::vector<BSpline<T>> box_cells(const std::vector<T>&, const std::vector<T>&);                          \
  template std::vector<BSpline<T>> sphere_cells(const T&, int, int);                                                \
  template BSpline<T> singular_cylinder(const T&, const T&);                                                         \
  template BSpline<T> singular_sphere(const T&);                                                                      \
  template std::optional<std::vector<HalfSpace<T>>> convex_planes(const BSpline<T>&, const T&);                      \
  template std::vector<std::vector<T>> face_corners(const BSpline<T>&, int, int);                                    \
  template std::optional<HalfSpace<T>> face_plane(const BSpline<T>&, int, int, const T&);                      \
  template VModel<T> boolean_op(const VModel<T>&, const VModel<T>&, BooleanOp, const T&, Blend, const Limits&,        \
                                BooleanStats<T>*);                                                                   \
  template T cell_volume(const VModel<T>&, std::size_t, const Limits&);                                              \
  template VolumeEnclosure<T> volume_enclosure(const BSpline<T>&, std::size_t, const Limits&);                                              \
  template std::vector<std::size_t> cells_containing(const VModel<T>&, const std::vector<T>&, const T&);

// Trimmed cells.
#define SPLINEX_INSTANTIATE_TRIMMED(T)                                                                              \
  template int Poly3<T>::degree() const;                                                                             \
  template Region<T> region_leaf(Poly3<T>, std::string);                                                             \
  template Region<T> region_and(std::vector<Region<T>>);                                                             \
  template Region<T> region_or(std::vector<Region<T>>);                                                              \
  template Region<T> region_not(Region<T>);                                                                          \
  template Region<T> box_region(const std::vector<T>&, const std::vector<T>&);                                       \
  template Region<T> cylinder_region(const T&, const T&);                                                            \
  template Region<T> cone_region(const T&, const T&, const T&);                                                      \
  template Region<T> torus_region(const T&, const T&);                                                               \
  template Region<T> ball_region(const std::array<T, 3>&, const T&);                                                 \
  template Region<T> sphere_region(const T&, int, int);                                                                \
  template std::optional<std::vector<T>> cases_cover_gap(const Region<T>&, const std::vector<BSpline<T>>&, int);                     \
  template Region<T> region_cases(std::vector<std::pair<Region<T>, Region<T>>>);                                       \
  template std::optional<Region<T>> planar_region(const VModel<T>&, const T&);                                       \
  template Region<T> place_region(const Region<T>&, int, const std::vector<T>&);                                     \
  template BSpline<T> place_trivariate(const BSpline<T>&, int, const std::vector<T>&);                               \
  template T poly_at(const Poly3<T>&, const T*);                                                                     \
  template Truth classify_point(const Region<T>&, const std::vector<T>&, const T&);                                  \
  template TrimmedModel<T> as_trimmed(const VModel<T>&, Region<T>);                                                  \
  template TrimmedModel<T> placed_primitive(std::vector<BSpline<T>>, const Region<T>&, int, const std::vector<T>&);    \
  template const char* to_string<T>(const Uncertain<typename CellClass<T>::Kind>&);                                                    \
  template CellClass<T> classify_cell(const BSpline<T>&, const Region<T>&, const TrimOptions&, const T&, const Limits&); \
  template TrimmedModel<T> trimmed_boolean(const TrimmedModel<T>&, const TrimmedModel<T>&, BooleanOp, Blend, const TrimOptions&, \
                                           const T&, const Limits&);                                                 \
  template VolumeEnclosure<T> trimmed_volume(const BSpline<T>&, const Region<T>&, std::size_t, const Limits&, const T&);       \
  template MomentEnclosure<T> trimmed_moment(const BSpline<T>&, const Region<T>&, int, std::size_t, const Limits&, const T&);  \
  template MomentEnclosure<T> trimmed_field_integral(const BSpline<T>&, const Region<T>&, const BSpline<T>&, int, std::size_t, const Limits&, const T&); \
  template IntegralEnclosures<T> integral_enclosures(const std::vector<IntegrandCell<T>>&, const std::vector<int>&, const T&, std::size_t, const Limits&); \
  template std::vector<std::string> check_region(const VModel<T>&, const Region<T>&, const TrimOptions&, const Limits&);

SPLINEX_VREP_ARITHMETICS(SPLINEX_INSTANTIATE_TRIMMED)
SPLINEX_VREP_ARITHMETICS(SPLINEX_INSTANTIATE_VREP)

}  // namespace splinex

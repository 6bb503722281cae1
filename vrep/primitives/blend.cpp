#include "vrep/primitives/blend.hpp"

#include <mpfi.h>
#include <mpfr.h>

#include "base/errors.hpp"
#include "base/point.hpp"
#include "spline/evaluate.hpp"
#include "vrep/boolean/boolean_impl.hpp"  // vrep_detail::affine_inverse

namespace splinex {

namespace {

using P3 = Point3<Rational>;


std::vector<std::vector<HalfSpace<Rational>>> cell_planes(const VModel<Rational>& M, const std::string& name) {
  std::vector<std::vector<HalfSpace<Rational>>> out;
  for (std::size_t c = 0; c < M.cells.size(); ++c) {
    auto P = convex_planes(M.trivariates[M.cells[c].trivariates.front()]);
    if (!P)
      throw DomainError(name + ".cells[" + std::to_string(c) + "]", "is not convex with planar faces: the distance blend is built for such cells only",
                        "give boxes or planar hexahedra");
    out.push_back(*P);
  }
  return out;
}

Rational value(const HalfSpace<Rational>& H, const P3& x) { return H.n[0] * x[0] + H.n[1] * x[1] + H.n[2] * x[2] + H.d; }

/// The boundary faces of M (convex quadrilaterals, in order).
std::vector<std::vector<P3>> boundary_faces(const VModel<Rational>& M) {
  std::vector<std::vector<P3>> out;
  for (const auto& h : M.half_surfaces) {
    if (h.twin) continue;
    std::vector<P3> q;
    for (const auto& p : face_corners(M.trivariates[h.trivariate], h.dir, h.side)) q.push_back({p[0], p[1], p[2]});
    out.push_back(q);
  }
  return out;
}

/// The part of polygon P on the inner side of every half-space (Sutherland-Hodgman, exact).
std::vector<P3> clip(std::vector<P3> P, const std::vector<HalfSpace<Rational>>& planes) {
  for (const auto& H : planes) {
    std::vector<P3> out;
    const std::size_t n = P.size();
    for (std::size_t i = 0; i < n; ++i) {
      const P3 &a = P[i], &b = P[(i + 1) % n];
      const Rational va = value(H, a), vb = value(H, b);
      if (va >= 0) out.push_back(a);
      if ((va < 0 && vb > 0) || (va > 0 && vb < 0)) {
        const Rational t = va / (va - vb);
        out.push_back({a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])});
      }
    }
    P.clear();
    for (const auto& x : out)
      if (P.empty() || x != P.back()) P.push_back(x);
    while (P.size() > 1 && P.front() == P.back()) P.pop_back();
    if (P.empty()) break;
  }
  return P;
}

Rational segment_d2(const P3& p, const P3& a, const P3& b) {
  const P3 ab = sub(b, a), ap = sub(p, a);
  const Rational L = dot(ab, ab);
  Rational t = L == 0 ? Rational(0) : Rational(dot(ap, ab) / L);
  if (t < 0) t = 0;
  if (t > 1) t = 1;
  const P3 q{a[0] + t * ab[0] - p[0], a[1] + t * ab[1] - p[1], a[2] + t * ab[2] - p[2]};
  return dot(q, q);
}

/// Squared distance from p to a convex planar polygon (a segment or a point when degenerate).
Rational polygon_d2(const P3& p, const std::vector<P3>& P) {
  Rational best = dot(sub(p, P[0]), sub(p, P[0]));
  for (std::size_t i = 0; i < P.size(); ++i) {
    const Rational d = segment_d2(p, P[i], P[(i + 1) % P.size()]);
    if (d < best) best = d;
  }
  if (P.size() < 3) return best;
  P3 n{0, 0, 0};
  for (std::size_t i = 2; i < P.size() && n == P3{0, 0, 0}; ++i) n = cross(sub(P[1], P[0]), sub(P[i], P[0]));
  if (n == P3{0, 0, 0}) return best;
  const Rational h = dot(n, sub(p, P[0])), nn = dot(n, n);
  const P3 q{p[0] - h / nn * n[0], p[1] - h / nn * n[1], p[2] - h / nn * n[2]};
  bool pos = true, neg = true;
  for (std::size_t i = 0; i < P.size(); ++i) {
    const Rational s = dot(cross(sub(P[(i + 1) % P.size()], P[i]), sub(q, P[i])), n);
    pos = pos && s >= 0;
    neg = neg && s <= 0;
  }
  return pos || neg ? Rational(h * h / nn) : best;
}

bool inside(const std::vector<std::vector<HalfSpace<Rational>>>& cells, const P3& x) {
  for (const auto& planes : cells) {
    bool in = true;
    for (const auto& H : planes) in = in && value(H, x) >= 0;
    if (in) return true;
  }
  return false;
}

Rational d2_to(const std::vector<std::vector<P3>>& polys, const P3& p) {
  if (polys.empty()) throw DomainError("models", "have no boundary of one inside the other", "blend models that overlap");
  Rational best = polygon_d2(p, polys[0]);
  for (std::size_t i = 1; i < polys.size(); ++i) {
    const Rational d = polygon_d2(p, polys[i]);
    if (d < best) best = d;
  }
  return best;
}

P3 point(const std::vector<Rational>& p) {
  if (p.size() != 3) throw ValidationError("at", "needs three coordinates", "give x,y,z");
  return {p[0], p[1], p[2]};
}

/// An end of an MPFI interval (left or right) as the exact rational it is.
Rational end_of(mpfi_t x, bool right) {
  mpfr_t e;
  mpfr_init2(e, mpfi_get_prec(x));
  if (right) mpfi_get_right(e, x);
  else mpfi_get_left(e, x);
  mpq_t q;
  mpq_init(q);
  mpfr_get_q(q, e);
  Rational r(q);
  mpq_clear(q);
  mpfr_clear(e);
  return r;
}

}  // namespace

DistanceBlend::DistanceBlend(const VModel<Rational>& V1, const VModel<Rational>& V2)
    : cells1_(cell_planes(V1, "first")), cells2_(cell_planes(V2, "second")) {
  for (const auto& f : boundary_faces(V1))
    for (const auto& planes : cells2_) {
      auto P = clip(f, planes);
      if (!P.empty()) boundary1_.push_back(std::move(P));
    }
  for (const auto& f : boundary_faces(V2))
    for (const auto& planes : cells1_) {
      auto P = clip(f, planes);
      if (!P.empty()) boundary2_.push_back(std::move(P));
    }
}

bool DistanceBlend::in_first(const std::vector<Rational>& p) const { return inside(cells1_, point(p)); }
bool DistanceBlend::in_second(const std::vector<Rational>& p) const { return inside(cells2_, point(p)); }
Rational DistanceBlend::d1_squared(const std::vector<Rational>& p) const { return d2_to(boundary1_, point(p)); }
Rational DistanceBlend::d2_squared(const std::vector<Rational>& p) const { return d2_to(boundary2_, point(p)); }

std::vector<Rational> attribute_at(const VModel<Rational>& M, const std::vector<Rational>& x, const std::string& name, std::size_t* cell) {
  if (x.size() != 3) throw ValidationError("at", "needs three coordinates", "give x,y,z");
  const auto cells = cells_containing(M, x);
  if (cells.empty()) throw ValidationError("at", "lies in no cell of the model", "give a point of the model");
  for (std::size_t c : cells) {
    const auto& a = M.cells[c].attributes;
    if (cell) *cell = c;
    if (const auto it = a.constants.find(name); it != a.constants.end()) return it->second;
    const auto f = a.fields.find(name);
    if (f == a.fields.end()) continue;
    const auto& V = M.trivariates[M.cells[c].trivariates.front()];
    const auto inv = vrep_detail::affine_inverse(V);
    if (!inv)
      throw DomainError("attributes." + name, "is a field on cell " + std::to_string(c) + " (" + M.cells[c].name +
                                                  "), which is not affine: its parameters at a point are not rational in general",
                        "give the field on an affine cell (a box or parallelepiped) or a constant");
    const auto s = (*inv)(x.data());
    return evaluate(f->second, std::vector<Rational>(s.begin(), s.end()));
  }
  throw ValidationError("attributes." + name, "is on none of the cells that hold the point", "give an attribute the model's cells carry");
}

BlendValue DistanceBlend::at(const std::vector<Rational>& p, const std::vector<Rational>& A1, const std::vector<Rational>& A2, int k,
                             int bits) const {
  if (A1.size() != A2.size()) throw ValidationError("attributes", "have different lengths in the two models", "give attributes of one length");
  if (k < 1 || k > 64) throw ValidationError("k", "must be 1..64", "give the blend's order k between 1 and 64");
  if (bits < 16 || bits > 100000) throw ValidationError("bits", "must be 16..100000", "give the enclosure's precision in bits");
  const bool in1 = in_first(p), in2 = in_second(p);
  BlendValue out;
  auto exact = [&](const std::vector<Rational>& A) {
    for (const auto& a : A) out.value.push_back({a, a});
    return out;
  };
  if (!in1 && !in2) throw ValidationError("at", "lies in neither model", "give a point of the union");
  if (!in2) return exact(A1);
  if (!in1) return exact(A2);
  out.d1_squared = d1_squared(p);
  out.d2_squared = d2_squared(p);
  if (out.d1_squared == 0 && out.d2_squared == 0) {
    out.singular = true;
    return out;
  }
  if (out.d1_squared == 0) return exact(A2);
  if (out.d2_squared == 0) return exact(A1);
  mpfi_t d1, d2, w1, w2, s, num, t;
  for (auto* x : {&d1, &d2, &w1, &w2, &s, &num, &t}) mpfi_init2(*x, bits);
  mpfi_set_q(d1, out.d1_squared.backend().data());
  mpfi_set_q(d2, out.d2_squared.backend().data());
  mpfi_sqrt(d1, d1);
  mpfi_sqrt(d2, d2);
  mpfi_set(w1, d1);
  mpfi_set(w2, d2);
  for (int i = 1; i < k; ++i) {
    mpfi_mul(w1, w1, d1);
    mpfi_mul(w2, w2, d2);
  }
  mpfi_add(s, w1, w2);
  for (std::size_t c = 0; c < A1.size(); ++c) {
    mpfi_mul_q(num, w1, A1[c].backend().data());
    mpfi_mul_q(t, w2, A2[c].backend().data());
    mpfi_add(num, num, t);
    mpfi_div(t, num, s);
    out.value.push_back({end_of(t, false), end_of(t, true)});
  }
  for (auto* x : {&d1, &d2, &w1, &w2, &s, &num, &t}) mpfi_clear(*x);
  return out;
}

}  // namespace splinex

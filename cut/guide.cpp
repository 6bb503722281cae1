#include "cut/guide.hpp"

#include <algorithm>
#include <chrono>

#include "base/errors.hpp"
#include "float/rounding.hpp"
#include "spline/basis.hpp"
#include "spline/evaluate.hpp"
#include "spline/factories.hpp"
#include "spline/knots.hpp"

namespace splinex {

namespace {

constexpr int kDegree = 3;

template <class T>
T from_q(const Rational& x) { return ArithTraits<T>::from_rational(x); }

// The non-zero basis values and first derivatives at x: (first index, values, derivatives).
template <class T>
struct Local {
  std::size_t first = 0;
  std::vector<T> v, d;
};

template <class T>
Local<T> local_basis(const std::vector<T>& U, std::size_t n, const T& x) {
  const std::size_t s = find_span(U, kDegree, n, x);
  const auto ders = ders_basis_funs(s, x, kDegree, 1, U);
  return {s - kDegree, ders[0], ders[1]};
}

template <class T>
BasisRow<T> basis_row_impl(const std::vector<T>& Ux, std::size_t n, const std::vector<T>& Uy, std::size_t ny, const T& x, const T& y) {
  const auto bx = local_basis(Ux, n, x), by = local_basis(Uy, ny, y);
  BasisRow<T> r;
  for (int b = 0; b <= kDegree; ++b)
    for (int a = 0; a <= kDegree; ++a) {
      const std::size_t idx = (bx.first + a) + n * (by.first + b);
      r.v.emplace_back(idx, bx.v[a] * by.v[b]);
      r.dx.emplace_back(idx, bx.d[a] * by.v[b]);
      r.dy.emplace_back(idx, bx.v[a] * by.d[b]);
    }
  return r;
}

template <class T>
void add_outer(QuadraticProgram<T>& qp, const std::vector<std::pair<std::size_t, T>>& a, const T& w) {
  for (const auto& [i, vi] : a)
    for (const auto& [j, vj] : a) qp.d(i, j) += w * vi * vj;
}

// The univariate Gram matrices G^a_{IJ} = int N_I^(a) N_J^(a), a = 0, 1, 2, over the knots' domain:
// per span, each basis function's Taylor expansion at the span's left end (exact from its
// derivatives there) gives its power form in t in [0, 1], and products integrate term by term.
template <class T>
std::array<std::vector<T>, 3> gram_matrices(const std::vector<T>& U) {
  const std::size_t n = U.size() - kDegree - 1;
  std::array<std::vector<T>, 3> G;
  for (auto& g : G) g.assign(n * n, T(0));
  for (std::size_t s = kDegree; s < n; ++s) {
    if (!(U[s] < U[s + 1])) continue;
    const T h = U[s + 1] - U[s];
    const auto ders = ders_basis_funs(s, U[s], kDegree, kDegree, U);
    // power coefficients in t of N_j(U[s] + h t): ders[r][j] h^r / r!
    std::vector<std::vector<T>> pw(kDegree + 1, std::vector<T>(kDegree + 1));
    for (int j = 0; j <= kDegree; ++j) {
      T hr(1), fact(1);
      for (int r = 0; r <= kDegree; ++r) {
        if (r > 0) hr = hr * h, fact = fact * T(r);
        pw[j][r] = ders[r][j] * hr / fact;
      }
    }
    for (int a = 0; a <= 2; ++a) {
      // the a-th x-derivative: d^a/dt^a times h^-a
      T scale(1);
      for (int k = 0; k < a; ++k) scale = scale / h;
      std::vector<std::vector<T>> q(kDegree + 1, std::vector<T>(kDegree + 1 - a, T(0)));
      for (int j = 0; j <= kDegree; ++j)
        for (int r = a; r <= kDegree; ++r) {
          T c = pw[j][r];
          for (int k = 0; k < a; ++k) c = c * T(r - k);
          q[j][r - a] = c * scale;
        }
      for (int i = 0; i <= kDegree; ++i)
        for (int j = 0; j <= kDegree; ++j) {
          T sum(0);
          for (std::size_t m = 0; m < q[i].size(); ++m)
            for (std::size_t l = 0; l < q[j].size(); ++l) sum += q[i][m] * q[j][l] / T(static_cast<int>(m + l + 1));
          G[a][(s - kDegree + i) * n + (s - kDegree + j)] += sum * h;
        }
    }
  }
  return G;
}

std::array<Rational, 2> normal_at(const CutData2<Rational>& cut, int e) {
  const auto& t = cut.ends[e].tangent;
  return e == 0 ? std::array<Rational, 2>{t[1], -t[0]} : std::array<Rational, 2>{-t[1], t[0]};
}

struct Sample {
  std::size_t facet;
  Rational param;
  bool positive;
};

template <class T>
std::array<T, 2> point_of(const BSpline<T>& F, const T& s) {
  const auto p = evaluate(F, std::vector<T>{s});
  return {p[0], p[1]};
}

}  // namespace

std::vector<Rational> guide_knots(int inner_knots) {
  std::vector<Rational> inner;
  for (int i = 1; i <= inner_knots; ++i) inner.push_back(Rational(i, inner_knots + 1));
  return clamped_knots<Rational>(kDegree, Rational(0), Rational(1), inner);
}

template <class T>
std::vector<T> regularization_matrix(const std::vector<T>& Ux, const std::vector<T>& Uy) {
  const std::size_t n = Ux.size() - kDegree - 1, m = Uy.size() - kDegree - 1, N = n * m;
  const auto G = gram_matrices(Ux);
  const auto H = gram_matrices(Uy);
  std::vector<T> M(N * N, T(0));
  for (std::size_t j1 = 0; j1 < m; ++j1)
    for (std::size_t i1 = 0; i1 < n; ++i1)
      for (std::size_t j2 = 0; j2 < m; ++j2)
        for (std::size_t i2 = 0; i2 < n; ++i2) {
          const std::size_t I = i1 + n * j1, J = i2 + n * j2;
          const std::size_t x = i1 * n + i2, y = j1 * m + j2;
          // f_xx^2 + 2 f_xy^2 + f_yy^2
          M[I * N + J] = G[2][x] * H[0][y] + T(2) * G[1][x] * H[1][y] + G[0][x] * H[2][y];
        }
  return M;
}

template <class T>
std::vector<T> regularization_matrix(const std::vector<T>& U) {
  return regularization_matrix(U, U);
}

namespace {

// An exact input number within the exact QP's size limit (SizeLimitError naming the field).
void check_bits(const Rational& x, const std::string& field, std::size_t max_bits) {
  const std::size_t bits = bit_size(x);
  if (bits > max_bits)
    throw SizeLimitError(field, "has a number of " + std::to_string(bits) + " bits, over the exact QP's limit of " + std::to_string(max_bits),
                         "give the number with fewer digits, or use --arith double");
}

std::size_t program_size(int kx, int ky, std::size_t rows) {
  const std::size_t N = (static_cast<std::size_t>(kx) + kDegree + 1) * (static_cast<std::size_t>(ky) + kDegree + 1);
  return N * (N + rows);
}
int first_ky(const GuideOptions& o) { return o.inner_knots_y < 0 ? o.inner_knots : o.inner_knots_y; }
}  // namespace

void validate_guide_options(const GuideOptions& o, std::size_t facets) {
  if (o.inner_knots < 0 || o.inner_knots > 1000) throw ValidationError("inner-knots", "is " + std::to_string(o.inner_knots), "give 0 .. 1000 inner knots");
  if (o.max_inner_knots < o.inner_knots) throw ValidationError("max-inner-knots", "is below inner-knots", "give max-inner-knots >= inner-knots");
  if (o.samples < 1 || o.samples > 100000) throw ValidationError("samples", "is " + std::to_string(o.samples), "give 1 .. 100000 samples per facet");
  if (!(o.delta > 0)) throw ValidationError("delta", "is not positive", "give delta > 0 (the margin of f* on the samples)");
  if (!(o.lambda_int > 0) || !(o.lambda_tan > 0) || !(o.lambda_reg > 0))
    throw ValidationError("weights", "are not all positive", "give positive lambda_int, lambda_tan, lambda_reg (Lemma 1 needs them)");
  if (o.strip < 0) throw ValidationError("strip", "is negative", "give a strip width >= 0");
  const std::size_t rows = static_cast<std::size_t>(o.samples) * facets;
  if (o.inner_knots_y < -1 || o.inner_knots_y > 1000) throw ValidationError("inner-knots-y", "is " + std::to_string(o.inner_knots_y), "give 0 .. 1000 inner knots in y, or leave it out (the same as in x)");
  if (program_size(o.inner_knots, first_ky(o), rows) > o.max_size)
    throw SizeLimitError("inner-knots", "a program with " + std::to_string(o.inner_knots) + " inner knots and up to " + std::to_string(rows) +
                                            " sample rows is over the size limit (" + std::to_string(o.max_size) + " entries)",
                         "give fewer inner knots or samples");
}

void check_exact_sizes(const Solid2<Rational>& S, const CutData2<Rational>& C, const GuideOptions& o) {
  auto check = [&](const Rational& x, const std::string& field) { check_bits(x, field, o.max_bits); };
  for (std::size_t i = 0; i < S.facets.size(); ++i) {
    const std::string f = "facets[" + std::to_string(i) + "]";
    for (const auto& v : S.facets[i].points) check(v, f + ".points");
    for (const auto& v : S.facets[i].knots[0]) check(v, f + ".knots");
  }
  for (int e = 0; e < 2; ++e) {
    const std::string f = "points[" + std::to_string(e) + "]";
    check(C.ends[e].param, f + ".parameter");
    check(C.ends[e].tangent[0], f + ".tangent");
    check(C.ends[e].tangent[1], f + ".tangent");
  }
  check(o.delta, "delta");
  check(o.strip, "strip");
  check(o.lambda_int, "lambda-int");
  check(o.lambda_tan, "lambda-tan");
  check(o.lambda_reg, "lambda-reg");
}

template <class T>
GuideResult<T> guide_curve(const Solid2<Rational>& solid_in, const CutData2<Rational>& cut_in, const GuideOptions& o) {
  const auto t0 = std::chrono::steady_clock::now();
  validate_solid(solid_in);
  validate_guide_options(o, solid_in.facets.size());
  if constexpr (ArithTraits<T>::exact) check_exact_sizes(solid_in, cut_in, o);
  GuideResult<T> R;
  R.cut = validate_cut(solid_in, cut_in);
  R.frame = unit_frame(solid_in);
  R.solid = to_frame(solid_in, R.frame);
  const auto& S = R.solid;

  // The cut points and their normals (exact), and the samples (parameters and sides exact).
  std::array<std::array<Rational, 2>, 2> ends;
  for (int e = 0; e < 2; ++e) {
    const auto p = evaluate(S.facets[R.cut.ends[e].facet], std::vector<Rational>{R.cut.ends[e].param});
    ends[e] = {p[0], p[1]};
  }
  auto in_strip = [&](const std::array<Rational, 2>& x) {
    for (const auto& p : ends) {
      Rational dx = x[0] - p[0], dy = x[1] - p[1];
      if (dx < 0) dx = -dx;
      if (dy < 0) dy = -dy;
      if (dx <= o.strip && dy <= o.strip) return true;
    }
    return false;
  };
  std::vector<Sample> samples;
  for (std::size_t i = 0; i < S.facets.size(); ++i) {
    const auto& F = S.facets[i];
    const Rational lo = F.domain_lo(0), hi = F.domain_hi(0);
    for (int j = 0; j < o.samples; ++j) {
      const Rational s = lo + (hi - lo) * Rational(j, o.samples);
      const auto p = evaluate(F, std::vector<Rational>{s});
      const std::array<Rational, 2> x{p[0], p[1]};
      if (in_strip(x)) continue;
      bool is_end = false;
      for (const auto& c : R.cut.ends) is_end = is_end || (c.facet == i && c.param == s);
      if (is_end) continue;
      samples.push_back({i, s, on_arc(i, s, R.cut.ends[0], R.cut.ends[1])});
    }
  }
  std::vector<Sample> ordered;
  for (const auto& s : samples) if (s.positive) ordered.push_back(s);
  R.samples_positive = ordered.size();
  for (const auto& s : samples) if (!s.positive) ordered.push_back(s);
  R.samples_negative = ordered.size() - R.samples_positive;
  for (const auto& s : ordered) {
    const auto p = evaluate(S.facets[s.facet], std::vector<Rational>{s.param});
    R.sample_points.push_back({p[0], p[1]});
  }

  // The facets, points and data in T (rounded for double).
  std::vector<BSpline<T>> facets;
  for (const auto& F : S.facets) {
    if constexpr (ArithTraits<T>::exact) facets.push_back(F);
    else facets.push_back(round_spline<T>(F, "facet"));
  }
  const T delta = from_q<T>(o.delta), li = from_q<T>(o.lambda_int), lt = from_q<T>(o.lambda_tan), lr = from_q<T>(o.lambda_reg);

  for (int k = o.inner_knots, ky = first_ky(o);; k = 2 * k + 1, ky = 2 * ky + 1) {
    R.tried.push_back(k);
    const std::size_t n = static_cast<std::size_t>(k) + kDegree + 1, ny = static_cast<std::size_t>(ky) + kDegree + 1, N = n * ny;
    std::vector<T> U, Uy;
    for (const auto& u : guide_knots(k)) U.push_back(from_q<T>(u));
    for (const auto& u : guide_knots(ky)) Uy.push_back(from_q<T>(u));
    QuadraticProgram<T> qp;
    qp.n = N;
    qp.D = regularization_matrix(U, Uy);
    for (auto& v : qp.D) v = v * lr;
    qp.c.assign(N, T(0));
    qp.c0 = T(0);
    for (int e = 0; e < 2; ++e) {
      const auto& c = R.cut.ends[e];
      const auto x = point_of(facets[c.facet], from_q<T>(c.param));
      const auto row = basis_row_impl(U, n, Uy, ny, x[0], x[1]);
      const auto nr = normal_at(R.cut, e);
      const T nx = from_q<T>(nr[0]), ny = from_q<T>(nr[1]);
      add_outer(qp, row.v, li);
      add_outer(qp, row.dx, lt);
      add_outer(qp, row.dy, lt);
      for (const auto& [i, v] : row.dx) qp.c[i] += T(-2) * lt * nx * v;
      for (const auto& [i, v] : row.dy) qp.c[i] += T(-2) * lt * ny * v;
      qp.c0 += lt * (nx * nx + ny * ny);
    }
    // Rounded sums need not be symmetric bit for bit; the solver reads the lower triangle, and so
    // does the program kept for the check.
    for (std::size_t i = 0; i < N; ++i)
      for (std::size_t j = i + 1; j < N; ++j) qp.d(i, j) = qp.d(j, i);
    for (const auto& s : ordered) {
      const auto x = point_of(facets[s.facet], from_q<T>(s.param));
      const auto row = basis_row_impl(U, n, Uy, ny, x[0], x[1]);
      typename QuadraticProgram<T>::Row r;
      r.a = row.v;
      r.at_least = s.positive;
      r.b = s.positive ? delta : T(-delta);
      qp.rows.push_back(std::move(r));
    }
    R.solution = solve_qp(qp);
    if constexpr (ArithTraits<T>::exact) R.program = qp;
    else R.program = exact_program(qp);
    R.status = R.solution.status;
    R.inner_knots = k;
    R.inner_knots_y = ky;
    if (R.status == QPStatus::optimal || 2 * k + 1 > o.max_inner_knots) break;
    if (program_size(2 * k + 1, 2 * ky + 1, ordered.size()) > o.max_size) {
      R.refinement_stopped_by_limit = true;
      break;
    }
  }
  R.kkt = check_kkt(R.program, R.solution);
  R.positive_definite = positive_definite(R.program);
  if (R.status == QPStatus::optimal) {
    const auto U = guide_knots(R.inner_knots), Uy = guide_knots(R.inner_knots_y);
    R.coefficients = R.solution.x;
    std::vector<T> pts;
    for (const auto& c : R.coefficients) pts.push_back(from_q<T>(c));
    std::vector<T> UT, UyT;
    for (const auto& u : U) UT.push_back(from_q<T>(u));
    for (const auto& u : Uy) UyT.push_back(from_q<T>(u));
    R.f = make_spline<T>({kDegree, kDegree}, {UT, UyT}, 1, pts);
    // The interpolation errors at L*, exactly (for double: of the spline the doubles hold).
    if constexpr (ArithTraits<T>::exact) R.f_exact = R.f;
    else R.f_exact = convert<Rational>(R.f, [](const T& v) { return ArithTraits<T>::to_rational(v); });
    const auto& fq = R.f_exact;
    for (int e = 0; e < 2; ++e) {
      const auto x = evaluate(S.facets[R.cut.ends[e].facet], std::vector<Rational>{R.cut.ends[e].param});
      R.value_at_ends[e] = evaluate(fq, x)[0];
      const Rational gx = derivative(fq, x, {1, 0})[0], gy = derivative(fq, x, {0, 1})[0];
      const auto nr = normal_at(R.cut, e);
      R.gradient_error2[e] = (gx - nr[0]) * (gx - nr[0]) + (gy - nr[1]) * (gy - nr[1]);
    }
  }
  R.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return R;
}

template GuideResult<Rational> guide_curve(const Solid2<Rational>&, const CutData2<Rational>&, const GuideOptions&);
template GuideResult<double> guide_curve(const Solid2<Rational>&, const CutData2<Rational>&, const GuideOptions&);
CoefficientError coefficient_error(const std::vector<Rational>& exact, const std::vector<Rational>& rounded) {
  if (exact.size() != rounded.size()) throw std::logic_error("coefficient_error: sizes differ");
  CoefficientError e;
  for (std::size_t i = 0; i < exact.size(); ++i) {
    const Rational d = abs(rounded[i] - exact[i]), m = abs(exact[i]);
    if (e.max_abs_error < d) e.max_abs_error = d;
    if (e.max_abs < m) e.max_abs = m;
  }
  if (e.max_abs_error > 0 && e.max_abs > 0) e.bits_lost = std::max(0.0, 53 + log2_abs(e.max_abs_error) - log2_abs(e.max_abs));
  return e;
}

template <class T>
BasisRow<T> basis_row(const std::vector<T>& Ux, std::size_t n, const std::vector<T>& Uy, std::size_t ny, const T& x, const T& y) {
  return basis_row_impl(Ux, n, Uy, ny, x, y);
}
template BasisRow<Rational> basis_row(const std::vector<Rational>&, std::size_t, const std::vector<Rational>&, std::size_t, const Rational&,
                                      const Rational&);
template BasisRow<double> basis_row(const std::vector<double>&, std::size_t, const std::vector<double>&, std::size_t, const double&,
                                    const double&);

template std::vector<Rational> regularization_matrix(const std::vector<Rational>&);
template std::vector<double> regularization_matrix(const std::vector<double>&);
template std::vector<Rational> regularization_matrix(const std::vector<Rational>&, const std::vector<Rational>&);
template std::vector<double> regularization_matrix(const std::vector<double>&, const std::vector<double>&);


// ---- d = 3 ---------------------------------------------------------------------------------------

template <class T>
std::vector<T> regularization_matrix3(const std::array<std::vector<T>, 3>& U) {
  std::array<std::size_t, 3> n;
  std::array<std::array<std::vector<T>, 3>, 3> G;
  for (int a = 0; a < 3; ++a) n[a] = U[a].size() - kDegree - 1, G[a] = gram_matrices(U[a]);
  const std::size_t N = n[0] * n[1] * n[2];
  std::vector<T> M(N * N, T(0));
  for (std::size_t I = 0; I < N; ++I) {
    const std::size_t i1 = I % n[0], j1 = (I / n[0]) % n[1], k1 = I / (n[0] * n[1]);
    for (std::size_t J = 0; J < N; ++J) {
      const std::size_t i2 = J % n[0], j2 = (J / n[0]) % n[1], k2 = J / (n[0] * n[1]);
      const std::size_t x = i1 * n[0] + i2, y = j1 * n[1] + j2, z = k1 * n[2] + k2;
      const auto &X = G[0], &Y = G[1], &Z = G[2];
      if (X[0][x] == T(0) && X[1][x] == T(0) && X[2][x] == T(0)) continue;  // disjoint supports
      // f_xx^2 + f_yy^2 + f_zz^2 + 2 (f_xy^2 + f_xz^2 + f_yz^2)
      M[I * N + J] = X[2][x] * Y[0][y] * Z[0][z] + X[0][x] * Y[2][y] * Z[0][z] + X[0][x] * Y[0][y] * Z[2][z] +
                     T(2) * (X[1][x] * Y[1][y] * Z[0][z] + X[1][x] * Y[0][y] * Z[1][z] + X[0][x] * Y[1][y] * Z[1][z]);
    }
  }
  return M;
}

namespace {

template <class T>
struct BasisRow3 {
  std::vector<std::pair<std::size_t, T>> v, d[3];
};

template <class T>
BasisRow3<T> basis_row3(const std::array<std::vector<T>, 3>& U, const std::array<std::size_t, 3>& n, const std::array<T, 3>& x) {
  const auto bx = local_basis(U[0], n[0], x[0]), by = local_basis(U[1], n[1], x[1]), bz = local_basis(U[2], n[2], x[2]);
  BasisRow3<T> r;
  for (int c = 0; c <= kDegree; ++c)
    for (int b = 0; b <= kDegree; ++b)
      for (int a = 0; a <= kDegree; ++a) {
        const std::size_t idx = (bx.first + a) + n[0] * ((by.first + b) + n[1] * (bz.first + c));
        r.v.emplace_back(idx, bx.v[a] * by.v[b] * bz.v[c]);
        r.d[0].emplace_back(idx, bx.d[a] * by.v[b] * bz.v[c]);
        r.d[1].emplace_back(idx, bx.v[a] * by.d[b] * bz.v[c]);
        r.d[2].emplace_back(idx, bx.v[a] * by.v[b] * bz.d[c]);
      }
  return r;
}

std::size_t program_size3(const std::array<int, 3>& k, std::size_t rows) {
  std::size_t N = 1;
  for (int a = 0; a < 3; ++a) N *= static_cast<std::size_t>(k[a]) + kDegree + 1;
  return N * (N + rows);
}

std::array<int, 3> first_knots3(const GuideOptions3& o) {
  std::array<int, 3> k;
  for (int a = 0; a < 3; ++a) k[a] = o.inner_knots[a] < 0 ? o.base.inner_knots : o.inner_knots[a];
  return k;
}

void validate_guide_options3(const GuideOptions3& o, std::size_t facets) {
  const auto& b = o.base;
  if (b.inner_knots < 0 || b.inner_knots > 100) throw ValidationError("inner-knots", "is " + std::to_string(b.inner_knots), "give 0 .. 100 inner knots");
  for (int a = 0; a < 3; ++a) {
    const std::string f = std::string("inner-knots-") + "xyz"[a];
    if (o.inner_knots[a] < -1 || o.inner_knots[a] > 100) throw ValidationError(f, "is " + std::to_string(o.inner_knots[a]), "give 0 .. 100 inner knots, or -1 for --inner-knots");
  }
  const auto k0 = first_knots3(o);
  if (b.max_inner_knots < *std::max_element(k0.begin(), k0.end()))
    throw ValidationError("max-inner-knots", "is below the inner knots", "give max-inner-knots >= every direction's inner knots");
  if (b.samples < 1 || b.samples > 1000) throw ValidationError("samples", "is " + std::to_string(b.samples), "give 1 .. 1000 samples per facet direction");
  if (o.loop_samples < 1 || o.loop_samples > 1000) throw ValidationError("loop-samples", "is " + std::to_string(o.loop_samples), "give 1 .. 1000 points per loop side");
  if (!(b.delta > 0)) throw ValidationError("delta", "is not positive", "give delta > 0 (the margin of f* on the samples)");
  if (!(b.lambda_int > 0) || !(b.lambda_tan > 0) || !(b.lambda_reg > 0))
    throw ValidationError("weights", "are not all positive", "give positive lambda_int, lambda_tan, lambda_reg (Lemma 1 needs them)");
  if (b.strip < 0) throw ValidationError("strip", "is negative", "give a strip width >= 0");
  const std::size_t rows = static_cast<std::size_t>(b.samples) * static_cast<std::size_t>(b.samples) * facets;
  if (program_size3(k0, rows) > b.max_size)
    throw SizeLimitError("inner-knots", "a program with " + std::to_string(k0[0]) + " x " + std::to_string(k0[1]) + " x " + std::to_string(k0[2]) + " inner knots and up to " + std::to_string(rows) +
                                            " sample rows is over the size limit (" + std::to_string(b.max_size) + " entries)",
                         "give fewer inner knots or samples");
}

void check_exact_sizes3(const Solid3<Rational>& S, const CutData3& C, const GuideOptions& o) {
  auto check = [&](const Rational& x, const std::string& field) { check_bits(x, field, o.max_bits); };
  for (std::size_t i = 0; i < S.facets.size(); ++i) {
    const std::string f = "facets[" + std::to_string(i) + "]";
    for (const auto& v : S.facets[i].points) check(v, f + ".points");
    for (const auto& U : S.facets[i].knots)
      for (const auto& v : U) check(v, f + ".knots");
  }
  for (std::size_t k = 0; k < C.tangents.size(); ++k)
    for (const auto& v : C.tangents[k].tangent) check(v, "tangents[" + std::to_string(k) + "].tangent");
  check(o.delta, "delta");
  check(o.strip, "strip");
  check(o.lambda_int, "lambda-int");
  check(o.lambda_tan, "lambda-tan");
  check(o.lambda_reg, "lambda-reg");
}

struct Sample3 {
  std::size_t facet;
  std::array<Rational, 2> param;
  std::array<Rational, 3> point;
};

}  // namespace

void validate_guide_options(const GuideOptions3& options, std::size_t facets) { validate_guide_options3(options, facets); }
void check_exact_sizes(const Solid3<Rational>& solid, const CutData3& cut, const GuideOptions& options) { check_exact_sizes3(solid, cut, options); }

template <class T>
GuideResult3<T> guide_surface(const Solid3<Rational>& solid_in, const CutData3& cut, const GuideOptions3& o3) {
  const auto t0 = std::chrono::steady_clock::now();
  const auto& o = o3.base;
  validate_guide_options3(o3, solid_in.facets.size());
  if constexpr (ArithTraits<T>::exact) check_exact_sizes3(solid_in, cut, o);
  GuideResult3<T> R;
  R.frame = unit_frame(solid_in);
  R.solid = to_frame(solid_in, R.frame);
  R.loop = validate_cut(R.solid, cut);  // the tangents' directions do not change under the scaling
  const auto& S = R.solid;

  // L*: loop_samples points per side, exact.
  std::vector<std::pair<std::array<Rational, 3>, std::array<Rational, 3>>> targets;  // point, normal
  for (const auto& L : R.loop)
    for (int j = 0; j < o3.loop_samples; ++j) {
      const Rational lam(j, o3.loop_samples);
      std::array<Rational, 3> x;
      for (int c = 0; c < 3; ++c) x[c] = L.start[c] + lam * (L.end[c] - L.start[c]);
      targets.push_back({x, L.normal});
      R.loop_points.push_back(x);
    }
  auto in_strip = [&](const std::array<Rational, 3>& x) {
    for (const auto& L : R.loop)
      if (within_segment(x, L.start, L.end, o.strip)) return true;
    return false;
  };
  std::vector<char> in_b(S.facets.size(), 0);
  for (auto i : cut.positive) in_b[i] = 1;
  std::vector<Sample3> pos, neg;
  for (std::size_t i = 0; i < S.facets.size(); ++i) {
    const auto& F = S.facets[i];
    for (int a = 0; a < o.samples; ++a)
      for (int b = 0; b < o.samples; ++b) {
        const Rational u = F.domain_lo(0) + (F.domain_hi(0) - F.domain_lo(0)) * Rational(2 * a + 1, 2 * o.samples);
        const Rational v = F.domain_lo(1) + (F.domain_hi(1) - F.domain_lo(1)) * Rational(2 * b + 1, 2 * o.samples);
        const auto p = evaluate(F, std::vector<Rational>{u, v});
        const std::array<Rational, 3> x{p[0], p[1], p[2]};
        if (in_strip(x)) continue;
        (in_b[i] ? pos : neg).push_back({i, {u, v}, x});
      }
  }
  R.samples_positive = pos.size();
  R.samples_negative = neg.size();
  std::vector<Sample3> ordered = pos;
  ordered.insert(ordered.end(), neg.begin(), neg.end());
  for (const auto& s : ordered) R.sample_points.push_back(s.point);

  // The data in T: exact, or the exact points and normals rounded (the facets' exact points are
  // the data; rounding them once is what a double pipeline reading these facets would hold).
  auto to_T = [](const std::array<Rational, 3>& x) { return std::array<T, 3>{from_q<T>(x[0]), from_q<T>(x[1]), from_q<T>(x[2])}; };
  const T delta = from_q<T>(o.delta), li = from_q<T>(o.lambda_int), lt = from_q<T>(o.lambda_tan), lr = from_q<T>(o.lambda_reg);

  for (auto k = first_knots3(o3);; ) {
    R.tried.push_back(k);
    std::array<std::size_t, 3> n;
    std::array<std::vector<T>, 3> U;
    std::size_t N = 1;
    for (int a = 0; a < 3; ++a) {
      n[a] = static_cast<std::size_t>(k[a]) + kDegree + 1;
      N *= n[a];
      for (const auto& u : guide_knots(k[a])) U[a].push_back(from_q<T>(u));
    }
    QuadraticProgram<T> qp;
    qp.n = N;
    qp.D = regularization_matrix3(U);
    for (auto& v : qp.D) v = v * lr;
    qp.c.assign(N, T(0));
    qp.c0 = T(0);
    for (const auto& [xq, nq] : targets) {
      const auto row = basis_row3(U, n, to_T(xq));
      const auto nr = to_T(nq);
      add_outer(qp, row.v, li);
      for (int c = 0; c < 3; ++c) {
        add_outer(qp, row.d[c], lt);
        for (const auto& [i, v] : row.d[c]) qp.c[i] += T(-2) * lt * nr[c] * v;
        qp.c0 += lt * nr[c] * nr[c];
      }
    }
    for (std::size_t i = 0; i < N; ++i)
      for (std::size_t j = i + 1; j < N; ++j) qp.d(i, j) = qp.d(j, i);
    for (std::size_t m = 0; m < ordered.size(); ++m) {
      const bool positive = m < pos.size();
      const auto row = basis_row3(U, n, to_T(ordered[m].point));
      typename QuadraticProgram<T>::Row r;
      r.a = row.v;
      r.at_least = positive;
      r.b = positive ? delta : T(-delta);
      qp.rows.push_back(std::move(r));
    }
    R.solution = solve_qp(qp);
    if constexpr (ArithTraits<T>::exact) R.program = qp;
    else R.program = exact_program(qp);
    R.status = R.solution.status;
    R.inner_knots = k;
    std::array<int, 3> next;
    for (int a = 0; a < 3; ++a) next[a] = 2 * k[a] + 1;
    if (R.status == QPStatus::optimal || *std::max_element(next.begin(), next.end()) > o.max_inner_knots) break;
    if (program_size3(next, ordered.size()) > o.max_size) {
      R.refinement_stopped_by_limit = true;
      break;
    }
    k = next;
  }
  R.kkt = check_kkt(R.program, R.solution);
  R.positive_definite = positive_definite(R.program);
  if (R.status == QPStatus::optimal) {
    R.coefficients = R.solution.x;
    std::vector<T> pts;
    for (const auto& c : R.coefficients) pts.push_back(from_q<T>(c));
    std::vector<std::vector<T>> UT(3);
    for (int a = 0; a < 3; ++a)
      for (const auto& u : guide_knots(R.inner_knots[a])) UT[a].push_back(from_q<T>(u));
    R.f = make_spline<T>({kDegree, kDegree, kDegree}, UT, 1, pts);
    if constexpr (ArithTraits<T>::exact) R.f_exact = R.f;
    else R.f_exact = convert<Rational>(R.f, [](const T& v) { return ArithTraits<T>::to_rational(v); });
    for (const auto& [x, nr] : targets) {
      const std::vector<Rational> xv{x[0], x[1], x[2]};
      const Rational v = evaluate(R.f_exact, xv)[0];
      if (R.max_abs_value_on_loop < abs(v)) R.max_abs_value_on_loop = abs(v);
      Rational e2(0);
      for (int c = 0; c < 3; ++c) {
        std::vector<int> order{0, 0, 0};
        order[c] = 1;
        const Rational g = derivative(R.f_exact, xv, order)[0] - nr[c];
        e2 += g * g;
      }
      if (R.max_gradient_error2 < e2) R.max_gradient_error2 = e2;
    }
  }
  R.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return R;
}

template GuideResult3<Rational> guide_surface(const Solid3<Rational>&, const CutData3&, const GuideOptions3&);
template GuideResult3<double> guide_surface(const Solid3<Rational>&, const CutData3&, const GuideOptions3&);
template std::vector<Rational> regularization_matrix3(const std::array<std::vector<Rational>, 3>&);
template std::vector<double> regularization_matrix3(const std::array<std::vector<double>, 3>&);

}  // namespace splinex

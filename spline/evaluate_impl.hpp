#pragma once
#include <algorithm>
#include <functional>
#include <string>

#include "spline/basis.hpp"
#include "spline/basis_sum.hpp"
#include "spline/bernstein.hpp"
#include "spline/evaluate.hpp"

namespace splinex {
namespace detail {

/// The dim() parameters at x inside the domain; `field` names the point in errors ("at[d]").
template <class T>
void check_in_domain(const BSpline<T>& S, const T* x, const std::string& field) {
  for (int d = 0; d < S.dim(); ++d)
    if (x[d] < S.domain_lo(d) || S.domain_hi(d) < x[d])
      throw DomainError(field + "[" + std::to_string(d) + "]", "lies outside the domain of direction " + std::to_string(d),
                        "give a parameter in [U[p], U[n]] of that direction");
}

template <class T>
void check_point(const BSpline<T>& S, const std::vector<T>& x) {
  if (x.size() != static_cast<std::size_t>(S.dim()))
    throw DomainError("at", "has " + std::to_string(x.size()) + " coordinates for a spline of dimension " +
                                std::to_string(S.dim()),
                      "give one parameter per direction");
  check_in_domain(S, x.data(), "at");
}

/// Scratch storage of evaluation: basis values, A2.2's left/right, index vectors and scalar
/// temporaries. Reused across calls on one thread where the arithmetic allows it
/// (reusable_scratch<T>), so evaluating a point allocates only its result.
template <class T>
struct EvalScratch {
  std::vector<T> N, left, right;
  T den, temp, w, prod;
  std::vector<std::size_t> span, stride;
  std::vector<int> i;
  std::vector<const T*> B;
  std::vector<T> h;  // a homogeneous value (rational batches)
};

/// Calls f(scratch) with this thread's scratch, or with a fresh one for arithmetics whose values
/// carry state that must not outlive a call (MPFR's precision).
template <class T, class F>
decltype(auto) with_eval_scratch(F&& f) {
  if constexpr (reusable_scratch<T>) {
    thread_local EvalScratch<T> ws;
    return f(ws);
  } else {
    EvalScratch<T> ws;
    return f(ws);
  }
}

/// Sum over the (p_d+1) tensor of basis values: out[c] = sum_i prod_d B[d][i_d] * H_i[c], with
/// H_i the homogeneous control point (w_i P_i, w_i) or P_i. Only the active points are touched;
/// products go through the scratch scalars, so an exact scalar makes no temporaries.
template <class T>
void tensor_sum(const BSpline<T>& S, const std::size_t* span, const T* const* B, T* out, EvalScratch<T>& ws) {
  const int k = S.dim();
  const bool rational = S.is_rational();
  const std::size_t q = S.q, qq = q + (rational ? 1 : 0);
  if (k == 1) {  // a curve: one run of p+1 consecutive control points, no index bookkeeping
    const int p = S.degrees[0];
    const std::size_t first = span[0] - static_cast<std::size_t>(p);
    for (std::size_t c = 0; c < qq; ++c) out[c] = zero_value<T>();
    for (int i = 0; i <= p; ++i) {
      T& w = ws.w;
      w = B[0][i];
      if (rational) {
        w *= S.weights[first + i];
        out[q] += w;
      }
      const T* P = S.points.data() + (first + i) * q;
      for (std::size_t c = 0; c < q; ++c) {
        ws.prod = w;
        ws.prod *= P[c];
        out[c] += ws.prod;
      }
    }
    return;
  }
  ws.stride.resize(k);
  std::size_t st = 1;
  for (int d = 0; d < k; ++d) { ws.stride[d] = st; st *= S.count(d); }
  ws.i.assign(k, 0);
  for (std::size_t c = 0; c < qq; ++c) out[c] = zero_value<T>();
  T& w = ws.w;
  while (true) {
    w = one_value<T>();
    std::size_t idx = 0;
    for (int d = 0; d < k; ++d) {
      w *= B[d][ws.i[d]];
      idx += (span[d] - S.degrees[d] + ws.i[d]) * ws.stride[d];
    }
    if (rational) {
      w *= S.weights[idx];
      out[q] += w;
    }
    const T* P = S.points.data() + idx * q;
    for (std::size_t c = 0; c < q; ++c) {
      ws.prod = w;
      ws.prod *= P[c];
      out[c] += ws.prod;
    }
    int d = 0;
    while (d < k && ++ws.i[d] > S.degrees[d]) { ws.i[d] = 0; ++d; }
    if (d == k) break;
  }
}

template <class T>
void tensor_sum(const BSpline<T>& S, const std::vector<std::size_t>& span, const std::vector<const std::vector<T>*>& B,
                std::vector<T>& out) {
  with_eval_scratch<T>([&](EvalScratch<T>& ws) {
    std::vector<const T*> ptr(B.size());
    for (std::size_t d = 0; d < B.size(); ++d) ptr[d] = B[d]->data();
    out.resize(S.q + (S.is_rational() ? 1 : 0));
    tensor_sum(S, span.data(), ptr.data(), out.data(), ws);
  });
}

/// Sizes the scratch for S (once per call or batch, not per point).
template <class T>
void size_scratch(const BSpline<T>& S, EvalScratch<T>& ws) {
  const int k = S.dim();
  std::size_t total = 0;
  int pmax = 0;
  for (int d = 0; d < k; ++d) {
    total += static_cast<std::size_t>(S.degrees[d]) + 1;
    pmax = std::max(pmax, S.degrees[d]);
  }
  if (ws.N.size() < total) ws.N.resize(total);
  if (ws.left.size() < static_cast<std::size_t>(pmax) + 1) {
    ws.left.resize(pmax + 1);
    ws.right.resize(pmax + 1);
  }
  ws.span.resize(k);
  ws.B.resize(k);
}

/// The homogeneous value at x (dim() parameters) into out (q or q+1 values), with a scratch that
/// size_scratch(S, ws) has sized.
template <class T>
void evaluate_homogeneous_into(const BSpline<T>& S, const T* x, T* out, EvalScratch<T>& ws) {
  const int k = S.dim();
  std::size_t off = 0;
  for (int d = 0; d < k; ++d) {
    ws.span[d] = find_span(S.knots[d], S.degrees[d], S.count(d), x[d]);
    T* N = ws.N.data() + off;
    basis_funs_into(ws.span[d], x[d], S.degrees[d], S.knots[d], N, ws.left.data(), ws.right.data(), ws.den, ws.temp);
    ws.B[d] = N;
    off += static_cast<std::size_t>(S.degrees[d]) + 1;
  }
  tensor_sum(S, ws.span.data(), ws.B.data(), out, ws);
}

}  // namespace detail

template <class T>
std::vector<T> basis_sum(const BSpline<T>& S, const std::vector<std::size_t>& span, const std::vector<const std::vector<T>*>& B) {
  std::vector<T> out;
  detail::tensor_sum(S, span, B, out);
  return out;
}

template <class T>
std::vector<T> evaluate_homogeneous(const BSpline<T>& S, const std::vector<T>& x) {
  detail::check_point(S, x);
  std::vector<T> out(S.q + (S.is_rational() ? 1 : 0));
  detail::with_eval_scratch<T>([&](detail::EvalScratch<T>& ws) {
    detail::size_scratch(S, ws);
    detail::evaluate_homogeneous_into(S, x.data(), out.data(), ws);
  });
  return out;
}

template <class T>
std::vector<T> evaluate_points(const BSpline<T>& S, const std::vector<T>& params) {
  const std::size_t k = S.dim(), q = S.q;
  if (params.size() % k != 0)
    throw DomainError("params", "has " + std::to_string(params.size()) + " numbers, not a multiple of the dimension " +
                                    std::to_string(k),
                      "give dim() parameters per point");
  const std::size_t N = params.size() / k;
  for (std::size_t i = 0; i < N; ++i) detail::check_in_domain(S, params.data() + i * k, "params[" + std::to_string(i) + "]");
  std::vector<T> out(N * q);
  detail::with_eval_scratch<T>([&](detail::EvalScratch<T>& ws) {
    detail::size_scratch(S, ws);
    if (!S.is_rational()) {
      for (std::size_t i = 0; i < N; ++i) detail::evaluate_homogeneous_into(S, params.data() + i * k, out.data() + i * q, ws);
      return;
    }
    ws.h.resize(q + 1);
    for (std::size_t i = 0; i < N; ++i) {
      detail::evaluate_homogeneous_into(S, params.data() + i * k, ws.h.data(), ws);
      for (std::size_t c = 0; c < q; ++c) {
        out[i * q + c] = ws.h[c];
        out[i * q + c] /= ws.h[q];
      }
    }
  });
  return out;
}

template <class T>
std::vector<T> evaluate(const BSpline<T>& S, const std::vector<T>& x) {
  std::vector<T> h = evaluate_homogeneous(S, x);
  if (!S.is_rational()) return h;
  std::vector<T> r(S.q);
  for (int c = 0; c < S.q; ++c) r[c] = h[c] / h[S.q];
  return r;
}

template <class T>
std::vector<T> evaluate_de_boor(const BSpline<T>& S, const std::vector<T>& x) {
  detail::check_point(S, x);
  const int k = S.dim();
  const bool rational = S.is_rational();
  const std::size_t q = S.q, qq = q + (rational ? 1 : 0);
  std::vector<std::size_t> span(k), stride(k);
  std::size_t st = 1, active = 1;
  for (int d = 0; d < k; ++d) {
    span[d] = find_span(S.knots[d], S.degrees[d], S.count(d), x[d]);
    stride[d] = st;
    st *= S.count(d);
    active *= S.degrees[d] + 1;
  }
  /// Gather the active homogeneous net, direction 0 fastest.
  std::vector<T> net;
  net.reserve(active * qq);
  std::vector<int> i(k, 0);
  while (true) {
    std::size_t idx = 0;
    for (int d = 0; d < k; ++d) idx += (span[d] - S.degrees[d] + i[d]) * stride[d];
    for (std::size_t c = 0; c < q; ++c) net.push_back(rational ? S.points[idx * q + c] * S.weights[idx] : S.points[idx * q + c]);
    if (rational) net.push_back(S.weights[idx]);
    int d = 0;
    while (d < k && ++i[d] > S.degrees[d]) { i[d] = 0; ++d; }
    if (d == k) break;
  }
  /// Reduce direction 0 (fastest) first: each run of p_0+1 consecutive points collapses to one,
  /// which leaves direction 1 fastest, and so on.
  const std::size_t width = qq;
  for (int d = 0; d < k; ++d) {
    const int p = S.degrees[d];
    const auto& U = S.knots[d];
    const std::size_t s = span[d], runs = net.size() / ((p + 1) * width);
    std::vector<T> next;
    next.reserve(runs * width);
    for (std::size_t r = 0; r < runs; ++r) {
      std::vector<T> tri(net.begin() + r * (p + 1) * width, net.begin() + (r + 1) * (p + 1) * width);
      for (int lev = 1; lev <= p; ++lev)
        for (int j = p; j >= lev; --j) {
          const std::size_t idx = s - p + j;
          const T alpha = (x[d] - U[idx]) / (U[idx + p - lev + 1] - U[idx]);
          for (std::size_t c = 0; c < width; ++c)
            tri[j * width + c] = tri[(j - 1) * width + c] + alpha * (tri[j * width + c] - tri[(j - 1) * width + c]);
        }
      next.insert(next.end(), tri.begin() + p * width, tri.begin() + (p + 1) * width);
    }
    net = std::move(next);
  }
  if (!rational) return net;
  std::vector<T> out(q);
  for (std::size_t c = 0; c < q; ++c) out[c] = net[c] / net[q];
  return out;
}

template <class T>
std::vector<T> derivative(const BSpline<T>& S, const std::vector<T>& x, const std::vector<int>& orders) {
  detail::check_point(S, x);
  const int k = S.dim();
  if (orders.size() != static_cast<std::size_t>(k))
    throw UsageError("orders", "needs one derivative order per direction", "give " + std::to_string(k) + " orders");
  for (int o : orders)
    if (o < 0) throw UsageError("orders", "a derivative order is negative", "use orders >= 0");
  // A polynomial piece of degree p has no derivative of order > p in that direction.
  if (!S.is_rational())
    for (int d = 0; d < k; ++d)
      if (orders[d] > S.degrees[d]) return std::vector<T>(S.q, T(0));
  /// The quotient rule needs every lower mixed partial: prod (k_d + 1) of them.
  std::size_t needed = 1;
  for (int o : orders) {
    needed *= static_cast<std::size_t>(o) + 1;
    if (needed > 1'000'000)
      throw SizeLimitError("derivative", "the derivative orders need more than 10^6 mixed partials",
                           "ask for lower orders");
  }
  std::vector<std::size_t> span(k);
  std::vector<std::vector<std::vector<T>>> D(k);
  for (int d = 0; d < k; ++d) {
    span[d] = find_span(S.knots[d], S.degrees[d], S.count(d), x[d]);
    D[d] = ders_basis_funs(span[d], x[d], S.degrees[d], std::min(orders[d], S.degrees[d]), S.knots[d]);
  }
  const std::size_t qq = S.q + (S.is_rational() ? 1 : 0);
  /// Homogeneous partials A^(beta) for every multi-index beta <= orders (beta_d past the degree: 0).
  std::vector<std::size_t> bstride(k);
  std::size_t nb = 1;
  for (int d = 0; d < k; ++d) { bstride[d] = nb; nb *= orders[d] + 1; }
  std::vector<std::vector<T>> A(nb);
  for (std::size_t b = 0; b < nb; ++b) {
    std::vector<const std::vector<T>*> B(k);
    bool zero = false;
    for (int d = 0; d < k; ++d) {
      int bd = static_cast<int>((b / bstride[d]) % (orders[d] + 1));
      if (bd > S.degrees[d]) { zero = true; break; }
      B[d] = &D[d][bd];
    }
    if (zero) A[b].assign(qq, T(0));
    else detail::tensor_sum(S, span, B, A[b]);
  }
  const std::size_t top = nb - 1;
  if (!S.is_rational()) return A[top];
  /// Quotient rule: C^(a) = (A^(a) - sum_{0 != b <= a} binom(a,b) w^(b) C^(a-b)) / w, in order of
  /// increasing multi-index so that every C^(a-b) is known.
  const int q = S.q;
  std::vector<std::vector<T>> C(nb, std::vector<T>(q));
  for (std::size_t a = 0; a < nb; ++a) {
    std::vector<int> al(k);
    for (int d = 0; d < k; ++d) al[d] = static_cast<int>((a / bstride[d]) % (orders[d] + 1));
    std::vector<T> v(A[a].begin(), A[a].begin() + q);
    for (std::size_t b = 1; b <= a; ++b) {
      bool le = true;
      long coef = 1;
      std::size_t amb = 0;
      for (int d = 0; d < k; ++d) {
        int bd = static_cast<int>((b / bstride[d]) % (orders[d] + 1));
        if (bd > al[d]) { le = false; break; }
        coef *= detail::binomial<long>(al[d], bd);
        amb += (al[d] - bd) * bstride[d];
      }
      if (!le) continue;
      const T f = T(coef) * A[b][q];
      for (int c = 0; c < q; ++c) v[c] -= f * C[amb][c];
    }
    for (int c = 0; c < q; ++c) C[a][c] = v[c] / A[0][q];
  }
  return C[top];
}

}  // namespace splinex

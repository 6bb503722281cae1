// The commands' side of the documents (issue 48: apps/ builds no JSON): a document file read into
// its validated value, a result printed or written as text, and the small result documents of the
// kernel commands (eval, the spline operations, hybrid eval). The commands route documents; what
// is in them is written here and in each package's io (vrep/io, cut/io).
#pragma once
#include <array>
#include <string>
#include <vector>

#include "hybrid/hybrid.hpp"
#include "io/json_io.hpp"
#include "io/result_json.hpp"
#include "untrim/loops.hpp"

namespace splinex {

/// A spline document (a path, "-" for standard input) read exactly and validated; `where` names
/// it in errors ("outer", "surface").
BSpline<Rational> read_spline(const std::string& path, const Limits& limits, const ReadLimits& read_limits, const std::string& where = "");
/// A hybrid patch document read exactly and validated.
HybridPatch<Rational> read_hybrid(const std::string& path, const Limits& limits, const ReadLimits& read_limits);
/// A trimmed-domain document (untrim's input) read exactly and validated.
TrimmedDomain read_trimmed_domain(const std::string& path, const ReadLimits& read_limits);

/// A document as text: one line (indent < 0) or indented, with the final newline.
std::string document_text(const Json& doc, int indent = -1);
/// The document on standard output (document_text).
void print_document(const Json& doc, int indent = -1);

/// {"point": [...]}: an evaluation's result.
template <class T>
Json point_document(const std::vector<T>& p) {
  return Json{{"point", point_to_json(p)}};
}
/// A spline operation's results: the spline itself when there is one, else {"splines": [...]}.
template <class T>
Json splines_document(const std::vector<BSpline<T>>& results) {
  if (results.size() == 1) return spline_to_json(results[0]);
  Json parts = Json::array();
  for (const auto& r : results) parts.push_back(spline_to_json(r));
  return Json{{"splines", parts}};
}

/// A result as its document: one overload per result type, so that a command writes
/// print_document(document(compose(...))) whatever it computed.
template <class T>
Json document(const BSpline<T>& S) {
  return spline_to_json(S);
}
/// Bezier extraction's result: {"pieces": [{"box": ..., "spline": ...}, ...]}.
template <class T>
Json document(const std::vector<BezierPiece<T>>& pieces) {
  return bezier_pieces_to_json(pieces);
}
/// Algorithm 2's untrimmed tiles.
template <class F>
Json document(const TensorComposition<F>& A) {
  return tensor_composition_to_json(A);
}
/// Algorithm 1's trimmed pieces; eps: the trimming polylines' tolerance of a float run.
template <class F>
Json document(const TrimmedComposition<F>& C, double eps) {
  return trimmed_composition_to_json(C, eps);
}
/// A hybrid patch (exact).
Json document(const HybridPatch<Rational>& P);

}  // namespace splinex

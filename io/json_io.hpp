// The spline document (JSON) read exactly and written per arithmetic.
//   {"type": "bspline", "degrees": [3, 2], "knots": [[...], [...]],
//    "points": [[x, y, z], ...], "weights": [...]}
// A number is a JSON string holding an integer, a fraction or a decimal, or a JSON number read
// exactly from its text (the SAX reader keeps the token, so 0.1 is 1/10, not the double near it).
#pragma once
#include <iosfwd>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "exact/rational.hpp"
#include "spline/bspline.hpp"

namespace splinex {

using Json = nlohmann::json;

/// What reading a document may cost, checked while reading (before the cost is paid).
struct ReadLimits {
  /// Elements of any one array (points, knots, weights, loop vertices, a point's coordinates).
  std::size_t max_elements = static_cast<std::size_t>(-1);
  /// Memory of the document tree, estimated per value as it is built (16 bytes per integer or
  /// literal, about 64 per other number or container, plus the text of long numbers).
  /// 0: a quarter of the memory budget (exact/memory.hpp).
  std::size_t max_tree_bytes = 0;
  /// From the spline limits: an array may hold max_control_points + 2 (max_degree + 1) elements.
  static ReadLimits from(const Limits& limits);
};

/// Parses JSON text; an integer that fits 64 bits stays a JSON integer, every other number becomes
/// a JSON string holding its original text (so json_number reads both exactly). Malformed
/// JSON, duplicate keys, nesting deeper than 64 and documents beyond `limits` throw ParseError
/// (SizeLimitError for the limits) naming `source`.
Json read_json(std::istream& in, const std::string& source, const ReadLimits& limits = {});
Json read_json_file(const std::string& path, const ReadLimits& limits = {});  // "-" is standard input

/// A number field (string or number text) read exactly.
Rational json_number(const Json& j, const std::string& field);
/// Every number of a model document (any text that reads as one) within limits.max_input_bits;
/// SizeLimitError naming its path otherwise. The readers of the exact subdivision engines' models
/// (V-rep, cutting, the hybrid patch) call it before anything else, since their work grows with
/// the length of the numbers and no box budget bounds that.
void check_document_bits(const Json& doc, const std::string& where, const Limits& limits);

/// A non-negative integer field (e.g. a degree), range-checked.
int json_int(const Json& j, const std::string& field, int lo, int hi);

/// The spline document read exactly and validated (validate() rules; unknown fields rejected).
BSpline<Rational> spline_from_json(const Json& doc, const Limits& limits = {}, const std::string& where = "");

/// A double for a JSON field beside an exact value: the number when finite, else a string saying
/// it is beyond double's range (JSON has no inf or nan; nlohmann would write null).
Json approx_json(double x);

/// Comma-separated numbers, each read exactly ("0.5,1/3,2e-1").
std::vector<Rational> parse_number_list(const std::string& text, const std::string& field);

template <class T>
Json spline_to_json(const BSpline<T>& S) {
  Json doc;
  doc["type"] = "bspline";
  doc["degrees"] = S.degrees;
  Json knots = Json::array();
  for (const auto& U : S.knots) {
    Json k = Json::array();
    for (const auto& u : U) k.push_back(ArithTraits<T>::to_json(u));
    knots.push_back(std::move(k));
  }
  doc["knots"] = std::move(knots);
  Json pts = Json::array();
  for (std::size_t i = 0; i < S.size(); ++i) {
    Json p = Json::array();
    for (int c = 0; c < S.q; ++c) p.push_back(ArithTraits<T>::to_json(S.points[i * S.q + c]));
    pts.push_back(std::move(p));
  }
  doc["points"] = std::move(pts);
  if (S.is_rational()) {
    Json w = Json::array();
    for (const auto& x : S.weights) w.push_back(ArithTraits<T>::to_json(x));
    doc["weights"] = std::move(w);
  }
  return doc;
}

template <class T>
Json point_to_json(const std::vector<T>& p) {
  Json a = Json::array();
  for (const auto& x : p) a.push_back(ArithTraits<T>::to_json(x));
  return a;
}

}  // namespace splinex

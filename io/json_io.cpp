#include <cmath>
#include "io/json_io.hpp"

#include <cctype>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>
#include <type_traits>

#include "base/errors.hpp"
#include "exact/memory.hpp"

namespace splinex {

namespace {

// A SAX consumer that builds a DOM in which numbers are kept as their source text.
class ExactNumberSax {
 public:
  using number_integer_t = Json::number_integer_t;
  using number_unsigned_t = Json::number_unsigned_t;
  using number_float_t = Json::number_float_t;
  using string_t = Json::string_t;
  using binary_t = Json::binary_t;

  ExactNumberSax(std::size_t max_elements, std::size_t max_bytes) : max_elements_(max_elements), max_bytes_(max_bytes) {}
  Json root;
  std::string error;
  bool size_limit = false;  // error is a size limit, not a syntax error

  bool null() { return put(nullptr) != nullptr; }
  bool boolean(bool b) { return put(b) != nullptr; }
  // Integers that fit 64 bits are kept as JSON integers (exact, no heap node); every other number
  // as its source text.
  bool number_integer(number_integer_t v) { return put(v) != nullptr; }
  bool number_unsigned(number_unsigned_t v) { return put(v) != nullptr; }
  bool number_float(number_float_t, const string_t& text) { return put(text) != nullptr; }
  bool string(string_t& s) { return put(s) != nullptr; }
  bool binary(binary_t&) { error = "binary values are not supported"; return false; }
  // Documents nest a few levels (a spline: 3); a deep nesting is refused before it costs memory
  // or stack (10^6 nested arrays would overflow the stack when the DOM is destroyed).
  static constexpr std::size_t max_depth = 64;
  bool too_deep() {
    if (stack_.size() < max_depth) return false;
    error = "nesting deeper than " + std::to_string(max_depth) + " levels";
    return true;
  }
  bool start_object(std::size_t) {
    if (too_deep()) return false;
    Json* j = put(Json::object());
    if (!j) return false;
    stack_.push_back(j);
    keys_.emplace_back();
    return true;
  }
  bool key(string_t& k) {
    if (stack_.back()->contains(k)) { error = "duplicate key \"" + k + "\""; return false; }
    if (!charge(k.size())) return false;
    slot_ = &(*stack_.back())[k];
    keys_.back() = k;
    return true;
  }
  bool end_object() { stack_.pop_back(); keys_.pop_back(); return true; }
  bool start_array(std::size_t) {
    if (too_deep()) return false;
    Json* j = put(Json::array());
    if (!j) return false;
    stack_.push_back(j);
    keys_.emplace_back();
    return true;
  }
  bool end_array() { stack_.pop_back(); keys_.pop_back(); return true; }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception& ex) {
    error = ex.what();
    return false;
  }

 private:
  // The path of the value being read (e.g. "points[17][0]"), or of the innermost open container.
  std::string path(bool of_new_value = true) const {
    std::string p;
    const std::size_t n = stack_.size() - (of_new_value || stack_.empty() ? 0 : 1);
    for (std::size_t i = 0; i < n; ++i) {
      if (stack_[i]->is_array())
        p += "[" + std::to_string(stack_[i]->size() - (i + 1 < stack_.size() ? 1 : 0)) + "]";
      else
        p += (p.empty() ? "" : ".") + keys_[i];
    }
    return p.empty() ? "document" : p;
  }
  // Estimated tree memory: a value (16 bytes), with its heap node for a string or a container
  // (about 48 bytes with malloc's overhead) plus text beyond the short-string buffer.
  bool charge(std::size_t text, bool heap = true) {
    bytes_ += 16 + (heap ? 48 : 0) + (text > 15 ? text + 1 : 0);
    if (bytes_ <= max_bytes_) return true;
    size_limit = true;
    error = "reading it needs more than " + format_bytes(max_bytes_) + " of memory (at " + path() +
            "); the limit is a quarter of the memory budget (fix: give a smaller document, or raise --max-memory)";
    return false;
  }
  template <class V>
  Json* put(V&& v) {
    std::size_t text = 0;
    constexpr bool heap = !std::is_arithmetic_v<std::decay_t<V>> && !std::is_null_pointer_v<std::decay_t<V>>;
    if constexpr (std::is_same_v<std::decay_t<V>, std::string>) text = v.size();
    if (!charge(text, heap)) return nullptr;
    if (stack_.empty()) { root = Json(std::forward<V>(v)); return &root; }
    if (stack_.back()->is_array()) {
      if (stack_.back()->size() >= max_elements_) {
        size_limit = true;
        error = path(false) + " has more than " + std::to_string(max_elements_) +
                " elements (fix: give a smaller document, or raise --max-control-points)";
        return nullptr;
      }
      stack_.back()->push_back(Json(std::forward<V>(v)));
      return &stack_.back()->back();
    }
    *slot_ = Json(std::forward<V>(v));
    return slot_;
  }
  std::vector<Json*> stack_;
  std::vector<std::string> keys_;
  Json* slot_ = nullptr;
  std::size_t max_elements_, max_bytes_, bytes_ = 0;
};

std::string at(const std::string& where, const std::string& field) { return where.empty() ? field : where + "." + field; }

}  // namespace

ReadLimits ReadLimits::from(const Limits& limits) {
  ReadLimits r;
  r.max_elements = limits.max_control_points + 2 * (static_cast<std::size_t>(limits.max_degree) + 1);
  return r;
}

Json read_json(std::istream& in, const std::string& source, const ReadLimits& limits) {
  std::size_t max_bytes = limits.max_tree_bytes;
  if (max_bytes == 0) {
    const auto& b = current_memory_budget();
    max_bytes = (b.bytes ? b.bytes : default_memory_budget()) / 4;
  }
  ExactNumberSax sax(limits.max_elements, max_bytes);
  bool ok = false;
  try {
    ok = Json::sax_parse(in, &sax);
  } catch (const nlohmann::json::exception& e) {
    sax.error = e.what();
  }
  if (!ok && sax.size_limit) throw SizeLimitError(source, sax.error, "");
  if (!ok) throw ParseError(source, "malformed JSON: " + sax.error, "fix the JSON syntax");
  return std::move(sax.root);  // a member: without the move, the whole tree would be copied
}

Json approx_json(double x) {
  if (std::isfinite(x)) return x;
  if (std::isnan(x)) return "not a number";
  return x > 0 ? "+inf: beyond double's range (see the exact value)" : "-inf: beyond double's range (see the exact value)";
}

Json read_json_file(const std::string& path, const ReadLimits& limits) {
  if (path == "-") return read_json(std::cin, "<stdin>", limits);
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw UsageError(path, "is a directory, not a document", "give the path of a JSON file");
  std::ifstream in(path);
  if (!in) throw UsageError(path, "cannot open the file", "check the path");
  return read_json(in, path, limits);
}

Rational json_number(const Json& j, const std::string& field) {
  if (j.is_number_integer() && !j.is_number_unsigned()) return Rational(j.get<std::int64_t>());
  if (j.is_number_unsigned()) return Rational(j.get<std::uint64_t>());
  if (!j.is_string()) throw ParseError(field, "is not a number", "write a number or a string holding one");
  return parse_number(j.get<std::string>(), field);
}

namespace {

/// The path of a document value, built only for the message of a refusal.
struct PathStep {
  const std::string* key = nullptr;
  std::size_t index = 0;
};
std::string path_text(const std::string& where, const std::vector<PathStep>& path) {
  std::string s = where;
  for (const auto& p : path) s += p.key ? "." + *p.key : "[" + std::to_string(p.index) + "]";
  return s;
}

/// Bounds on the bits of a decimal number text without reading it: value = M 10^e with M of d
/// digits (the decimal point folded into e), so in lowest terms some part has at least
/// (|e| - d) log2(10) bits and none more than (d + |e|) log2(10) + 1. False when the text is not of
/// that form (fractions "p/q" are read exactly).
bool decimal_bit_bounds(const std::string& t, double& lo, double& hi) {
  std::size_t i = 0, d = 0;
  long long e = 0;
  if (i < t.size() && (t[i] == '-' || t[i] == '+')) ++i;
  bool point = false;
  for (; i < t.size(); ++i) {
    if (std::isdigit(static_cast<unsigned char>(t[i]))) {
      ++d;
      if (point) --e;
    } else if (t[i] == '.' && !point) {
      point = true;
    } else {
      break;
    }
  }
  if (d == 0) return false;
  if (i < t.size()) {
    if (t[i] != 'e' && t[i] != 'E') return false;
    const std::string x = t.substr(i + 1);
    if (x.empty() || x.size() > 9) return false;
    std::size_t k = 0;
    long long v = 0;
    bool neg = false;
    if (x[k] == '-' || x[k] == '+') neg = x[k++] == '-';
    if (k == x.size()) return false;
    for (; k < x.size(); ++k) {
      if (!std::isdigit(static_cast<unsigned char>(x[k]))) return false;
      v = 10 * v + (x[k] - '0');
    }
    e += neg ? -v : v;
  }
  const double log2_10 = 3.3219280948873622;
  const double ae = static_cast<double>(e < 0 ? -e : e), dd = static_cast<double>(d);
  lo = (ae - dd) * log2_10;
  hi = (dd + ae) * log2_10 + 1;
  return true;
}

void check_bits_at(const Json& doc, const std::string& where, std::vector<PathStep>& path, const Limits& limits) {
  if (doc.is_object()) {
    for (auto it = doc.begin(); it != doc.end(); ++it) {
      // What a command wrote about the model (at its top level) and text fields are not input numbers.
      const std::string& k = it.key();
      if ((path.empty() && (k == "summary" || k == "topology")) || k == "name" || k == "label" || k == "type" ||
          k == "category" || k == "status" || k == "description" || k == "note")
        continue;
      path.push_back({&k, 0});
      check_bits_at(it.value(), where, path, limits);
      path.pop_back();
    }
  } else if (doc.is_array()) {
    for (std::size_t i = 0; i < doc.size(); ++i) {
      path.push_back({nullptr, i});
      check_bits_at(doc[i], where, path, limits);
      path.pop_back();
    }
  } else if (doc.is_string()) {
    const std::string& t = doc.get_ref<const std::string&>();
    // Names and labels are strings too: only a text that reads as a number is one.
    if (t.empty() || !(std::isdigit(static_cast<unsigned char>(t[0])) || t[0] == '-' || t[0] == '+' || t[0] == '.')) return;
    double lo = 0, hi = 0;
    if (decimal_bit_bounds(t, lo, hi)) {
      if (hi <= static_cast<double>(limits.max_input_bits)) return;  // short: no need to read it
      if (lo > static_cast<double>(limits.max_input_bits))
        throw SizeLimitError(path_text(where, path),
                             "has a number of at least " + std::to_string(static_cast<long long>(lo)) + " bits, over the exact limit of " +
                                 std::to_string(limits.max_input_bits),
                             "give the number with fewer digits, or raise the limit with --max-input-bits");
    }
    Rational x;
    try {
      x = parse_number(t, where);
    } catch (const ParseError&) {
      return;  // not a number: the reader names it where a number is needed
    }
    limits.check_bits(bit_size(x), path_text(where, path));
  }
  // JSON integers fit 64 bits: under any limit (--max-input-bits is at least 64).
}

}  // namespace

void check_document_bits(const Json& doc, const std::string& where, const Limits& limits) {
  std::vector<PathStep> path;
  check_bits_at(doc, where, path, limits);
}

int json_int(const Json& j, const std::string& field, int lo, int hi) {
  const Rational r = json_number(j, field);
  if (denominator(r) != 1 || r < lo || r > hi)
    throw ValidationError(field, "must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]",
                          "give a whole number in that range");
  return static_cast<int>(numerator(r).convert_to<long>());
}

BSpline<Rational> spline_from_json(const Json& doc, const Limits& limits, const std::string& where) {
  if (!doc.is_object()) throw ValidationError(at(where, "document"), "is not a JSON object", "give a spline document {\"type\": \"bspline\", ...}");
  static const std::set<std::string> known{"type", "degrees", "knots", "points", "weights"};
  for (auto it = doc.begin(); it != doc.end(); ++it)
    if (!known.count(it.key()))
      throw ValidationError(at(where, it.key()), "is an unknown field",
                            "remove it; a spline document has type, degrees, knots, points and optional weights");
  for (const char* f : {"type", "degrees", "knots", "points"})
    if (!doc.contains(f)) throw ValidationError(at(where, f), "is missing", "add the field");
  if (doc["type"] != "bspline")
    throw ValidationError(at(where, "type"), "is not \"bspline\"", "set \"type\": \"bspline\"");
  const Json& degs = doc["degrees"];
  if (!degs.is_array() || degs.empty())
    throw ValidationError(at(where, "degrees"), "is not a non-empty array", "give one degree per direction, e.g. [3, 2]");
  BSpline<Rational> S;
  for (std::size_t d = 0; d < degs.size(); ++d)
    S.degrees.push_back(json_int(degs[d], at(where, "degrees[" + std::to_string(d) + "]"), 0, limits.max_degree));
  const Json& knots = doc["knots"];
  if (!knots.is_array()) throw ValidationError(at(where, "knots"), "is not an array", "give one array of knots per direction");
  for (std::size_t d = 0; d < knots.size(); ++d) {
    const std::string f = at(where, "knots[" + std::to_string(d) + "]");
    if (!knots[d].is_array()) throw ValidationError(f, "is not an array", "give the knots of this direction as an array");
    if (knots[d].size() > limits.max_control_points + 2 * static_cast<std::size_t>(limits.max_degree) + 2)
      limits.check_count(knots[d].size(), f);
    std::vector<Rational> U;
    U.reserve(knots[d].size());
    for (std::size_t i = 0; i < knots[d].size(); ++i) U.push_back(json_number(knots[d][i], f + "[" + std::to_string(i) + "]"));
    S.knots.push_back(std::move(U));
  }
  const Json& pts = doc["points"];
  if (!pts.is_array() || pts.empty())
    throw ValidationError(at(where, "points"), "is not a non-empty array", "give the control points as [[x, y, ...], ...]");
  limits.check_count(pts.size(), at(where, "points"));
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const std::string f = at(where, "points[" + std::to_string(i) + "]");
    if (!pts[i].is_array() || pts[i].empty()) throw ValidationError(f, "is not a non-empty array", "write a point as [x, y, ...]");
    if (i == 0) S.q = static_cast<int>(pts[0].size());
    if (pts[i].size() != static_cast<std::size_t>(S.q))
      throw ValidationError(f, "has " + std::to_string(pts[i].size()) + " coordinates, point 0 has " + std::to_string(S.q),
                            "give every control point the same number of coordinates");
    for (std::size_t c = 0; c < pts[i].size(); ++c) S.points.push_back(json_number(pts[i][c], f + "[" + std::to_string(c) + "]"));
  }
  if (doc.contains("weights")) {
    const Json& w = doc["weights"];
    if (!w.is_array()) throw ValidationError(at(where, "weights"), "is not an array", "give one weight per control point");
    for (std::size_t i = 0; i < w.size(); ++i) S.weights.push_back(json_number(w[i], at(where, "weights[" + std::to_string(i) + "]")));
    if (S.weights.empty()) throw ValidationError(at(where, "weights"), "is empty", "give one weight per control point, or omit the field");
  }
  try {
    validate(S, limits);
  } catch (const Error& e) {
    if (where.empty()) throw;
    throw ValidationError(where, e.what(), "");
  }
  return S;
}

std::vector<Rational> parse_number_list(const std::string& text, const std::string& field) {
  std::vector<Rational> out;
  std::size_t start = 0;
  if (text.find_first_not_of(" \t") == std::string::npos) return out;
  while (true) {
    const std::size_t comma = text.find(',', start);
    out.push_back(parse_number(text.substr(start, comma - start), field + "[" + std::to_string(out.size()) + "]"));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

}  // namespace splinex

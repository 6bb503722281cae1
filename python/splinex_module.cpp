// The Python module `splinex` (pybind11): spline documents, the exact kernel operations and
// verify, with numbers going in and out exactly. In: int, float (the double it is, a dyadic
// rational), fractions.Fraction, or a string ("1/3", "0.1" = 1/10). Out: fractions.Fraction.
//
//   import splinex
//   S = {"degrees": [3], "knots": [[0, 0, 0, 0, 0.5, 1, 1, 1, 1]], "points": [[0], [1], [3], [2], [5]]}
//   E = splinex.elevate(S, by=1)                  # exact, Fractions
//   rep = splinex.verify("elevate", S, my_float_result, by=1)
//   assert rep.bits_lost < 4 and rep.structure != "different"
#include <algorithm>
#include <limits>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "compose/compose.hpp"
#include "crosscheck/operations_ff.hpp"
#include "crosscheck/verify.hpp"
#include "fixtures/random_spline.hpp"
#include "spline/kernel.hpp"

namespace py = pybind11;
using namespace splinex;

namespace {

/// A Python number as the exact text splinex's readers take (floats exactly as their doubles).
std::string number_text(const py::handle& v, const std::string& field) {
  if (py::isinstance<py::bool_>(v)) throw ValidationError(field, "is a bool", "give a number");
  if (py::isinstance<py::int_>(v)) return py::str(v);
  if (py::isinstance<py::float_>(v)) return to_fraction_string(exact_from_double(v.cast<double>(), field));
  if (py::isinstance<py::str>(v)) return v.cast<std::string>();
  if (py::hasattr(v, "numerator") && py::hasattr(v, "denominator"))  // fractions.Fraction, numbers.Rational
    return std::string(py::str(v.attr("numerator"))) + "/" + std::string(py::str(v.attr("denominator")));
  throw ValidationError(field, "is not a number (" + std::string(py::str(v.get_type().attr("__name__"))) + ")",
                        "give an int, float, fractions.Fraction or a string such as \"1/3\"");
}

Rational to_rational(const py::handle& v, const std::string& field) { return parse_number(number_text(v, field), field); }

py::object fraction(const Rational& x) {
  static py::object F = py::module_::import("fractions").attr("Fraction");
  return F(to_fraction_string(x));
}

/// A Python int (not a bool) in [lo, hi], or a ValidationError naming the field (never pybind11's
/// untyped "Unable to cast").
long long int_in_range(const py::handle& v, const std::string& field, long long lo, long long hi) {
  if (py::isinstance<py::bool_>(v) || !py::isinstance<py::int_>(v))
    throw ValidationError(field, "is not an integer (" + std::string(py::str(v.get_type().attr("__name__"))) + ")",
                          "give an int in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  const py::int_ lo_py(lo), hi_py(hi);
  if (v < lo_py || v > hi_py)
    throw ValidationError(field, std::string(py::str(v)) + " is outside [" + std::to_string(lo) + ", " + std::to_string(hi) + "]",
                          "give an int in that range");
  return v.cast<long long>();
}

/// Documents nest a few levels (a spline: 3), as the CLI's JSON reader: deeper nesting (or a list
/// that contains itself) is refused before it costs stack.
constexpr int max_nesting = 64;

Json degrees_json(const py::handle& v, const std::string& field) {
  if (!py::isinstance<py::list>(v) && !py::isinstance<py::tuple>(v))
    throw ValidationError(field, "is not a list of degrees", "give e.g. [3] or [2, 3]");
  Json out = Json::array();
  std::size_t i = 0;
  for (auto x : v) {
    out.push_back(int_in_range(x, field + "[" + std::to_string(i) + "]", 0, std::numeric_limits<int>::max()));
    if (++i > 3) break;  // the reader refuses more than 3 directions; no need to read a huge list
  }
  return out;
}

/// Python containers of numbers -> the JSON document splinex reads (numbers as exact strings).
Json to_json_numbers(const py::handle& v, const std::string& field, int depth = 0) {
  if (depth > max_nesting)
    throw ValidationError(field, "nests deeper than " + std::to_string(max_nesting) + " levels (or contains itself)",
                          "give a document of numbers, lists and dicts as splinex writes them");
  if (py::isinstance<py::dict>(v)) {
    Json out = Json::object();
    for (auto kv : v.cast<py::dict>()) {
      const std::string key = py::str(kv.first);
      out[key] = (key == "type") ? Json(std::string(py::str(kv.second)))
                 : (key == "degrees") ? degrees_json(kv.second, field + "." + key)
                                      : to_json_numbers(kv.second, field + "." + key, depth + 1);
    }
    return out;
  }
  if (py::isinstance<py::list>(v) || py::isinstance<py::tuple>(v)) {
    Json out = Json::array();
    std::size_t i = 0;
    for (auto x : v) out.push_back(to_json_numbers(x, field + "[" + std::to_string(i++) + "]", depth + 1));
    return out;
  }
  if (py::isinstance<py::bool_>(v)) return Json(v.cast<bool>());  // flags of result documents ("homogeneous")
  if (v.is_none()) return Json(nullptr);
  return Json(number_text(v, field));
}

BSpline<Rational> to_spline(const py::handle& v, const std::string& field = "spline") {
  if (!py::isinstance<py::dict>(v))
    throw ValidationError(field, "is not a dict", "give {\"degrees\": [...], \"knots\": [[...]], \"points\": [[...]]}");
  Json doc = to_json_numbers(v, field);
  if (!doc.contains("type")) doc["type"] = "bspline";
  return spline_from_json(doc, Limits{}, field);
}

py::dict from_spline(const BSpline<Rational>& S) {
  py::dict d;
  d["type"] = "bspline";
  d["degrees"] = S.degrees;
  py::list knots, points;
  for (const auto& U : S.knots) {
    py::list row;
    for (const auto& u : U) row.append(fraction(u));
    knots.append(row);
  }
  for (std::size_t i = 0; i < S.points.size() / S.q; ++i) {
    py::list p;
    for (int c = 0; c < S.q; ++c) p.append(fraction(S.points[i * S.q + c]));
    points.append(p);
  }
  d["knots"] = knots;
  d["points"] = points;
  if (S.is_rational()) {
    py::list w;
    for (const auto& x : S.weights) w.append(fraction(x));
    d["weights"] = w;
  }
  return d;
}

std::vector<Rational> to_rationals(const py::handle& v, const std::string& field) {
  std::vector<Rational> out;
  if (py::isinstance<py::list>(v) || py::isinstance<py::tuple>(v)) {
    std::size_t i = 0;
    for (auto x : v) out.push_back(to_rational(x, field + "[" + std::to_string(i++) + "]"));
  } else {
    out.push_back(to_rational(v, field));
  }
  return out;
}

py::list fractions_of(const std::vector<Rational>& v) {
  py::list l;
  for (const auto& x : v) l.append(fraction(x));
  return l;
}

/// The Operation for `name` from keyword arguments (the CLI's options, range-checked as the CLI
/// does; an argument the operation does not take is a TypeError, as Python's own functions raise).
Operation make_operation(const std::string& name, const py::dict& kw, const std::string& caller = "verify: ") {
  // "refine" is knot refinement, insert-knots by A5.4 (Operation's default), as in `splinex verify`.
  Operation op = Operation::parse_kind(name == "refine" ? "insert-knots" : name);
  std::vector<std::string> allowed{"dir"};
  switch (op.kind) {
    case Operation::Kind::insert_knots: allowed.push_back("knots"); break;
    case Operation::Kind::elevate: allowed.push_back("by"); break;
    case Operation::Kind::derivative: allowed.push_back("order"); break;
    case Operation::Kind::split: allowed.push_back("at"); break;
    case Operation::Kind::reparametrize: allowed.push_back("interval"); break;
    case Operation::Kind::extract_bezier: allowed.clear(); break;
    default: break;
  }
  for (auto kv : kw) {
    const std::string key = py::str(kv.first);
    if (std::find(allowed.begin(), allowed.end(), key) == allowed.end()) {
      std::string names;
      for (const auto& a : allowed) names += (names.empty() ? "" : ", ") + a;
      throw py::type_error(caller + name + " takes no argument '" + key + "'" +
                           (names.empty() ? std::string(" (it takes none)") : " (it takes " + names + ")"));
    }
  }
  if (kw.contains("dir")) op.dir = static_cast<int>(int_in_range(kw["dir"], "dir", 0, 2));
  switch (op.kind) {
    case Operation::Kind::insert_knots:
      if (!kw.contains("knots")) throw UsageError("knots", "insert-knots needs knots", "pass knots=[...]");
      op.knots = to_rationals(kw["knots"], "knots");
      break;
    case Operation::Kind::elevate: op.by = kw.contains("by") ? static_cast<int>(int_in_range(kw["by"], "by", 0, 1000000)) : 1; break;
    case Operation::Kind::derivative:
      op.by = kw.contains("order") ? static_cast<int>(int_in_range(kw["order"], "order", 1, 1000)) : 1;
      break;
    case Operation::Kind::split:
      if (!kw.contains("at")) throw UsageError("at", "split needs a parameter", "pass at=...");
      op.at = to_rational(kw["at"], "at");
      break;
    case Operation::Kind::reparametrize: {
      if (!kw.contains("interval")) throw UsageError("interval", "reparametrize needs an interval", "pass interval=(lo, hi)");
      const auto v = to_rationals(kw["interval"], "interval");
      if (v.size() != 2) throw UsageError("interval", "needs two numbers", "pass interval=(lo, hi)");
      op.lo = v[0];
      op.hi = v[1];
      break;
    }
    default: break;
  }
  return op;
}

/// verify's options, range-checked as the CLI checks --precision and --factor.
VerifyOptions verify_options(const py::object& precision, const py::object& factor) {
  VerifyOptions vo;
  vo.precision = static_cast<int>(int_in_range(precision, "precision", 2, 100000));
  vo.factor = to_rational(factor, "factor");
  if (!(vo.factor > 1)) throw UsageError("factor", "must be greater than 1", "pass e.g. factor=2");
  return vo;
}

/// What verify returns: the report's main numbers as attributes, the whole report as `report`.
struct PyReport {
  std::string structure;
  double bits_lost = 0;  // the worst of coefficients, values and the function-level error
  py::object function_upper, function_lower;
  py::list at;
  bool certified = false, within_factor = false;
  py::object report;  // the JSON report as Python objects
};

PyReport to_py(const VerifyReport& r) {
  PyReport p;
  p.structure = r.structure;
  const Json j = r.document();
  p.bits_lost = r.worst_bits_lost();
  // Only a certified bound (as the JSON report): None where the functions were not compared.
  p.function_upper = r.function.certified ? fraction(r.function.upper) : py::none();
  p.function_lower = fraction(r.function.lower);
  p.at = fractions_of(r.function.at);
  p.certified = r.function.certified;
  p.within_factor = r.function.within_factor;
  p.report = py::module_::import("json").attr("loads")(j.dump());
  return p;
}

}  // namespace

/// The rest of `splinex verify`'s operations as functions: refine, derivative, reparametrize, run
/// as verify runs them (run_operation), arguments checked by verify's reader.
static void add_more_operations(py::module_& m) {
  const auto one_result = [](const std::string& name, const py::dict& S, const py::dict& args) {
    const auto out = run_operation_exact(make_operation(name, args, "splinex."), to_spline(S), Limits{});
    return from_spline(out.at(0));
  };
  const auto with = [](std::initializer_list<std::pair<const char*, py::object>> kv) {
    py::dict d;
    for (const auto& [k, v] : kv)
      if (!v.is_none()) d[k] = v;
    return d;
  };
  m.def("refine", [one_result, with](const py::dict& S, const py::object& knots, const py::object& dir) {
          return one_result("refine", S, with({{"knots", knots}, {"dir", dir}}));
        },
        py::arg("spline"), py::arg("knots"), py::arg("dir") = 0, "knot refinement by A5.4 (NURBS Book): refine(spline, knots, dir=0), exact");
  m.def("derivative", [one_result, with](const py::dict& S, const py::object& order, const py::object& dir) {
          return one_result("derivative", S, with({{"order", order}, {"dir", dir}}));
        },
        py::arg("spline"), py::arg("order") = 1, py::arg("dir") = 0,
        "the derivative spline (hodograph): derivative(spline, order=1, dir=0), exact; polynomial splines only (a rational one is refused, as by the CLI)");
  m.def("reparametrize", [one_result, with](const py::dict& S, const py::object& interval, const py::object& dir) {
          return one_result("reparametrize", S, with({{"interval", interval}, {"dir", dir}}));
        },
        py::arg("spline"), py::arg("interval"), py::arg("dir") = 0, "the same function on a new interval: reparametrize(spline, (lo, hi), dir=0), exact");
}

PYBIND11_MODULE(splinex, m) {
  m.doc() = "splinex: exact B-spline kernel operations and exact verification of results computed elsewhere";
  // Every splinex error (bad input, limits, domains) is a ValueError with splinex's one-line text.
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const splinex::Error& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });
  py::class_<PyReport>(m, "Report")
      .def_readonly("structure", &PyReport::structure, "\"equal\", \"equal after rounding\" or \"different\"")
      .def_readonly("bits_lost", &PyReport::bits_lost, "worst bits lost: coefficients, values, function-level error")
      .def_readonly("function_upper", &PyReport::function_upper, "certified bound of sup |candidate - exact| (polynomial)")
      .def_readonly("function_lower", &PyReport::function_lower, "witnessed |candidate - exact| at `at`")
      .def_readonly("at", &PyReport::at)
      .def_readonly("certified", &PyReport::certified)
      .def_readonly("within_factor", &PyReport::within_factor)
      .def_readonly("report", &PyReport::report, "the whole report (as `splinex verify` prints it)")
      .def("__repr__", [](const PyReport& r) {
        return "<splinex.Report structure=" + r.structure + " bits_lost=" + std::to_string(r.bits_lost) + ">";
      });
  m.def(
      "structured_case",
      [](std::uint64_t seed, const py::object& max_dim_obj, bool rational, bool discontinuous, bool extreme_values) {
        const int max_dim = static_cast<int>(int_in_range(max_dim_obj, "max_dim", 1, 3));
        std::mt19937_64 rng(seed);
        StructuredOptions so;
        so.max_dim = max_dim;
        so.rational = rational;
        so.discontinuous = discontinuous;
        so.extreme_values = extreme_values;
        const StructuredCase c = structured_case(rng, so);
        return py::make_tuple(from_spline(c.spline), c.structures);
      },
      py::arg("seed"), py::arg("max_dim") = 1, py::arg("rational") = false, py::arg("discontinuous") = true,
      py::arg("extreme_values") = false,
      "splinex's structured generator (degree 0..7, C^-1 knots, single spans, unclamped ends, knots 2^-60 apart, "
      "shifted domains, ...): (spline, the structures it contains), reproducible from the seed");
  m.def("validate", [](const py::dict& S) { return from_spline(to_spline(S)); },
        "the spline read exactly and validated, as Fractions");
  // The exact kernel operations run on the fraction-free kernel, as `--arith exact` does
  // (crosscheck/operations_ff.hpp): the same values and errors as GMP's.
  m.def("evaluate", [](const py::dict& S, const py::object& at) { return fractions_of(evaluate_exact(to_spline(S), to_rationals(at, "at"))); },
        py::arg("spline"), py::arg("at"), "the exact value at a parameter (a number or a list, one per direction)");
  m.def("insert_knots", [](const py::dict& S, const py::object& knots, int dir) {
          return from_spline(ff::to_bspline(ff::refine_knots(ff::from_bspline(to_spline(S)), dir, to_rationals(knots, "knots"))));
        },
        py::arg("spline"), py::arg("knots"), py::arg("dir") = 0);
  m.def("elevate", [](const py::dict& S, int by, int dir) { return from_spline(ff::to_bspline(ff::elevate_degree(ff::from_bspline(to_spline(S)), dir, by))); },
        py::arg("spline"), py::arg("by") = 1, py::arg("dir") = 0);
  m.def("extract_bezier", [](const py::dict& S) {
    py::list out;
    for (const auto& pc : extract_bezier_exact(to_spline(S), Limits{})) {
      py::list box;
      for (const auto& [lo, hi] : pc.box) box.append(py::make_tuple(fraction(lo), fraction(hi)));
      py::dict d;
      d["box"] = box;
      d["spline"] = from_spline(pc.spline);
      out.append(d);
    }
    return out;
  });
  m.def("split", [](const py::dict& S, const py::object& at, int dir) {
          auto [L, R] = split_at(to_spline(S), dir, to_rational(at, "at"));
          return py::make_tuple(from_spline(L), from_spline(R));
        },
        py::arg("spline"), py::arg("at"), py::arg("dir") = 0);
  m.def("reverse", [](const py::dict& S, int dir) { return from_spline(reverse(to_spline(S), dir)); }, py::arg("spline"),
        py::arg("dir") = 0);
  add_more_operations(m);
  m.def(
      "verify",
      [](const std::string& operation, const py::dict& S, const py::object& candidate, const py::object& precision,
         const py::object& factor, const py::kwargs& kw) {
        VerifyOptions vo = verify_options(precision, factor);
        const BSpline<Rational> input = to_spline(S, "spline");
        if (operation == "eval") {
          for (auto kv : kw) throw py::type_error("verify: eval takes no argument '" + std::string(py::str(kv.first)) + "'");
          if (!py::isinstance<py::dict>(candidate) || !candidate.contains("at") || !candidate.contains("values"))
            throw ValidationError("candidate", "an eval candidate is {\"at\": [...], \"values\": [...]}", "give both lists");
          std::vector<std::vector<Rational>> at, values;
          std::size_t i = 0;
          for (auto x : candidate["at"]) at.push_back(to_rationals(x, "candidate.at[" + std::to_string(i++) + "]"));
          i = 0;
          for (auto x : candidate["values"]) values.push_back(to_rationals(x, "candidate.values[" + std::to_string(i++) + "]"));
          return to_py(verify_values(input, at, values, vo));
        }
        std::vector<BSpline<Rational>> cands;
        if (py::isinstance<py::dict>(candidate)) {  // the CLI's candidate documents: a spline, {"splines": ...}, {"pieces": ...}
          Json doc = to_json_numbers(candidate, "candidate");
          if (!doc.contains("splines") && !doc.contains("pieces") && !doc.contains("type")) doc["type"] = "bspline";
          cands = verify_candidate_splines(doc);
        } else {
          if (!py::isinstance<py::list>(candidate) && !py::isinstance<py::tuple>(candidate))
            throw py::type_error("candidate: is a " + std::string(py::str(py::type::of(candidate).attr("__name__"))) +
                                 ", not a spline document or a list of splines");
          std::size_t i = 0;
          for (auto c : candidate) {
            const std::string where = "candidate[" + std::to_string(i++) + "]";
            cands.push_back(py::isinstance<py::dict>(c) && c.contains("spline") ? to_spline(c["spline"], where + ".spline")
                                                                                  : to_spline(c, where));
          }
        }
        return to_py(verify(make_operation(operation, kw), input, cands, vo));
      },
      py::arg("operation"), py::arg("spline"), py::arg("candidate"), py::arg("precision") = 53, py::arg("factor") = 2,
      "Judge a candidate result exactly: operation is insert-knots or refine (knots=...), elevate (by=...), extract-bezier, "
      "split (at=...), reparametrize (interval=(lo, hi)), reverse, derivative (order=...) or eval (candidate {\"at\": [...], \"values\": [...]}); "
      "dir=... selects the direction. Floats are taken as the doubles they are.");
  m.def(
      "verify_compose",
      [](const py::dict& T, const py::dict& S, const py::object& candidate, const std::string& method, bool expand,
         const py::object& precision, const py::object& factor) {
        VerifyOptions vo = verify_options(precision, factor);
        const auto outer = to_spline(T, "outer"), inner = to_spline(S, "inner");
        if (method == "trimmed") return to_py(verify_trimmed_composition(outer, inner, to_json_numbers(candidate, "candidate"), vo));
        if (method == "tensor") return to_py(verify_tensor_composition(outer, inner, to_json_numbers(candidate, "candidate"), vo));
        if (method != "symbolic" && method != "interpolation")
          throw UsageError("method", method + " is not a composition method", "pass symbolic, interpolation, trimmed or tensor");
        CompositionOptions co;
        co.expand = expand;
        return to_py(verify_splines("compose", {compose(outer, inner, co)}, {to_spline(candidate, "candidate")}, vo));
      },
      py::arg("outer"), py::arg("inner"), py::arg("candidate"), py::arg("method") = "symbolic", py::arg("expand") = false,
      py::arg("precision") = 53, py::arg("factor") = 2,
      "Judge a composition T(S) exactly: method symbolic or interpolation (candidate: one spline), trimmed (Algorithm 1: "
      "the document of splinex compose --method trimmed, e.g. json.load of it) or tensor (Algorithm 2's tiles). "
      "Floats are taken as the doubles they are.");
}

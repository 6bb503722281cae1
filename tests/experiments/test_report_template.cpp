// The report's templates (experiments/report_template.hpp): placeholders, conditions, and the
// errors that keep a section from dropping a sentence or computing a number for nothing.
#include <catch2/catch.hpp>

#include <stdexcept>
#include <string>

#include "experiments/report_template.hpp"

using splinex::ReportTemplate;

TEST_CASE("report templates fill values and conditions", "[report_template]") {
  const std::string text = "a {{x}} b{{?c}} yes {{y}}{{?d}} both{{/d}}{{:c}} no{{/c}}.";
  auto t = ReportTemplate::from_text("t", text);
  t.set("x", 3).set("y", "Y").when("c", true).when("d", true);
  CHECK(t.render() == "a 3 b yes Y both.");
  t.when("d", false);
  CHECK(t.render() == "a 3 b yes Y.");
  t.when("c", false).when("d", true);  // the inner block of a left-out branch stays out
  CHECK(t.render() == "a 3 b no.");
  // A value used only in a branch left out must still be set (the template is checked whole).
  auto u = ReportTemplate::from_text("u", "{{?c}}{{y}}{{/c}}");
  u.when("c", false);
  CHECK_THROWS_AS(u.render(), std::logic_error);
  u.set("y", "1");
  CHECK(u.render().empty());
}

TEST_CASE("report templates refuse what a section got wrong", "[report_template]") {
  auto missing = ReportTemplate::from_text("m", "n = {{n}}");
  CHECK_THROWS_WITH(missing.render(), Catch::Contains("{{n}} has no value"));
  // A planted bug: a value computed for a sentence the template no longer has.
  auto unused = ReportTemplate::from_text("u", "n = {{n}}");
  unused.set("n", 1).set("m", 2);
  CHECK_THROWS_WITH(unused.render(), Catch::Contains("'m' is set but"));
  auto flag = ReportTemplate::from_text("f", "text");
  flag.when("ran:cut", true);
  CHECK_THROWS_WITH(flag.render(), Catch::Contains("'ran:cut' is set but"));
  auto cond = ReportTemplate::from_text("c", "{{?ran:cut}}see the cut section{{/ran:cut}}");
  CHECK_THROWS_WITH(cond.render(), Catch::Contains("has no condition"));
  cond.when("ran:cut", false);
  CHECK(cond.render().empty());
  CHECK_THROWS_AS(ReportTemplate::from_text("b", "{{?a}} x"), std::logic_error);            // never closed
  CHECK_THROWS_AS(ReportTemplate::from_text("b", "{{?a}} x {{/b}}"), std::logic_error);     // closes another
  CHECK_THROWS_AS(ReportTemplate::from_text("b", "{{:a}}"), std::logic_error);              // else outside
  CHECK_THROWS_AS(ReportTemplate::from_text("b", "{{a b}}"), std::logic_error);             // not a name
  CHECK_THROWS_AS(ReportTemplate::from_text("b", "{{a"), std::logic_error);                 // not closed
  CHECK_THROWS_WITH(ReportTemplate::from_text("b", "{{?a}}{{?c}}{{/a}}{{/c}}"), Catch::Contains("'{{?c}}' is still open"));
  // What an editor would change silently: CRLF line ends, a space at a line's end.
  CHECK_THROWS_WITH(ReportTemplate::from_text("b", "one\r\ntwo"), Catch::Contains("carriage return"));
  CHECK_THROWS_WITH(ReportTemplate::from_text("b", "one; \ntwo"), Catch::Contains("ends in a space"));
  CHECK_THROWS_WITH(ReportTemplate("no-such-part"), Catch::Contains("does not exist"));
}

TEST_CASE("every embedded report template parses and drops one final newline", "[report_template]") {
  const auto names = splinex::report_template_names();
  REQUIRE(names.size() >= 2);
  for (const auto& n : names) {
    INFO(n);
    CHECK_NOTHROW(splinex::report_template_fields(n));
  }
  // proofs.md ends with "{{rows}}\n" in the file; the table's rows bring their own newlines.
  CHECK(ReportTemplate("proofs").set("rows", "| r |\n").render().substr(0, 31) == "## Proofs (exact, by identity)\n");
  const auto p = ReportTemplate("proofs").set("rows", "| r |\n").render();
  CHECK(p.substr(p.size() - 7) == "\n| r |\n");
}

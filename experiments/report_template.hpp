// The report's prose as Markdown templates (issue 48 item 9): report.md's sentences live in
// experiments/report/<name>.md, embedded at build time (experiments/embed_templates.cmake), and a
// section fills their placeholders with what it measured. The C++ keeps the numbers and the tables
// built from data; the words are in the templates, where they can be read and edited as text.
//
// A template is the file's text with its one final newline dropped (so an editor that ends files
// with a newline changes nothing); a template whose text ends a line ends with an empty line.
// Line ends are LF (.gitattributes); a carriage return, or a line ending in a space (which an
// editor trimming whitespace would change), is refused.
// The syntax, all of it:
//   {{name}}                       the value set by set("name", ...)
//   {{?name}} A {{:name}} B {{/name}}  A where when("name", true), else B (the {{:name}} part may be
//                                  left out); blocks nest
// A name is letters, digits and . _ : -. Every placeholder must be filled and every value set must
// be used: render() throws std::logic_error otherwise (a sentence silently left out or a number
// computed for nothing is a bug of the section, found by the first run of the section's test).
// A reference to another section is a condition on it having run: when("ran:NAME", ctx.ran("NAME")).
#pragma once
#include <cstddef>
#include <map>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace splinex {

class ReportTemplate {
 public:
  /// The template experiments/report/<name>.md; std::logic_error naming the known ones if absent.
  explicit ReportTemplate(std::string_view name);
  /// A template from the given text, copied (the tests' own templates; the report uses the files).
  static ReportTemplate from_text(std::string name, std::string text);

  ReportTemplate& set(const std::string& key, std::string value);
  ReportTemplate& set(const std::string& key, const char* value) { return set(key, std::string(value)); }
  /// Integers as decimal text. A double must be formatted by the caller (fmt, to the precision
  /// the sentence means), so there is no overload for it.
  template <class I, std::enable_if_t<std::is_integral_v<I> && !std::is_same_v<I, bool> && !std::is_same_v<I, char>, int> = 0>
  ReportTemplate& set(const std::string& key, I value) {
    return set(key, std::to_string(value));
  }
  template <class F, std::enable_if_t<std::is_floating_point_v<F>, int> = 0>
  ReportTemplate& set(const std::string& key, F value) = delete;
  ReportTemplate& when(const std::string& key, bool flag);

  /// The text with every placeholder filled; std::logic_error on a placeholder without a value, a
  /// value or condition the template does not use, or unbalanced blocks.
  std::string render() const;

  const std::string& name() const { return name_; }

 private:
  ReportTemplate() = default;
  std::string name_;
  std::string text_;
  std::map<std::string, std::string> values_;
  std::map<std::string, bool> flags_;
};

/// Shorthand for a template with values only: render_template("vrep.intro", {{"n", "3"}}).
std::string render_template(std::string_view name, const std::map<std::string, std::string>& values);

/// The names of every embedded template, sorted (for the test that renders each one's syntax).
std::vector<std::string> report_template_names();
/// The placeholders and conditions a template uses (sorted, each once): "name" and "?name".
std::vector<std::string> report_template_fields(std::string_view name);

}  // namespace splinex

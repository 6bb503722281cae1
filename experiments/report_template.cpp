// The renderer of experiments/report_template.hpp; the texts come from the generated
// report_templates.cpp (experiments/embed_templates.cmake).
#include "experiments/report_template.hpp"

#include <algorithm>
#include <set>
#include <stdexcept>
#include <utility>

namespace splinex {

namespace report_templates {
struct Entry {
  const char* name;
  const char* text;
  std::size_t size;
};
// Generated at build time, sorted by name.
extern const Entry kEntries[];
extern const std::size_t kCount;
}  // namespace report_templates

namespace {

const report_templates::Entry* find_template(std::string_view name) {
  const auto* end = report_templates::kEntries + report_templates::kCount;
  const auto* it = std::find_if(report_templates::kEntries, end, [&](const auto& e) { return name == e.name; });
  return it == end ? nullptr : it;
}

// The file's text without its one final newline (report_template.hpp).
std::string_view text_of(const report_templates::Entry& e) {
  std::string_view t(e.text, e.size);
  if (!t.empty() && t.back() == '\n') t.remove_suffix(1);
  return t;
}

[[noreturn]] void fail(const std::string& name, const std::string& what) {
  throw std::logic_error("report template " + name + ".md: " + what);
}

bool name_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' || c == '_' || c == ':' ||
         c == '-';
}

// One placeholder: its kind ('=' value, '?' open, ':' else, '/' close), its name, where it ends.
struct Tag {
  char kind;
  std::string key;
  std::size_t begin, end;
};

std::vector<Tag> parse(const std::string& name, std::string_view t) {
  if (const auto cr = t.find('\r'); cr != std::string_view::npos)
    fail(name, "a carriage return at byte " + std::to_string(cr) + " (the templates' line ends are LF, .gitattributes)");
  if (const auto sp = t.find(" \n"); sp != std::string_view::npos)
    fail(name, "a line ends in a space at byte " + std::to_string(sp) + " (an editor trimming whitespace would change report.md: put it in the C++)");
  std::vector<Tag> tags;
  for (std::size_t pos = t.find("{{"); pos != std::string_view::npos; pos = t.find("{{", pos)) {
    const auto close = t.find("}}", pos + 2);
    if (close == std::string_view::npos) fail(name, "'{{' at byte " + std::to_string(pos) + " is never closed");
    std::string_view inner = t.substr(pos + 2, close - pos - 2);
    char kind = '=';
    if (!inner.empty() && (inner[0] == '?' || inner[0] == ':' || inner[0] == '/')) {
      kind = inner[0];
      inner.remove_prefix(1);
    }
    if (inner.empty() || !std::all_of(inner.begin(), inner.end(), name_char))
      fail(name, "'{{" + std::string(t.substr(pos + 2, close - pos - 2)) + "}}' is not a placeholder (names are letters, digits, . _ : -)");
    tags.push_back({kind, std::string(inner), pos, close + 2});
    pos = close + 2;
  }
  // Blocks balanced and nested; an else only inside its own block, at most once.
  std::vector<std::pair<std::string, bool>> open;
  for (const auto& g : tags) {
    if (g.kind == '?') open.emplace_back(g.key, false);
    if (g.kind == ':') {
      if (open.empty() || open.back().first != g.key || open.back().second) fail(name, "'{{:" + g.key + "}}' outside its block");
      open.back().second = true;
    }
    if (g.kind == '/') {
      if (open.empty()) fail(name, "'{{/" + g.key + "}}' closes no open block");
      if (open.back().first != g.key) fail(name, "'{{/" + g.key + "}}' while '{{?" + open.back().first + "}}' is still open");
      open.pop_back();
    }
  }
  if (!open.empty()) fail(name, "'{{?" + open.back().first + "}}' is never closed");
  return tags;
}

}  // namespace

ReportTemplate::ReportTemplate(std::string_view name) : name_(name) {
  const auto* e = find_template(name);
  if (!e) {
    std::string known;
    for (const auto& n : report_template_names()) known += (known.empty() ? "" : ", ") + n;
    throw std::logic_error("report template '" + name_ + "' does not exist (experiments/report/ has " + known + ")");
  }
  text_ = std::string(text_of(*e));
}

ReportTemplate ReportTemplate::from_text(std::string name, std::string text) {
  ReportTemplate t;
  t.name_ = std::move(name);
  t.text_ = std::move(text);
  parse(t.name_, t.text_);
  return t;
}

ReportTemplate& ReportTemplate::set(const std::string& key, std::string value) {
  values_[key] = std::move(value);
  return *this;
}

ReportTemplate& ReportTemplate::when(const std::string& key, bool flag) {
  flags_[key] = flag;
  return *this;
}

std::string ReportTemplate::render() const {
  const auto tags = parse(name_, text_);
  std::set<std::string> used_values, used_flags;
  std::string out;
  // Per open block (and the whole text at the bottom): whether its text is written.
  std::vector<bool> writing{true};
  std::size_t at = 0;
  for (const auto& g : tags) {
    if (writing.back()) out.append(text_.substr(at, g.begin - at));
    at = g.end;
    if (g.kind == '=') {
      const auto it = values_.find(g.key);
      if (it == values_.end()) fail(name_, "{{" + g.key + "}} has no value (set it, or remove it from the template)");
      used_values.insert(g.key);
      if (writing.back()) out += it->second;
    } else {
      const auto it = flags_.find(g.key);
      if (it == flags_.end()) fail(name_, "{{?" + g.key + "}} has no condition (call when(\"" + g.key + "\", ...))");
      used_flags.insert(g.key);
      if (g.kind == '?') writing.push_back(writing.back() && it->second);
      if (g.kind == ':') writing.back() = writing[writing.size() - 2] && !it->second;
      if (g.kind == '/') writing.pop_back();
    }
  }
  out.append(text_.substr(at));
  for (const auto& [k, v] : values_)
    if (!used_values.count(k)) fail(name_, "the value '" + k + "' is set but the template has no {{" + k + "}}");
  for (const auto& [k, v] : flags_)
    if (!used_flags.count(k)) fail(name_, "the condition '" + k + "' is set but the template has no {{?" + k + "}}");
  return out;
}

std::string render_template(std::string_view name, const std::map<std::string, std::string>& values) {
  ReportTemplate t(name);
  for (const auto& [k, v] : values) t.set(k, v);
  return t.render();
}

std::vector<std::string> report_template_names() {
  std::vector<std::string> names;
  for (std::size_t k = 0; k < report_templates::kCount; ++k) names.emplace_back(report_templates::kEntries[k].name);
  return names;
}

std::vector<std::string> report_template_fields(std::string_view name) {
  const auto* e = find_template(name);
  if (!e) throw std::logic_error("report template '" + std::string(name) + "' does not exist");
  std::set<std::string> fields;
  for (const auto& g : parse(std::string(name), text_of(*e)))
    fields.insert(g.kind == '=' ? g.key : "?" + g.key);
  return {fields.begin(), fields.end()};
}

}  // namespace splinex

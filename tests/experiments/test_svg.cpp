// The figures' SVG writer (experiments/svg.hpp): escaping, the text-width estimate, wrapping, and
// the canvas's promise that titles and captions fit: the produced document is parsed back here and
// every text element's estimated extent is checked against the canvas width (a planted document
// with an overflowing title shows that the check can fail).
#include <catch2/catch.hpp>

#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "experiments/svg.hpp"
#include "experiments/svg_plot.hpp"

using namespace splinex;

namespace {

std::vector<std::string> words(const std::string& s) {
  std::istringstream in(s);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

std::string unescape(std::string s) {
  for (const auto& [e, c] : std::vector<std::pair<std::string, std::string>>{{"&lt;", "<"}, {"&gt;", ">"}, {"&quot;", "\""}, {"&apos;", "'"}, {"&amp;", "&"}})
    for (std::size_t i = s.find(e); i != std::string::npos; i = s.find(e, i + c.size())) s.replace(i, e.size(), c);
  return s;
}

double attribute(const std::string& attrs, const std::string& name, double otherwise) {
  std::smatch m;
  return std::regex_search(attrs, m, std::regex("(^|\\s)" + name + "=\"([-0-9.e+]+)\"")) ? std::stod(m[2]) : otherwise;
}

struct TextElement {
  double left, right;  // the estimated extent in x
  std::string content;
};

// Every <text> of the document with its estimated horizontal extent (by svg::text_width).
std::vector<TextElement> texts(const std::string& doc) {
  std::vector<TextElement> out;
  const std::regex text("<text([^>]*)>([^<]*)</text>");
  for (auto it = std::sregex_iterator(doc.begin(), doc.end(), text); it != std::sregex_iterator(); ++it) {
    const std::string attrs = (*it)[1], content = unescape((*it)[2]);
    if (attrs.find("transform=") != std::string::npos) continue;  // rotated (an axis label): its extent is vertical
    const double x = attribute(attrs, "x", 0), w = svg::text_width(content, attribute(attrs, "font-size", 12));
    const double left = attrs.find("text-anchor=\"middle\"") != std::string::npos ? x - w / 2
                        : attrs.find("text-anchor=\"end\"") != std::string::npos  ? x - w
                                                                                  : x;
    out.push_back({left, left + w, content});
  }
  return out;
}

// The texts whose estimated extent passes an edge of [0, width].
std::vector<std::string> overflowing(const std::string& doc, double width) {
  std::vector<std::string> bad;
  for (const auto& t : texts(doc))
    if (t.left < 0 || t.right > width) bad.push_back(t.content);
  return bad;
}

double document_height(const std::string& doc) { return attribute(doc, "height", 0); }

const std::string kLong = "Teapot handle and body: the intersection branches in both parameter planes (step 1/16) & more <text>";

}  // namespace

TEST_CASE("svg escape turns the five XML specials into entities") {
  CHECK(svg::escape("a<b & \"c\" 'd' >") == "a&lt;b &amp; &quot;c&quot; &apos;d&apos; &gt;");
  CHECK(svg::escape("plain text, 1/16") == "plain text, 1/16");
  // Control characters XML 1.0 cannot hold are left out (a document with one would not parse).
  CHECK(svg::escape(std::string("a\x01" "b\x1f" "\tc")) == "ab\tc");
  CHECK(unescape(svg::escape(kLong)) == kLong);
}

TEST_CASE("svg text_width grows with the text and the font, wide for non-ASCII") {
  CHECK(svg::text_width("", 12) == 0);
  CHECK(svg::text_width("W", 12) > svg::text_width("i", 12));
  CHECK(svg::text_width("abc", 24) == Approx(2 * svg::text_width("abc", 12)));
  CHECK(svg::text_width("\xc3\xa9", 10) == Approx(10));  // one code point beyond ASCII: 1 em
  // Conservative: at least Helvetica's and DejaVu Sans's advance for "m" (833 and 974 in 1/1000 em).
  CHECK(svg::text_width("m", 1000) >= 974);
}

TEST_CASE("svg wrap keeps every line within the width and loses no word") {
  // A wrap that ignored the width (one line of the whole text) fails the first CHECK below, and
  // in the canvas test below the taller-canvas and overflow CHECKs (tried with that bug planted in a
  // copy of svg.cpp: those three failed); a wrap that dropped or reordered words fails the second.
  for (double width : {40.0, 120.0, 260.0, 500.0}) {
    const auto lines = svg::wrap(kLong, width, 13);
    std::string joined;
    for (const auto& l : lines) {
      CHECK((svg::text_width(l, 13) <= width || words(l).size() == 1));
      joined += (joined.empty() ? "" : " ") + l;
    }
    CHECK(words(joined) == words(kLong));
  }
  CHECK(svg::wrap("", 100, 12).empty());
  CHECK(svg::wrap("   ", 100, 12).empty());
  const auto lone = svg::wrap("a supercalifragilisticexpialidocious word", 60, 12);
  CHECK(lone == std::vector<std::string>{"a", "supercalifragilisticexpialidocious", "word"});
}

TEST_CASE("svg canvas: a long title makes the canvas taller and every text stays inside") {
  const double W = 300, H = 200;
  svg::Canvas plain(W, H);
  plain.title("short");
  svg::Canvas tall(W, H);
  tall.title(kLong);
  tall.caption(kLong + " " + kLong);
  tall.text(W - 5, 50, "end-anchored", 12, svg::Anchor::end);
  tall.text(W / 2, 80, "centred", 12, svg::Anchor::middle);
  const std::string a = plain.str(), b = tall.str();
  CHECK(document_height(b) > document_height(a) + 2 * 14);
  CHECK(b.find("viewBox=\"0 0 300 " + svg::num(document_height(b)) + "\"") != std::string::npos);
  CHECK(b.find("font-family=\"sans-serif\"") != std::string::npos);
  CHECK(b.find("&lt;text&gt;") != std::string::npos);  // text is escaped
  CHECK(overflowing(b, W).empty());
  // Every word of the title and the caption is drawn.
  std::string drawn;
  for (const auto& t : texts(b)) drawn += t.content + " ";
  for (const auto& w : words(kLong)) CHECK(drawn.find(w) != std::string::npos);
  // The drawing starts below the title band: the group's shift is past the last title baseline.
  std::smatch m;
  REQUIRE(std::regex_search(b, m, std::regex("translate\\(0,([-0-9.e+]+)\\)")));
  const auto title_lines = svg::wrap(kLong, W - 20, 14).size();
  CHECK(std::stod(m[1]) >= 1.25 * 14 * static_cast<double>(title_lines));
  CHECK(b.size() > 6);
  CHECK(b.substr(b.size() - 7) == "</svg>\n");
}

TEST_CASE("svg canvas: panel titles wrap to their own panels and do not overlap") {
  svg::Canvas c(840, 390);
  c.panel_title(30, 380, "(a) Algorithm 1: trimmed patches, texture by S's parameters (Definition 1 holds)");
  c.panel_title(450, 380, "(b) Algorithm 2: 10 tensor-product tiles, texture by each tile's parameters");
  const auto t = texts(c.str());
  REQUIRE(t.size() >= 4);  // each title needs two lines at 380 px
  for (const auto& e : t) {
    const bool first = e.left < 450;
    CHECK(e.left >= (first ? 30 : 450));
    CHECK(e.right <= (first ? 410 : 830));
  }
}

TEST_CASE("svg overflow check refuses a planted title that runs past the edge") {
  // What the emitters wrote before the canvas: an 89-character title centred at x = 260 in 15 px
  // type on a 720 px figure (it ran past the left edge). The parser must see it.
  const std::string planted = "<text x=\"260\" y=\"22\" text-anchor=\"middle\" font-size=\"15\">" + svg::escape(kLong) + "</text>";
  CHECK(overflowing(planted, 720) == std::vector<std::string>{kLong});
  svg::Canvas c(720, 400);
  c.title(kLong, 15);
  CHECK(overflowing(c.str(), 720).empty());
}

TEST_CASE("svg line plot: a long title and long legend labels stay inside the figure") {
  // The titles that ran past the left edge before (74 and 89 characters, centred at x = 260 in 15 px type).
  const PlotSpec spec{"Union of two overlapping boxes in double: volume counted twice against eps", "eps",
                      "sum of cell volumes - true volume (exact; 1e-20 drawn for 0)", true, true,
                      "Trimming curves of the teapot from a float SSI: exact distance from the true intersection"};
  std::vector<PlotSeries> series;
  for (int k = 0; k < 3; ++k)
    series.push_back({"control points, mpfr:113 (m = " + std::to_string(k) + "), a long legend label", {{1e-6, 1e-3}, {1e-3, 1e-9}}, svg::palette(k)});
  const std::string doc = svg_line_plot(spec, series);
  CHECK(doc.find("viewBox=\"0 0 720 ") != std::string::npos);
  CHECK(overflowing(doc, 720).empty());
  std::string drawn;
  for (const auto& t : texts(doc)) drawn += t.content + " ";
  for (const auto& w : words(spec.title + " " + spec.note + " " + series[0].label)) CHECK(drawn.find(w) != std::string::npos);
}

TEST_CASE("svg palette cycles the Tableau colours and numbers are deterministic") {
  CHECK(svg::palette(0) == "#1f77b4");
  CHECK(svg::palette(1) == "#d62728");
  CHECK(svg::palette(20) == svg::palette(0));
  CHECK(svg::palette(10) == svg::palette_light(0));
  CHECK(svg::num(1.0 / 3) == "0.333333");
  CHECK(svg::num(-0.0) == "0");
  CHECK(svg::rgb({1, 2, 3}) == "rgb(1,2,3)");
}

// The one SVG writer of the report's figures (see svg.hpp). The only file that opens an SVG
// document: scripts/check_layering.py (ctest "layering") refuses the element's opening tag anywhere else.
#include "experiments/svg.hpp"

#include <algorithm>
#include <cstdio>

namespace splinex::svg {

namespace {

// Advance widths of ASCII 32..126 in 1/1000 em: Helvetica (Adobe's AFM) and DejaVu Sans (what
// fontconfig answers for sans-serif on most Linux systems, wider than Helvetica in most letters).
constexpr int kHelvetica[95] = {
    278, 278, 355, 556, 556, 889, 667, 191, 333, 333, 389, 584, 278, 333, 278, 278,            // space ! " # $ % & ' ( ) * + , - . /
    556, 556, 556, 556, 556, 556, 556, 556, 556, 556, 278, 278, 584, 584, 584, 556, 1015,      // 0-9 : ; < = > ? @
    667, 667, 722, 722, 667, 611, 778, 722, 278, 500, 667, 556, 833, 722, 778, 667, 778, 722,  // A-R
    667, 611, 722, 667, 944, 667, 667, 611, 278, 278, 278, 469, 556, 333,                      // S-Z [ \ ] ^ _ `
    556, 556, 500, 556, 556, 278, 556, 556, 222, 222, 500, 222, 833, 556, 556, 556, 556, 333,  // a-r
    500, 278, 556, 500, 722, 500, 500, 500, 334, 260, 334, 584};                               // s-z { | } ~
constexpr int kDejaVuSans[95] = {
    318, 401, 460, 838, 636, 950, 780, 275, 390, 390, 500, 838, 318, 361, 318, 337,
    636, 636, 636, 636, 636, 636, 636, 636, 636, 636, 337, 337, 838, 838, 838, 531, 1000,
    684, 686, 698, 770, 632, 575, 775, 752, 295, 295, 656, 557, 863, 748, 787, 603, 787, 695,
    635, 611, 732, 684, 989, 685, 611, 685, 390, 337, 390, 838, 500, 500,
    613, 635, 550, 635, 615, 352, 635, 634, 278, 278, 579, 278, 974, 634, 612, 635, 635, 411,
    521, 392, 634, 592, 818, 592, 592, 525, 636, 337, 636, 838};
constexpr int kWide = 1000;  // a character beyond ASCII: 1 em

// Tableau 10 and the light colours of Tableau 20, in the order the figures have always used.
constexpr std::array<int, 3> kColours[20] = {
    {31, 119, 180},  {214, 39, 40},   {44, 160, 44},   {148, 103, 189}, {255, 127, 14},
    {140, 86, 75},   {23, 190, 207},  {188, 189, 34},  {227, 119, 194}, {127, 127, 127},
    {174, 199, 232}, {255, 152, 150}, {152, 223, 138}, {197, 176, 213}, {255, 187, 120},
    {196, 156, 148}, {158, 218, 229}, {219, 219, 141}, {247, 182, 210}, {199, 199, 199}};

std::string hex(const std::array<int, 3>& c) {
  char b[8];
  std::snprintf(b, sizeof b, "#%02x%02x%02x", c[0], c[1], c[2]);
  return b;
}

const char* anchor_name(Anchor a) { return a == Anchor::start ? "start" : a == Anchor::middle ? "middle" : "end"; }

constexpr double kPad = 10;        // left and right margin of the bands
constexpr double kLineHeight = 1.25;  // in em

double band_height(const std::vector<std::string>& lines, double font_px) {
  return static_cast<double>(lines.size()) * kLineHeight * font_px;
}

}  // namespace

std::string escape(const std::string& text) {
  std::string o;
  o.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': o += "&amp;"; break;
      case '<': o += "&lt;"; break;
      case '>': o += "&gt;"; break;
      case '"': o += "&quot;"; break;
      case '\'': o += "&apos;"; break;
      default:
        // XML 1.0 has no other control characters than tab, line feed and carriage return.
        if (static_cast<unsigned char>(c) >= 0x20 || c == '\t' || c == '\n' || c == '\r') o += c;
    }
  }
  return o;
}

double text_width(const std::string& text, double font_px) {
  long units = 0;
  for (unsigned char c : text) {
    if (c >= 32 && c <= 126) units += std::max(kHelvetica[c - 32], kDejaVuSans[c - 32]);
    else if (c >= 0xC0) units += kWide;  // the lead byte of a UTF-8 sequence (continuation bytes add nothing)
    else if (c >= 0x80 && c < 0xC0) continue;
    else if (c == '\t') units += 4 * kDejaVuSans[0];
  }
  return static_cast<double>(units) * font_px / 1000.0;
}

std::vector<std::string> wrap(const std::string& text, double max_width, double font_px) {
  std::vector<std::string> lines;
  std::string current;
  std::size_t i = 0;
  while (i < text.size()) {
    if (text[i] == ' ') { ++i; continue; }
    const std::size_t j = std::min(text.find(' ', i), text.size());
    const std::string word = text.substr(i, j - i);
    i = j;
    if (current.empty()) current = word;
    else if (text_width(current + " " + word, font_px) <= max_width) current += " " + word;
    else {
      lines.push_back(current);
      current = word;
    }
  }
  if (!current.empty()) lines.push_back(current);
  return lines;
}

std::string num(double v, int digits) {
  if (v == 0) v = 0;  // no "-0"
  char b[40];
  std::snprintf(b, sizeof b, "%.*g", digits, v);
  return b;
}

std::array<int, 3> palette_rgb(std::size_t k) { return kColours[k % 20]; }
std::string palette(std::size_t k) { return hex(palette_rgb(k)); }
std::string palette_light(std::size_t k) { return hex(kColours[10 + k % 10]); }
std::string rgb(const std::array<int, 3>& c) {
  return "rgb(" + std::to_string(c[0]) + "," + std::to_string(c[1]) + "," + std::to_string(c[2]) + ")";
}

std::string attr(const std::string& name, const std::string& value) { return " " + name + "=\"" + escape(value) + "\""; }
std::string attr(const std::string& name, double value) { return " " + name + "=\"" + num(value) + "\""; }

Canvas::Canvas(double width, double height, int digits) : width_(width), height_(height), digits_(digits) {}

void Canvas::title(const std::string& text, double font_px) {
  title_.push_back({kPad, width_ - 2 * kPad, font_px, wrap(text, width_ - 2 * kPad, font_px)});
}

void Canvas::caption(const std::string& text, double font_px) {
  caption_.push_back({kPad, width_ - 2 * kPad, font_px, wrap(text, width_ - 2 * kPad, font_px)});
}

void Canvas::panel_title(double x, double width, const std::string& text, double font_px) {
  panels_.push_back({x, width, font_px, wrap(text, width, font_px)});
}

std::string Canvas::points(const Points& pts) const {
  std::string s;
  for (const auto& [x, y] : pts) s += n(x) + "," + n(y) + " ";
  if (!s.empty()) s.pop_back();
  return s;
}

void Canvas::rect(double x, double y, double w, double h, const std::string& attrs) {
  body_ << "<rect x=\"" << n(x) << "\" y=\"" << n(y) << "\" width=\"" << n(w) << "\" height=\"" << n(h) << "\"" << attrs << "/>\n";
}

void Canvas::line(double x1, double y1, double x2, double y2, const std::string& attrs) {
  body_ << "<line x1=\"" << n(x1) << "\" y1=\"" << n(y1) << "\" x2=\"" << n(x2) << "\" y2=\"" << n(y2) << "\"" << attrs << "/>\n";
}

void Canvas::polyline(const Points& pts, const std::string& attrs) {
  body_ << "<polyline points=\"" << points(pts) << "\"" << (attrs.find(" fill=") == std::string::npos ? " fill=\"none\"" : "") << attrs << "/>\n";
}

void Canvas::polygon(const Points& pts, const std::string& attrs) { body_ << "<polygon points=\"" << points(pts) << "\"" << attrs << "/>\n"; }

void Canvas::circle(double cx, double cy, double r, const std::string& attrs) {
  body_ << "<circle cx=\"" << n(cx) << "\" cy=\"" << n(cy) << "\" r=\"" << n(r) << "\"" << attrs << "/>\n";
}

void Canvas::path(const std::string& d, const std::string& attrs) {
  body_ << "<path d=\"" << d << "\"" << (attrs.find(" fill=") == std::string::npos ? " fill=\"none\"" : "") << attrs << "/>\n";
}

void Canvas::text(double x, double y, const std::string& content, double font_px, Anchor anchor, const std::string& attrs) {
  body_ << "<text x=\"" << n(x) << "\" y=\"" << n(y) << "\" font-size=\"" << n(font_px) << "\"";
  if (anchor != Anchor::start) body_ << " text-anchor=\"" << anchor_name(anchor) << "\"";
  body_ << attrs << ">" << escape(content) << "</text>\n";
}

std::size_t Canvas::text_block(double x, double y, const std::string& content, double max_width, double font_px, const std::string& attrs) {
  const auto lines = wrap(content, max_width, font_px);
  for (std::size_t i = 0; i < lines.size(); ++i) text(x, y + static_cast<double>(i) * kLineHeight * font_px, lines[i], font_px, Anchor::start, attrs);
  return lines.size();
}

void Canvas::open_group(const std::string& attrs) {
  body_ << "<g" << attrs << ">\n";
  ++open_groups_;
}

void Canvas::close_group() {
  if (open_groups_ == 0) return;
  body_ << "</g>\n";
  --open_groups_;
}

std::string Canvas::move_to(double x, double y) const {
  std::string s = "M";
  return s.append(n(x)).append(" ").append(n(y));
}
std::string Canvas::line_to(double x, double y) const {
  std::string s = "L";
  return s.append(n(x)).append(" ").append(n(y));
}

double Canvas::title_height() const {
  double h = 0, panels = 0;
  for (const auto& b : title_) h += band_height(b.lines, b.font_px);
  for (const auto& b : panels_) panels = std::max(panels, band_height(b.lines, b.font_px));
  h += panels;
  return h > 0 ? h + 10 : 0;  // 6 px above the first line, 4 px below the last
}

std::string Canvas::str() const {
  const double top = title_height();
  double bottom = 0;
  for (const auto& b : caption_) bottom += band_height(b.lines, b.font_px);
  if (bottom > 0) bottom += 10;
  const double total = top + height_ + bottom;
  std::ostringstream o;
  o << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << n(width_) << "\" height=\"" << n(total) << "\" viewBox=\"0 0 " << n(width_) << " "
    << n(total) << "\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  // A line's baseline sits 0.95 em below the top of its 1.25 em line box (descenders fit below).
  auto band = [&](const Band& b, double y, const char* fill) {
    for (const auto& l : b.lines) {
      o << "<text x=\"" << n(b.x) << "\" y=\"" << n(y + 0.95 * b.font_px) << "\" font-size=\"" << n(b.font_px) << "\"" << fill << ">" << escape(l)
        << "</text>\n";
      y += kLineHeight * b.font_px;
    }
    return y;
  };
  double y = 6;
  for (const auto& b : title_) y = band(b, y, "");
  for (const auto& b : panels_) band(b, y, "");
  o << "<g transform=\"translate(0," << n(top) << ")\">\n" << body_.str();
  for (int i = 0; i < open_groups_; ++i) o << "</g>\n";
  o << "</g>\n";
  y = top + height_ + 6;
  for (const auto& b : caption_) y = band(b, y, " fill=\"#333\"");
  o << "</svg>\n";
  return o.str();
}

}  // namespace splinex::svg

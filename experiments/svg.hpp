// The one SVG writer of the report's figures: escaping, a conservative text-width estimate, word
// wrapping, one categorical palette, and a Canvas every figure is drawn on. The canvas always has
// a viewBox and sans-serif type; its title band (top) and caption band (bottom) hold text wrapped
// to the canvas width and grow with the lines, so titles never run past the edges; the drawing sits
// between them in its own coordinates (0..width x 0..height). Numbers are written with a fixed
// precision, so a figure's bytes depend only on its data.
#pragma once
#include <array>
#include <cstddef>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace splinex::svg {

/// Text for XML content and attribute values: & < > " ' as entities; control characters XML cannot
/// hold (all below 0x20 but tab, line feed, carriage return) left out.
std::string escape(const std::string& text);

/// An upper estimate of the width in px of `text` in a sans-serif font of `font_px`: per character
/// the larger of the Helvetica (AFM) and DejaVu Sans advance widths; 1 em for anything beyond ASCII.
double text_width(const std::string& text, double font_px);

/// `text` broken at spaces into lines whose text_width is at most max_width; a word wider than
/// max_width on its own gets a line of its own (it is never cut). No word is lost or reordered.
std::vector<std::string> wrap(const std::string& text, double max_width, double font_px);

/// A number as the figures write it: %.6g (deterministic, short).
std::string num(double v, int digits = 6);

/// The categorical colours (Tableau 10, then their light partners of Tableau 20), cycling.
std::string palette(std::size_t k);
std::array<int, 3> palette_rgb(std::size_t k);
/// The light partner of palette(k) (fills under dark text).
std::string palette_light(std::size_t k);
/// "rgb(r,g,b)".
std::string rgb(const std::array<int, 3>& c);

enum class Anchor { start, middle, end };

using Points = std::vector<std::pair<double, double>>;

class Canvas {
 public:
  /// A canvas whose drawing area is width x height px; the bands are added above and below it.
  Canvas(double width, double height, int digits = 6);

  /// The title (wrapped to the canvas width, 14 px) and the caption (wrapped, 11 px, grey).
  void title(const std::string& text, double font_px = 14);
  void caption(const std::string& text, double font_px = 11);
  /// A panel's own title in the title band, wrapped to the panel's columns [x, x + width].
  void panel_title(double x, double width, const std::string& text, double font_px = 13);

  // Primitives in drawing coordinates; `attrs` are further attributes written as given
  // (fill, stroke, ...: build them with attr()).
  void rect(double x, double y, double w, double h, const std::string& attrs);
  void line(double x1, double y1, double x2, double y2, const std::string& attrs);
  void polyline(const Points& pts, const std::string& attrs);
  void polygon(const Points& pts, const std::string& attrs);
  void circle(double cx, double cy, double r, const std::string& attrs);
  void path(const std::string& d, const std::string& attrs);
  /// One line of text, escaped.
  void text(double x, double y, const std::string& content, double font_px = 12, Anchor anchor = Anchor::start,
            const std::string& attrs = "");
  /// Text wrapped to max_width from (x, y) down (line height 1.25 em); returns the number of lines.
  std::size_t text_block(double x, double y, const std::string& content, double max_width, double font_px = 12,
                         const std::string& attrs = "");
  void open_group(const std::string& attrs);
  void close_group();

  /// The path data helpers: "M x y" and "L x y" with the canvas's precision.
  std::string move_to(double x, double y) const;
  std::string line_to(double x, double y) const;
  std::string n(double v) const { return num(v, digits_); }

  /// The drawing's height when it is known only after drawing (text blocks below panels).
  void set_height(double height) { height_ = height; }
  double width() const { return width_; }
  double height() const { return height_; }
  /// The whole document.
  std::string str() const;

 private:
  struct Band {
    double x, width, font_px;
    std::vector<std::string> lines;
  };
  std::string points(const Points& pts) const;
  double title_height() const;

  double width_, height_;
  int digits_;
  std::vector<Band> title_, panels_, caption_;
  std::ostringstream body_;
  int open_groups_ = 0;
};

/// A string of attributes: attr("fill", "none") + attr("stroke-width", 2).
std::string attr(const std::string& name, const std::string& value);
std::string attr(const std::string& name, double value);

}  // namespace splinex::svg

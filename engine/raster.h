// A small RGB raster for plots: pixels, anti-aliased lines of a given width, rectangles and
// text in the 5×7 bitmap font scaled by an integer factor; written as PNG with libpng.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace scenario {

struct Rgb {
  std::uint8_t r = 0, g = 0, b = 0;
};

class Raster {
 public:
  Raster(int width, int height, Rgb background);
  int width() const { return width_; }
  int height() const { return height_; }

  /// Blends `c` into the pixel with coverage `alpha` in [0, 1]; outside the clip: nothing.
  void blend(int x, int y, Rgb c, double alpha = 1.0);
  void fill_rect(int x0, int y0, int x1, int y1, Rgb c);
  /// A line of width `w` pixels from (x0, y0) to (x1, y1), anti-aliased.
  void line(double x0, double y0, double x1, double y1, Rgb c, double w = 1.0);
  /// Text with its top-left corner at (x, y); `scale` multiplies the 5×7 glyphs.
  void text(int x, int y, std::string_view s, Rgb c, int scale = 2);
  /// Text turned 90° counter-clockwise (reads bottom to top), top-left corner at (x, y).
  void text_vertical(int x, int y, std::string_view s, Rgb c, int scale = 2);
  static int text_width(std::string_view s, int scale = 2) { return static_cast<int>(s.size()) * 6 * scale - scale; }
  static int text_height(int scale = 2) { return 7 * scale; }

  /// Restricts drawing to a rectangle (inclusive); reset with clip_none().
  void clip(int x0, int y0, int x1, int y1);
  void clip_none() { clip(0, 0, width_ - 1, height_ - 1); }

  /// Writes the raster as an 8-bit RGB PNG; returns an error message, empty on success.
  std::string write_png(const std::string& path) const;

 private:
  int width_, height_;
  int cx0_, cy0_, cx1_, cy1_;
  std::vector<std::uint8_t> pixels_;
};

}  // namespace scenario

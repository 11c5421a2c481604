#include "engine/raster.h"

#include <png.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "engine/bitmap_font.h"

namespace scenario {

Raster::Raster(int width, int height, Rgb background)
    : width_(width), height_(height), pixels_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3) {
  clip_none();
  for (std::size_t i = 0; i < pixels_.size(); i += 3) {
    pixels_[i] = background.r;
    pixels_[i + 1] = background.g;
    pixels_[i + 2] = background.b;
  }
}

void Raster::clip(int x0, int y0, int x1, int y1) {
  cx0_ = std::max(0, x0);
  cy0_ = std::max(0, y0);
  cx1_ = std::min(width_ - 1, x1);
  cy1_ = std::min(height_ - 1, y1);
}

void Raster::blend(int x, int y, Rgb c, double alpha) {
  if (x < cx0_ || x > cx1_ || y < cy0_ || y > cy1_ || alpha <= 0) return;
  alpha = std::min(alpha, 1.0);
  auto* p = &pixels_[(static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x)) * 3];
  const auto mix = [alpha](std::uint8_t dst, std::uint8_t src) {
    return static_cast<std::uint8_t>(std::lround(dst + (src - dst) * alpha));
  };
  p[0] = mix(p[0], c.r);
  p[1] = mix(p[1], c.g);
  p[2] = mix(p[2], c.b);
}

void Raster::fill_rect(int x0, int y0, int x1, int y1, Rgb c) {
  for (int y = std::min(y0, y1); y <= std::max(y0, y1); ++y)
    for (int x = std::min(x0, x1); x <= std::max(x0, x1); ++x) blend(x, y, c);
}

void Raster::line(double x0, double y0, double x1, double y1, Rgb c, double w) {
  if (!std::isfinite(x0) || !std::isfinite(y0) || !std::isfinite(x1) || !std::isfinite(y1)) return;
  // Coverage of each pixel centre by a capsule of radius w/2 around the segment.
  const double r = w / 2.0;
  const int xa = static_cast<int>(std::floor(std::min(x0, x1) - r - 1)), xb = static_cast<int>(std::ceil(std::max(x0, x1) + r + 1));
  const int ya = static_cast<int>(std::floor(std::min(y0, y1) - r - 1)), yb = static_cast<int>(std::ceil(std::max(y0, y1) + r + 1));
  const double dx = x1 - x0, dy = y1 - y0;
  const double len2 = dx * dx + dy * dy;
  for (int y = std::max(ya, cy0_); y <= std::min(yb, cy1_); ++y) {
    for (int x = std::max(xa, cx0_); x <= std::min(xb, cx1_); ++x) {
      const double px = x + 0.5 - x0, py = y + 0.5 - y0;
      const double t = len2 > 0 ? std::clamp((px * dx + py * dy) / len2, 0.0, 1.0) : 0.0;
      const double ex = px - t * dx, ey = py - t * dy;
      const double d = std::sqrt(ex * ex + ey * ey);
      const double cover = std::clamp(r + 0.5 - d, 0.0, 1.0);
      if (cover > 0) blend(x, y, c, cover);
    }
  }
}

void Raster::text(int x, int y, std::string_view s, Rgb c, int scale) {
  for (char ch : s) {
    const std::uint8_t* g = glyph(ch);
    for (int col = 0; col < kGlyphWidth; ++col)
      for (int row = 0; row < kGlyphHeight; ++row)
        if (g[col] >> row & 1)
          for (int dy = 0; dy < scale; ++dy)
            for (int dx = 0; dx < scale; ++dx) blend(x + col * scale + dx, y + row * scale + dy, c);
    x += 6 * scale;
  }
}

void Raster::text_vertical(int x, int y, std::string_view s, Rgb c, int scale) {
  // Rotated 90° counter-clockwise: the string runs upwards from (x, y + width).
  int base = y + text_width(s, scale);
  for (char ch : s) {
    const std::uint8_t* g = glyph(ch);
    for (int col = 0; col < kGlyphWidth; ++col)
      for (int row = 0; row < kGlyphHeight; ++row)
        if (g[col] >> row & 1)
          for (int dy = 0; dy < scale; ++dy)
            for (int dx = 0; dx < scale; ++dx) blend(x + row * scale + dx, base - col * scale - dy, c);
    base -= 6 * scale;
  }
}

std::string Raster::write_png(const std::string& path) const {
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return "cannot write '" + path + "': " + std::strerror(errno);
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!png || !info) {
    png_destroy_write_struct(&png, &info);
    std::fclose(f);
    return "libpng: out of memory";
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    std::fclose(f);
    return "libpng: error writing '" + path + "'";
  }
  png_init_io(png, f);
  png_set_IHDR(png, info, static_cast<png_uint_32>(width_), static_cast<png_uint_32>(height_), 8, PNG_COLOR_TYPE_RGB,
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  for (int y = 0; y < height_; ++y)
    png_write_row(png, &pixels_[static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) * 3]);
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return std::fclose(f) == 0 ? std::string() : "cannot write '" + path + "': " + std::strerror(errno);
}

}  // namespace scenario

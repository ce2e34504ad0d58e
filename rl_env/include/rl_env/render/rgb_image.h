/**
 * RgbImage: an 8-bit RGB raster (row-major, 3 bytes a pixel, row 0 at the top) with the few
 * drawing operations the environments' views need: filled rectangles and discs, and text in a
 * fixed 5x7 bitmap font (upper-case letters, digits, space and ": - ."). It carries no ROS
 * type; the env node copies it into a sensor_msgs/Image ("rgb8").
 */
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace rl_env {

struct Rgb {
  std::uint8_t r = 0;
  std::uint8_t g = 0;
  std::uint8_t b = 0;
  bool operator==(const Rgb& o) const { return r == o.r && g == o.g && b == o.b; }
  bool operator!=(const Rgb& o) const { return !(*this == o); }
};

class RgbImage {
 public:
  /// A width x height image filled with `background`. Throws std::invalid_argument if a side
  /// is not positive.
  RgbImage(int width, int height, Rgb background = {});

  int width() const { return width_; }
  int height() const { return height_; }
  /// width * 3: the bytes of one row (sensor_msgs/Image's `step`).
  int rowBytes() const { return width_ * 3; }
  const std::vector<std::uint8_t>& bytes() const { return bytes_; }

  /// The pixel at column x, row y. Throws std::out_of_range outside the image.
  Rgb at(int x, int y) const;

  /// Fills the rectangle [x, x + w) x [y, y + h), clipped to the image.
  void fillRect(int x, int y, int w, int h, Rgb colour);
  /// Fills the disc of radius `radius` centred on (cx, cy), clipped to the image.
  void fillDisc(double cx, double cy, double radius, Rgb colour);
  /// Draws `text` with its top-left corner at (x, y), each font pixel as a scale x scale
  /// block, 6 * scale pixels a character. Lower-case letters are drawn upper-case. Throws
  /// std::invalid_argument on a character the font lacks.
  void drawText(int x, int y, const std::string& text, int scale, Rgb colour);
  /// The width drawText() gives `text` at `scale`.
  static int textWidth(const std::string& text, int scale);

 private:
  int width_;
  int height_;
  std::vector<std::uint8_t> bytes_;
};

}  // namespace rl_env

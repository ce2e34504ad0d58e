#include "rl_env/render/rgb_image.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <stdexcept>

namespace rl_env {

namespace {

// 5x7 glyphs, one byte a row from the top, bit 4 the leftmost column.
using Glyph = std::array<std::uint8_t, 7>;

const Glyph* glyph(char c) {
  static const Glyph kLetters[26] = {
      {0x0E, 0x11, 0x11, 0x1F, 0x11, 0x11, 0x11},  // A
      {0x1E, 0x11, 0x11, 0x1E, 0x11, 0x11, 0x1E},  // B
      {0x0E, 0x11, 0x10, 0x10, 0x10, 0x11, 0x0E},  // C
      {0x1E, 0x11, 0x11, 0x11, 0x11, 0x11, 0x1E},  // D
      {0x1F, 0x10, 0x10, 0x1E, 0x10, 0x10, 0x1F},  // E
      {0x1F, 0x10, 0x10, 0x1E, 0x10, 0x10, 0x10},  // F
      {0x0E, 0x11, 0x10, 0x17, 0x11, 0x11, 0x0F},  // G
      {0x11, 0x11, 0x11, 0x1F, 0x11, 0x11, 0x11},  // H
      {0x0E, 0x04, 0x04, 0x04, 0x04, 0x04, 0x0E},  // I
      {0x07, 0x02, 0x02, 0x02, 0x02, 0x12, 0x0C},  // J
      {0x11, 0x12, 0x14, 0x18, 0x14, 0x12, 0x11},  // K
      {0x10, 0x10, 0x10, 0x10, 0x10, 0x10, 0x1F},  // L
      {0x11, 0x1B, 0x15, 0x15, 0x11, 0x11, 0x11},  // M
      {0x11, 0x11, 0x19, 0x15, 0x13, 0x11, 0x11},  // N
      {0x0E, 0x11, 0x11, 0x11, 0x11, 0x11, 0x0E},  // O
      {0x1E, 0x11, 0x11, 0x1E, 0x10, 0x10, 0x10},  // P
      {0x0E, 0x11, 0x11, 0x11, 0x15, 0x12, 0x0D},  // Q
      {0x1E, 0x11, 0x11, 0x1E, 0x14, 0x12, 0x11},  // R
      {0x0F, 0x10, 0x10, 0x0E, 0x01, 0x01, 0x1E},  // S
      {0x1F, 0x04, 0x04, 0x04, 0x04, 0x04, 0x04},  // T
      {0x11, 0x11, 0x11, 0x11, 0x11, 0x11, 0x0E},  // U
      {0x11, 0x11, 0x11, 0x11, 0x11, 0x0A, 0x04},  // V
      {0x11, 0x11, 0x11, 0x15, 0x15, 0x15, 0x0A},  // W
      {0x11, 0x11, 0x0A, 0x04, 0x0A, 0x11, 0x11},  // X
      {0x11, 0x11, 0x11, 0x0A, 0x04, 0x04, 0x04},  // Y
      {0x1F, 0x01, 0x02, 0x04, 0x08, 0x10, 0x1F},  // Z
  };
  static const Glyph kDigits[10] = {
      {0x0E, 0x11, 0x13, 0x15, 0x19, 0x11, 0x0E},  // 0
      {0x04, 0x0C, 0x04, 0x04, 0x04, 0x04, 0x0E},  // 1
      {0x0E, 0x11, 0x01, 0x02, 0x04, 0x08, 0x1F},  // 2
      {0x1F, 0x02, 0x04, 0x02, 0x01, 0x11, 0x0E},  // 3
      {0x02, 0x06, 0x0A, 0x12, 0x1F, 0x02, 0x02},  // 4
      {0x1F, 0x10, 0x1E, 0x01, 0x01, 0x11, 0x0E},  // 5
      {0x06, 0x08, 0x10, 0x1E, 0x11, 0x11, 0x0E},  // 6
      {0x1F, 0x01, 0x02, 0x04, 0x08, 0x08, 0x08},  // 7
      {0x0E, 0x11, 0x11, 0x0E, 0x11, 0x11, 0x0E},  // 8
      {0x0E, 0x11, 0x11, 0x0F, 0x01, 0x02, 0x0C},  // 9
  };
  static const Glyph kSpace = {0, 0, 0, 0, 0, 0, 0};
  static const Glyph kColon = {0x00, 0x0C, 0x0C, 0x00, 0x0C, 0x0C, 0x00};
  static const Glyph kDash = {0x00, 0x00, 0x00, 0x1F, 0x00, 0x00, 0x00};
  static const Glyph kDot = {0x00, 0x00, 0x00, 0x00, 0x00, 0x0C, 0x0C};
  const char u = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  if (u >= 'A' && u <= 'Z') return &kLetters[u - 'A'];
  if (u >= '0' && u <= '9') return &kDigits[u - '0'];
  switch (u) {
    case ' ':
      return &kSpace;
    case ':':
      return &kColon;
    case '-':
      return &kDash;
    case '.':
      return &kDot;
    default:
      return nullptr;
  }
}

}  // namespace

RgbImage::RgbImage(int width, int height, Rgb background) : width_(width), height_(height) {
  if (width <= 0 || height <= 0) {
    throw std::invalid_argument("RgbImage: size " + std::to_string(width) + "x" +
                                std::to_string(height) + " is not positive");
  }
  bytes_.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3);
  fillRect(0, 0, width, height, background);
}

Rgb RgbImage::at(int x, int y) const {
  if (x < 0 || x >= width_ || y < 0 || y >= height_) {
    throw std::out_of_range("RgbImage::at(" + std::to_string(x) + ", " + std::to_string(y) +
                            "): outside the " + std::to_string(width_) + "x" +
                            std::to_string(height_) + " image");
  }
  const std::size_t i = (static_cast<std::size_t>(y) * width_ + x) * 3;
  return {bytes_[i], bytes_[i + 1], bytes_[i + 2]};
}

void RgbImage::fillRect(int x, int y, int w, int h, Rgb colour) {
  const int x0 = std::max(x, 0), x1 = std::min(x + w, width_);
  const int y0 = std::max(y, 0), y1 = std::min(y + h, height_);
  for (int row = y0; row < y1; ++row) {
    for (int col = x0; col < x1; ++col) {
      const std::size_t i = (static_cast<std::size_t>(row) * width_ + col) * 3;
      bytes_[i] = colour.r;
      bytes_[i + 1] = colour.g;
      bytes_[i + 2] = colour.b;
    }
  }
}

void RgbImage::fillDisc(double cx, double cy, double radius, Rgb colour) {
  const int x0 = static_cast<int>(std::floor(cx - radius)), x1 = static_cast<int>(cx + radius);
  const int y0 = static_cast<int>(std::floor(cy - radius)), y1 = static_cast<int>(cy + radius);
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      const double dx = x + 0.5 - cx, dy = y + 0.5 - cy;  // the pixel's centre
      if (dx * dx + dy * dy <= radius * radius) fillRect(x, y, 1, 1, colour);
    }
  }
}

int RgbImage::textWidth(const std::string& text, int scale) {
  return static_cast<int>(text.size()) * 6 * scale;
}

void RgbImage::drawText(int x, int y, const std::string& text, int scale, Rgb colour) {
  // Every character is checked before any is drawn: a bad text leaves the image as it was.
  for (const char c : text) {
    if (glyph(c) == nullptr) {
      throw std::invalid_argument(std::string("RgbImage::drawText(): no glyph for '") + c +
                                  "' (the font has A-Z, 0-9, space and \": - .\")");
    }
  }
  for (std::size_t k = 0; k < text.size(); ++k) {
    const Glyph* g = glyph(text[k]);
    const int left = x + static_cast<int>(k) * 6 * scale;
    for (int row = 0; row < 7; ++row) {
      for (int col = 0; col < 5; ++col) {
        if (((*g)[row] >> (4 - col)) & 1) {
          fillRect(left + col * scale, y + row * scale, scale, scale, colour);
        }
      }
    }
  }
}

}  // namespace rl_env

// RgbImage: size checks, clipped rectangles and discs, the bitmap font (a glyph's pixels, the
// text width, a character the font lacks leaves the image untouched).
#include "rl_env/render/rgb_image.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace {

using rl_env::Rgb;
using rl_env::RgbImage;

const Rgb kWhite{255, 255, 255};
const Rgb kRed{255, 0, 0};

TEST(RgbImage, SizeBackgroundAndBounds) {
  const RgbImage image(4, 3, kWhite);
  EXPECT_EQ(image.width(), 4);
  EXPECT_EQ(image.height(), 3);
  EXPECT_EQ(image.rowBytes(), 12);
  EXPECT_EQ(image.bytes().size(), 36u);
  EXPECT_EQ(image.at(3, 2), kWhite);
  EXPECT_THROW(image.at(4, 0), std::out_of_range);
  EXPECT_THROW(image.at(0, -1), std::out_of_range);
  EXPECT_THROW(RgbImage(0, 3), std::invalid_argument);
}

TEST(RgbImage, RectanglesAreClippedAndRowMajor) {
  RgbImage image(4, 3, kWhite);
  image.fillRect(2, 1, 10, 10, kRed);  // runs past the right and bottom edges
  EXPECT_EQ(image.at(1, 1), kWhite);
  EXPECT_EQ(image.at(2, 1), kRed);
  EXPECT_EQ(image.at(3, 2), kRed);
  EXPECT_EQ(image.at(2, 0), kWhite);
  // Pixel (2, 1) is bytes (1 * 4 + 2) * 3 ..: red, green, blue.
  EXPECT_EQ(image.bytes()[18], 255);
  EXPECT_EQ(image.bytes()[19], 0);
  image.fillRect(-5, -5, 6, 6, kRed);  // only (0, 0) is inside
  EXPECT_EQ(image.at(0, 0), kRed);
  EXPECT_EQ(image.at(1, 0), kWhite);
}

TEST(RgbImage, DiscCoversItsCentreNotItsCorners) {
  RgbImage image(20, 20, kWhite);
  image.fillDisc(10.0, 10.0, 5.0, kRed);
  EXPECT_EQ(image.at(10, 10), kRed);
  EXPECT_EQ(image.at(14, 10), kRed);
  EXPECT_EQ(image.at(15, 10), kWhite);  // its pixel centre is 5.5 away
  EXPECT_EQ(image.at(14, 14), kWhite);  // the bounding box's corner
}

TEST(RgbImage, TextDrawsTheGlyphAndRejectsUnknownCharacters) {
  RgbImage image(40, 20, kWhite);
  EXPECT_EQ(RgbImage::textWidth("AB", 2), 24);
  image.drawText(1, 1, "l", 1, kRed);  // lower case is drawn as 'L': the left column, the base
  for (int row = 0; row < 7; ++row) EXPECT_EQ(image.at(1, 1 + row), kRed) << row;
  EXPECT_EQ(image.at(2, 1), kWhite);
  EXPECT_EQ(image.at(5, 7), kRed);  // the base's right end
  const RgbImage before = image;
  EXPECT_THROW(image.drawText(10, 1, "OK?", 1, kRed), std::invalid_argument);
  EXPECT_EQ(image.bytes(), before.bytes());  // nothing drawn, not even "OK"
}

}  // namespace

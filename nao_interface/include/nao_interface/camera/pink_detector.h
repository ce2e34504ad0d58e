/**
 * PinkDetector: counts pink pixels in a camera image, the paper's pink-pixel state feature
 * and pink-task reward (Hester & Stone, TEXPLORE-VANIR, §5.2).
 *
 * The detection pipeline a robot would run: convert the BGR image to HSV with OpenCV and keep
 * the pixels whose hue lies in the magenta-pink band (OpenCV hue 0..180) with enough
 * saturation and brightness (cv::inRange), then count them (cv::countNonZero). A pink surface
 * that is shaded dark (too close to the lens, or turned away from the light) falls below the
 * brightness threshold and is not counted, as in the paper.
 */
#pragma once

#include <opencv2/core.hpp>

namespace nao_interface {

struct PinkThreshold {
  int hueLow = 145;  ///< OpenCV hue (0..180): pink/magenta sits around 160-170
  int hueHigh = 175;
  int satMin = 90;  ///< 0..255
  int valMin = 70;  ///< 0..255: darker pixels are shadow, not pink
};

class PinkDetector {
 public:
  explicit PinkDetector(PinkThreshold threshold = {}) : threshold_(threshold) {}

  /// Binary mask (CV_8U, 255 = pink) of an 8-bit 3-channel image in BGR order.
  /// Throws std::invalid_argument for another image type.
  cv::Mat mask(const cv::Mat& bgr) const;
  /// Number of pink pixels of an 8-bit 3-channel BGR image.
  int count(const cv::Mat& bgr) const { return cv::countNonZero(mask(bgr)); }

  const PinkThreshold& threshold() const { return threshold_; }

 private:
  PinkThreshold threshold_;
};

}  // namespace nao_interface

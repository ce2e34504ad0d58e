#include "nao_interface/camera/pink_detector.h"

#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace nao_interface {

cv::Mat PinkDetector::mask(const cv::Mat& bgr) const {
  if (bgr.empty() || bgr.type() != CV_8UC3) {
    throw std::invalid_argument("PinkDetector::mask(): expected a non-empty 8-bit BGR image");
  }
  cv::Mat hsv, out;
  cv::cvtColor(bgr, hsv, cv::COLOR_BGR2HSV);
  cv::inRange(hsv, cv::Scalar(threshold_.hueLow, threshold_.satMin, threshold_.valMin),
              cv::Scalar(threshold_.hueHigh, 255, 255), out);
  return out;
}

}  // namespace nao_interface

// PinkDetector: HSV thresholds on synthetic images with known pixel counts.
#include "nao_interface/camera/pink_detector.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

using nao_interface::PinkDetector;

TEST(PinkDetector, CountsExactlyThePinkRectangle) {
  cv::Mat img(240, 320, CV_8UC3, cv::Scalar(150, 180, 205));  // beige floor (BGR)
  cv::rectangle(img, cv::Rect(10, 20, 30, 40), cv::Scalar(170, 80, 255), cv::FILLED);  // pink
  EXPECT_EQ(PinkDetector().count(img), 30 * 40);
}

TEST(PinkDetector, RejectsOtherHuesAndDarkOrPalePink) {
  cv::Mat img(240, 320, CV_8UC3, cv::Scalar(0, 0, 0));
  cv::rectangle(img, cv::Rect(0, 0, 50, 50), cv::Scalar(0, 0, 255), cv::FILLED);        // red
  cv::rectangle(img, cv::Rect(50, 0, 50, 50), cv::Scalar(60, 160, 200), cv::FILLED);    // gold
  cv::rectangle(img, cv::Rect(100, 0, 50, 50), cv::Scalar(255, 0, 0), cv::FILLED);      // blue
  cv::rectangle(img, cv::Rect(150, 0, 50, 50), cv::Scalar(34, 16, 51), cv::FILLED);     // shaded
  cv::rectangle(img, cv::Rect(200, 0, 50, 50), cv::Scalar(235, 225, 245), cv::FILLED);  // pale
  cv::rectangle(img, cv::Rect(250, 0, 10, 10), cv::Scalar(120, 55, 180), cv::FILLED);   // pink
  EXPECT_EQ(PinkDetector().count(img), 100);
}

TEST(PinkDetector, RejectsNonColourImages) {
  EXPECT_THROW(PinkDetector().count(cv::Mat(10, 10, CV_8UC1)), std::invalid_argument);
  EXPECT_THROW(PinkDetector().count(cv::Mat()), std::invalid_argument);
}

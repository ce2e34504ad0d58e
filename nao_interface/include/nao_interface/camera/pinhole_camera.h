/**
 * PinholeCamera: the Nao top camera as an ideal pinhole (no distortion), in the REP-103
 * optical frame (z forward, x right, y down): u = fx x / z + cx, v = fy y / z + cy.
 *
 * Defaults are the V4/V5 top camera (MT9M114) at QVGA, 320x240, with the focal lengths that
 * its 60.9° x 47.6° field of view gives (fx = 160 / tan(30.45°) ≈ 272); source:
 * naoqi_driver/src/tools/alvisiondefinitions.h, see shared/spec/NAO.md §1.3.
 */
#pragma once

#include <Eigen/Core>
#include <optional>

namespace nao_interface {

struct PinholeCamera {
  int width = 320;
  int height = 240;
  double fx = 0.0;
  double fy = 0.0;
  double cx = 0.0;
  double cy = 0.0;

  /// An ideal camera of `width` x `height` pixels with the given full fields of view (degrees),
  /// principal point at the image centre. Throws std::invalid_argument on bad values.
  static PinholeCamera fromFieldOfView(int width, int height, double hfovDeg, double vfovDeg);
  /// The Nao V4/V5 top camera at 320x240 (MT9M114, 60.9° x 47.6°).
  static PinholeCamera naoTopQvga() { return fromFieldOfView(320, 240, 60.9, 47.6); }

  /// Pixel of a point in the optical frame, or nothing if it lies behind `near` metres.
  std::optional<Eigen::Vector2d> project(const Eigen::Vector3d& p, double near = 1e-3) const;
  /// Direction (not normalised) of the ray through pixel (u, v), in the optical frame.
  Eigen::Vector3d ray(double u, double v) const {
    return Eigen::Vector3d((u - cx) / fx, (v - cy) / fy, 1.0);
  }
  /// True if pixel (u, v) lies inside the image.
  bool inside(const Eigen::Vector2d& px) const {
    return px.x() >= 0 && px.y() >= 0 && px.x() < width && px.y() < height;
  }
};

}  // namespace nao_interface

#include "nao_interface/camera/pinhole_camera.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace nao_interface {

PinholeCamera PinholeCamera::fromFieldOfView(int width, int height, double hfovDeg,
                                             double vfovDeg) {
  if (width <= 0 || height <= 0) {
    throw std::invalid_argument(
        "PinholeCamera::fromFieldOfView(): image size must be positive, got " +
        std::to_string(width) + "x" + std::to_string(height));
  }
  if (!(hfovDeg > 0 && hfovDeg < 180 && vfovDeg > 0 && vfovDeg < 180)) {
    throw std::invalid_argument(
        "PinholeCamera::fromFieldOfView(): fields of view must lie in (0, 180) degrees");
  }
  PinholeCamera c;
  c.width = width;
  c.height = height;
  c.fx = (width / 2.0) / std::tan(hfovDeg * M_PI / 360.0);
  c.fy = (height / 2.0) / std::tan(vfovDeg * M_PI / 360.0);
  c.cx = width / 2.0;
  c.cy = height / 2.0;
  return c;
}

std::optional<Eigen::Vector2d> PinholeCamera::project(const Eigen::Vector3d& p, double near) const {
  if (p.z() < near) return std::nullopt;
  return Eigen::Vector2d(fx * p.x() / p.z() + cx, fy * p.y() / p.z() + cy);
}

}  // namespace nao_interface

/**
 * SceneRenderer: draws what the seated Nao's top camera sees, with OpenCV, so that the pink
 * pixel count comes from a real image through the real detection pipeline (PinkDetector).
 *
 * The scene (all in the torso frame, from the URDF kinematics): a floor (beige/brown checker)
 * and a wall behind it, the right leg and foot, the cymbal (a golden disc), the right arm as
 * light-grey capsules (shoulder-elbow-wrist-hand) and the pink square taped to the hand. Each
 * primitive is clipped at the near plane, projected through the pinhole camera and painted far
 * to near (painter's algorithm). The pink square is shaded: brightness
 *   b = (ambient + (1 - ambient) |n . v|) * clamp((d - shadowNear) / (shadowFar - shadowNear), 0.1,
 * 1) for its normal n, the unit vector v to the lens and its distance d, so a square held close to
 * the lens turns dark and stops being classified pink, as the paper observed (§5.2). Optional
 * seeded Gaussian pixel noise stands in for sensor noise.
 */
#pragma once

#include <Eigen/Geometry>
#include <opencv2/core.hpp>
#include <vector>

#include "nao_interface/camera/pinhole_camera.h"
#include "rl_common/random.h"

namespace nao_interface {

/// Where everything is, in the torso frame (metres).
struct SceneGeometry {
  Eigen::Isometry3d camera = Eigen::Isometry3d::Identity();  ///< the optical frame
  std::vector<Eigen::Vector3d> arm;  ///< shoulder, elbow, wrist, hand (gripper)
  Eigen::Isometry3d pinkSquare = Eigen::Isometry3d::Identity();  ///< centre, normal = z axis
  double squareSize = 0.06;                                      ///< side (m)
  Eigen::Vector3d hip = Eigen::Vector3d::Zero();
  Eigen::Vector3d ankle = Eigen::Vector3d::Zero();
  Eigen::Vector3d bumper = Eigen::Vector3d::Zero();
  Eigen::Isometry3d cymbal = Eigen::Isometry3d::Identity();  ///< disc normal = y axis
  double cymbalRadius = 0.12;
};

struct RenderOptions {
  PinholeCamera camera = PinholeCamera::naoTopQvga();
  double floorZ = -0.135;    ///< floor height in the torso frame (m)
  double ambient = 0.35;     ///< share of the square's brightness that is not directional
  double shadowNear = 0.06;  ///< at or below this distance (m) the square is darkest
  double shadowFar = 0.16;   ///< beyond this distance it is fully lit
  double pixelNoise = 0.0;   ///< standard deviation of Gaussian pixel noise (0 = none)
};

class SceneRenderer {
 public:
  explicit SceneRenderer(RenderOptions options = {});

  /// Renders the view as an 8-bit BGR image of the camera's size. `noise` (may be null) draws
  /// the pixel noise when options().pixelNoise > 0.
  cv::Mat render(const SceneGeometry& scene, rl_common::Random* noise = nullptr) const;

  const RenderOptions& options() const { return options_; }

 private:
  cv::Mat background(const Eigen::Isometry3d& camera) const;

  RenderOptions options_;
  mutable cv::Mat cachedBackground_;
  mutable Eigen::Isometry3d cachedCamera_ = Eigen::Isometry3d::Identity();
};

}  // namespace nao_interface

/**
 * naoArmMarkers: the rviz markers of the Nao arm scene that the URDF's RobotModel cannot show,
 * built from what the bridge knows through the driver: the right foot bumper (frame
 * RFootBumper; grey, red while pressed) and the cymbal (frame cymbal, a disc whose normal is
 * the frame's y axis; brass, flashing bright and a little larger on a hit, fading with
 * CymbalHitDetector::flash), each with a text label above it. The frames are URDF links, so
 * robot_state_publisher's TF places them; the markers are frame-locked, stamped 0 (rviz draws
 * them at the latest transform) and never expire.
 */
#pragma once

#include <visualization_msgs/MarkerArray.h>

#include <string>

namespace nao_interface {

struct NaoArmMarkerState {
  bool bumperPressed = false;
  double cymbalFlash = 0.0;    ///< in [0, 1] (CymbalHitDetector::flash)
  long cymbalHits = 0;         ///< shown on the cymbal's label
  double cymbalRadius = 0.12;  ///< m (NaoArmSimConfig::cymbalRadius)
};

/// Marker namespaces (ids 0 and 1: the shape and its label).
inline const std::string kBumperMarkerNs = "foot_bumper";
inline const std::string kCymbalMarkerNs = "cymbal";

/// The bumper's and the cymbal's markers (a shape and a text each) for `state`.
visualization_msgs::MarkerArray naoArmMarkers(const NaoArmMarkerState& state);

}  // namespace nao_interface

#include "nao_interface/ros/nao_arm_markers.h"

#include <algorithm>
#include <cmath>

namespace nao_interface {

namespace {

std_msgs::ColorRGBA rgba(double r, double g, double b, double a) {
  std_msgs::ColorRGBA c;
  c.r = static_cast<float>(r);
  c.g = static_cast<float>(g);
  c.b = static_cast<float>(b);
  c.a = static_cast<float>(a);
  return c;
}

std_msgs::ColorRGBA mix(const std_msgs::ColorRGBA& a, const std_msgs::ColorRGBA& b, double t) {
  return rgba(a.r + (b.r - a.r) * t, a.g + (b.g - a.g) * t, a.b + (b.b - a.b) * t,
              a.a + (b.a - a.a) * t);
}

visualization_msgs::Marker marker(const std::string& ns, int id, const std::string& frame,
                                  int type) {
  visualization_msgs::Marker m;
  m.header.frame_id = frame;  // stamp 0: the latest transform
  m.ns = ns;
  m.id = id;
  m.type = type;
  m.action = visualization_msgs::Marker::ADD;
  m.pose.orientation.w = 1.0;
  m.frame_locked = true;
  return m;
}

visualization_msgs::Marker label(const std::string& ns, const std::string& frame, double z,
                                 const std::string& text, const std_msgs::ColorRGBA& colour) {
  visualization_msgs::Marker m = marker(ns, 1, frame, visualization_msgs::Marker::TEXT_VIEW_FACING);
  m.pose.position.z = z;
  m.scale.z = 0.03;  // text height (m)
  m.color = colour;
  m.text = text;
  return m;
}

}  // namespace

visualization_msgs::MarkerArray naoArmMarkers(const NaoArmMarkerState& s) {
  visualization_msgs::MarkerArray out;

  // The bumper: a box around the URDF's (0.015 x 0.04 x 0.015 m).
  visualization_msgs::Marker bumper =
      marker(kBumperMarkerNs, 0, "RFootBumper", visualization_msgs::Marker::CUBE);
  bumper.scale.x = 0.025;
  bumper.scale.y = 0.05;
  bumper.scale.z = 0.025;
  bumper.color = s.bumperPressed ? rgba(1.0, 0.1, 0.1, 1.0) : rgba(0.55, 0.55, 0.6, 0.8);
  out.markers.push_back(bumper);
  out.markers.push_back(label(kBumperMarkerNs, "RFootBumper", 0.06,
                              s.bumperPressed ? "bumper PRESSED" : "bumper", bumper.color));

  // The cymbal: a thin cylinder whose axis (marker z) is the frame's y axis.
  const double flash = std::clamp(s.cymbalFlash, 0.0, 1.0);
  visualization_msgs::Marker cymbal =
      marker(kCymbalMarkerNs, 0, "cymbal", visualization_msgs::Marker::CYLINDER);
  cymbal.pose.orientation.x = std::sqrt(0.5);  // 90 degrees about x: z -> -y
  cymbal.pose.orientation.w = std::sqrt(0.5);
  const double grow = 1.0 + 0.25 * flash;
  cymbal.scale.x = cymbal.scale.y = 2.0 * s.cymbalRadius * grow;
  cymbal.scale.z = 0.004;
  cymbal.color = mix(rgba(0.8, 0.6, 0.2, 0.5), rgba(1.0, 1.0, 0.5, 1.0), flash);
  out.markers.push_back(cymbal);
  out.markers.push_back(label(kCymbalMarkerNs, "cymbal", s.cymbalRadius + 0.04,
                              "cymbal hits: " + std::to_string(s.cymbalHits),
                              mix(rgba(0.9, 0.75, 0.3, 1.0), rgba(1.0, 1.0, 0.6, 1.0), flash)));
  return out;
}

}  // namespace nao_interface

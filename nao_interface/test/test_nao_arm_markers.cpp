// naoArmMarkers: the rviz markers' frames (URDF links), the bumper's colour when pressed and
// the cymbal's flash.
#include "nao_interface/ros/nao_arm_markers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

using namespace nao_interface;
using visualization_msgs::Marker;

namespace {

const Marker& find(const visualization_msgs::MarkerArray& a, const std::string& ns, int id) {
  for (const Marker& m : a.markers) {
    if (m.ns == ns && m.id == id) return m;
  }
  throw std::runtime_error("no marker " + ns + "/" + std::to_string(id));
}

bool sameColour(const std_msgs::ColorRGBA& a, const std_msgs::ColorRGBA& b) {
  return a.r == b.r && a.g == b.g && a.b == b.b && a.a == b.a;
}

}  // namespace

TEST(NaoArmMarkers, FramesAreLinksOfTheUrdf) {
  std::ifstream f(std::string(NAO_INTERFACE_URDF_DIR) + "/nao_upper_body.urdf");
  std::stringstream urdf;
  urdf << f.rdbuf();
  const visualization_msgs::MarkerArray a = naoArmMarkers({});
  ASSERT_EQ(a.markers.size(), 4u);
  for (const Marker& m : a.markers) {
    EXPECT_NE(urdf.str().find("<link name=\"" + m.header.frame_id + "\""), std::string::npos)
        << m.header.frame_id;
    EXPECT_EQ(m.action, Marker::ADD);
    EXPECT_TRUE(m.frame_locked);
    EXPECT_EQ(m.header.stamp.toSec(), 0.0);
    EXPECT_GT(m.color.a, 0.0f);
  }
  EXPECT_EQ(find(a, kBumperMarkerNs, 0).header.frame_id, "RFootBumper");
  EXPECT_EQ(find(a, kCymbalMarkerNs, 0).header.frame_id, "cymbal");
  EXPECT_EQ(find(a, kBumperMarkerNs, 0).type, Marker::CUBE);
  EXPECT_EQ(find(a, kCymbalMarkerNs, 0).type, Marker::CYLINDER);
}

TEST(NaoArmMarkers, BumperTurnsRedWhilePressed) {
  NaoArmMarkerState s;
  const Marker released = find(naoArmMarkers(s), kBumperMarkerNs, 0);
  s.bumperPressed = true;
  const visualization_msgs::MarkerArray a = naoArmMarkers(s);
  const Marker& pressed = find(a, kBumperMarkerNs, 0);
  EXPECT_FALSE(sameColour(released.color, pressed.color));
  EXPECT_GT(pressed.color.r, 0.9f);
  EXPECT_LT(pressed.color.g, 0.2f);
  EXPECT_EQ(find(a, kBumperMarkerNs, 1).text, "bumper PRESSED");
}

TEST(NaoArmMarkers, CymbalFlashesAndGrowsOnAHit) {
  NaoArmMarkerState s;
  s.cymbalRadius = 0.12;
  const Marker quiet = find(naoArmMarkers(s), kCymbalMarkerNs, 0);
  EXPECT_NEAR(quiet.scale.x, 0.24, 1e-9);
  EXPECT_NEAR(quiet.scale.y, 0.24, 1e-9);
  // The disc's axis (the marker's z) along the cymbal frame's y axis: 90 degrees about x.
  EXPECT_NEAR(quiet.pose.orientation.x, std::sqrt(0.5), 1e-9);
  EXPECT_NEAR(quiet.pose.orientation.w, std::sqrt(0.5), 1e-9);
  s.cymbalFlash = 1.0;
  s.cymbalHits = 3;
  const visualization_msgs::MarkerArray a = naoArmMarkers(s);
  const Marker& flash = find(a, kCymbalMarkerNs, 0);
  EXPECT_GT(flash.scale.x, quiet.scale.x);
  EXPECT_FLOAT_EQ(flash.color.a, 1.0f);
  EXPECT_GT(flash.color.g + flash.color.b, quiet.color.g + quiet.color.b);  // brighter
  EXPECT_EQ(find(a, kCymbalMarkerNs, 1).text, "cymbal hits: 3");
  // Half faded: between the two.
  s.cymbalFlash = 0.5;
  const Marker half = find(naoArmMarkers(s), kCymbalMarkerNs, 0);
  EXPECT_GT(half.color.a, quiet.color.a);
  EXPECT_LT(half.color.a, flash.color.a);
}

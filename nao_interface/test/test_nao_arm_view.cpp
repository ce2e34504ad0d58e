// The bridge's rviz topics through ROS (nao_arm_view.test): with this node as the driver, the
// bridge publishes the pink detector's mask of each camera image on ~pink_mask (mono8, the
// image's header, 255 exactly on the pink pixels) and its markers on ~markers, whose frames
// are URDF links, whose bumper turns red on a press event and back on the release, and whose
// cymbal flashes on a cymbal-loud audio buffer but not on a knock-loud one.
#include <gtest/gtest.h>
#include <naoqi_bridge_msgs/AudioBuffer.h>
#include <naoqi_bridge_msgs/Bumper.h>
#include <ros/ros.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/image_encodings.h>
#include <visualization_msgs/MarkerArray.h>

#include <cstdint>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

namespace {

constexpr int kWidth = 320, kHeight = 240;
// The pink patch: columns [100, 120), rows [50, 60); BGR (180, 105, 255) is hot pink.
bool inPatch(int x, int y) { return x >= 100 && x < 120 && y >= 50 && y < 60; }

sensor_msgs::Image cameraImage() {
  sensor_msgs::Image im;
  im.header.frame_id = "CameraTop_optical_frame";
  im.header.stamp = ros::Time::now();
  im.width = kWidth;
  im.height = kHeight;
  im.encoding = sensor_msgs::image_encodings::BGR8;
  im.step = kWidth * 3;
  im.data.assign(im.step * kHeight, 128);  // grey
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      if (!inPatch(x, y)) continue;
      std::uint8_t* p = &im.data[y * im.step + x * 3];
      p[0] = 180;
      p[1] = 105;
      p[2] = 255;
    }
  }
  return im;
}

/// A 4-channel buffer of 2048 frames whose samples alternate +-amplitude (energy = amplitude).
naoqi_bridge_msgs::AudioBuffer audio(std::int16_t amplitude) {
  naoqi_bridge_msgs::AudioBuffer a;
  a.header.stamp = ros::Time::now();
  a.frequency = 48000;
  a.channelMap = {0, 2, 1, 3};
  a.data.resize(4 * 2048);
  for (std::size_t i = 0; i < a.data.size(); ++i) {
    a.data[i] = static_cast<std::int16_t>((i / 4) % 2 ? amplitude : -amplitude);
  }
  return a;
}

const visualization_msgs::Marker* find(const visualization_msgs::MarkerArray& a,
                                       const std::string& ns, int id) {
  for (const auto& m : a.markers) {
    if (m.ns == ns && m.id == id) return &m;
  }
  return nullptr;
}

class NaoArmView : public ::testing::Test {
 protected:
  void SetUp() override {
    image_ = nh_.advertise<sensor_msgs::Image>("naoqi_driver/camera/front/image_raw", 1);
    bumper_ = nh_.advertise<naoqi_bridge_msgs::Bumper>("naoqi_driver/bumper", 10, true);
    audio_ = nh_.advertise<naoqi_bridge_msgs::AudioBuffer>("naoqi_driver/audio", 10);
    maskSub_ = nh_.subscribe<sensor_msgs::Image>(
        "nao_arm_bridge/pink_mask", 1,
        [this](const sensor_msgs::Image::ConstPtr& m) { mask_ = m; });
    markerSub_ = nh_.subscribe<visualization_msgs::MarkerArray>(
        "nao_arm_bridge/markers", 1,
        [this](const visualization_msgs::MarkerArray::ConstPtr& m) { markers_ = m; });
  }

  /// Spins (publishing a camera image every 0.1 s) until `done` or `timeout` seconds.
  bool spinUntil(const std::function<bool()>& done, double timeout = 10.0) {
    const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(timeout);
    ros::WallTime nextImage = ros::WallTime::now();
    while (ros::ok() && ros::WallTime::now() < end) {
      if (ros::WallTime::now() >= nextImage) {
        image_.publish(cameraImage());
        nextImage += ros::WallDuration(0.1);
      }
      ros::spinOnce();
      if (done()) return true;
      ros::WallDuration(0.005).sleep();
    }
    return false;
  }

  /// The next marker array received after now.
  visualization_msgs::MarkerArray nextMarkers() {
    markers_.reset();
    EXPECT_TRUE(spinUntil([this] { return markers_ != nullptr; })) << "no ~markers";
    return markers_ ? *markers_ : visualization_msgs::MarkerArray();
  }

  void pressBumper(bool pressed) {
    naoqi_bridge_msgs::Bumper b;
    b.bumper = naoqi_bridge_msgs::Bumper::right;
    b.state = pressed ? naoqi_bridge_msgs::Bumper::statePressed
                      : naoqi_bridge_msgs::Bumper::stateReleased;
    bumper_.publish(b);
  }

  ros::NodeHandle nh_;
  ros::Publisher image_, bumper_, audio_;
  ros::Subscriber maskSub_, markerSub_;
  sensor_msgs::Image::ConstPtr mask_;
  visualization_msgs::MarkerArray::ConstPtr markers_;
};

TEST_F(NaoArmView, PinkMaskIsTheDetectorsMonoMask) {
  ASSERT_TRUE(spinUntil([this] { return mask_ != nullptr; })) << "no ~pink_mask";
  const sensor_msgs::Image& m = *mask_;
  EXPECT_EQ(m.encoding, sensor_msgs::image_encodings::MONO8);
  EXPECT_EQ(m.header.frame_id, "CameraTop_optical_frame");
  ASSERT_EQ(m.width, static_cast<unsigned>(kWidth));
  ASSERT_EQ(m.height, static_cast<unsigned>(kHeight));
  ASSERT_GE(m.step, m.width);
  int wrong = 0, pink = 0;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const std::uint8_t v = m.data[y * m.step + x];
      pink += v == 255;
      wrong += v != (inPatch(x, y) ? 255 : 0);
    }
  }
  EXPECT_EQ(pink, 200);
  EXPECT_EQ(wrong, 0);
}

TEST_F(NaoArmView, MarkersShowTheBumperAndTheCymbal) {
  std::ifstream f(NAO_INTERFACE_URDF);
  std::stringstream urdf;
  urdf << f.rdbuf();
  ASSERT_FALSE(urdf.str().empty());

  visualization_msgs::MarkerArray a = nextMarkers();
  ASSERT_FALSE(a.markers.empty());
  for (const auto& m : a.markers) {
    EXPECT_NE(urdf.str().find("<link name=\"" + m.header.frame_id + "\""), std::string::npos)
        << "marker " << m.ns << "/" << m.id << " in frame '" << m.header.frame_id
        << "', not a link of the URDF";
  }
  const auto* bumper = find(a, "foot_bumper", 0);
  const auto* cymbal = find(a, "cymbal", 0);
  ASSERT_TRUE(bumper && cymbal);
  const std_msgs::ColorRGBA released = bumper->color, quiet = cymbal->color;
  const double quietSize = cymbal->scale.x;
  EXPECT_LT(released.r, 0.9f);

  // Press: the bumper turns red; release: back to its colour.
  pressBumper(true);
  ASSERT_TRUE(spinUntil([this] {
    const auto* b = markers_ ? find(*markers_, "foot_bumper", 0) : nullptr;
    return b && b->color.r > 0.9f && b->color.g < 0.2f;
  })) << "the bumper marker did not turn red on a press";
  pressBumper(false);
  ASSERT_TRUE(spinUntil([&] {
    const auto* b = markers_ ? find(*markers_, "foot_bumper", 0) : nullptr;
    return b && b->color.r == released.r && b->color.g == released.g;
  })) << "the bumper marker did not turn back on the release";

  // A knock-loud buffer (energy 300) is not a cymbal hit; a cymbal-loud one (3000) is.
  audio_.publish(audio(20));
  audio_.publish(audio(300));
  a = nextMarkers();
  a = nextMarkers();
  ASSERT_TRUE(find(a, "cymbal", 1));
  EXPECT_EQ(find(a, "cymbal", 1)->text, "cymbal hits: 0");
  EXPECT_EQ(find(a, "cymbal", 0)->color.a, quiet.a);
  audio_.publish(audio(3000));
  ASSERT_TRUE(spinUntil([this] {
    const auto* t = markers_ ? find(*markers_, "cymbal", 1) : nullptr;
    return t && t->text == "cymbal hits: 1";
  })) << "no cymbal hit on a loud buffer";
  const auto* flash = find(*markers_, "cymbal", 0);
  ASSERT_TRUE(flash);
  EXPECT_GT(flash->color.a, quiet.a);
  EXPECT_GT(flash->scale.x, quietSize);
  // The flash fades back to the quiet cymbal.
  ASSERT_TRUE(spinUntil([&] {
    const auto* c = markers_ ? find(*markers_, "cymbal", 0) : nullptr;
    return c && c->color.a == quiet.a;
  })) << "the cymbal's flash did not fade";
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_nao_arm_view");
  return RUN_ALL_TESTS();
}

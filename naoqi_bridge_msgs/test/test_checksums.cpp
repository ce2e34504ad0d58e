// The messages' MD5 checksums equal those of ros-naoqi/naoqi_bridge_msgs (shared/spec/NAO.md
// §2.3), so the suite's nodes and a real Nao driver accept each other's connections.
#include <gtest/gtest.h>
#include <naoqi_bridge_msgs/AudioBuffer.h>
#include <naoqi_bridge_msgs/Bumper.h>
#include <naoqi_bridge_msgs/FloatStamped.h>
#include <naoqi_bridge_msgs/JointAnglesWithSpeed.h>

#include <string>

template <class M>
std::string md5() {
  return ros::message_traits::MD5Sum<M>::value();
}

TEST(NaoqiBridgeMsgs, ChecksumsMatchTheRealDriver) {
  EXPECT_EQ(md5<naoqi_bridge_msgs::JointAnglesWithSpeed>(), "052ca11f74a00ad6745dfff6ebc2b4d8");
  EXPECT_EQ(md5<naoqi_bridge_msgs::Bumper>(), "89965a81ab868825f18d59365e28ddaf");
  EXPECT_EQ(md5<naoqi_bridge_msgs::AudioBuffer>(), "50f300aa63f3c1b2f3d3173329165316");
  EXPECT_EQ(md5<naoqi_bridge_msgs::FloatStamped>(), "ef848af8cf12f6df11682cc76fba477b");
}

TEST(NaoqiBridgeMsgs, ConstantsAndTypes) {
  EXPECT_EQ(naoqi_bridge_msgs::Bumper::right, 0);
  EXPECT_EQ(naoqi_bridge_msgs::Bumper::statePressed, 1);
  EXPECT_EQ(naoqi_bridge_msgs::AudioBuffer::CHANNEL_FRONT_CENTER, 1);
  EXPECT_EQ(std::string(ros::message_traits::DataType<naoqi_bridge_msgs::Bumper>::value()),
            "naoqi_bridge_msgs/Bumper");
}

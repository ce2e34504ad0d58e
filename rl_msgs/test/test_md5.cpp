// The five original messages must keep the original's checksums (and hence fields and order),
// or an original node and one of ours refuse to connect.
#include <gtest/gtest.h>
#include <rl_msgs/RLAction.h>
#include <rl_msgs/RLEnvDescription.h>
#include <rl_msgs/RLEnvSeedExperience.h>
#include <rl_msgs/RLExperimentInfo.h>
#include <rl_msgs/RLStateReward.h>
#include <ros/message_traits.h>

#include <string>

template <class M>
std::string md5() {
  return ros::message_traits::MD5Sum<M>::value();
}

TEST(RlMsgs, ChecksumsEqualTheOriginals) {
  EXPECT_EQ(md5<rl_msgs::RLAction>(), "b028501ac85c840a01d50342b4cc9b6e");
  EXPECT_EQ(md5<rl_msgs::RLEnvDescription>(), "41ee0d621b8031a958ff6d1f587a3860");
  EXPECT_EQ(md5<rl_msgs::RLEnvSeedExperience>(), "e195f7b7c1a41138d96a4af2de05b1b1");
  EXPECT_EQ(md5<rl_msgs::RLExperimentInfo>(), "df389dab0f017dc2a66e6cedd44b7a1e");
  EXPECT_EQ(md5<rl_msgs::RLStateReward>(), "d7e0cc8b9cf2889f09d7f096a11a2873");
}

TEST(RlMsgs, FieldTypesAsTheOriginal) {
  rl_msgs::RLEnvDescription d;
  static_assert(std::is_same_v<decltype(d.num_actions), float>);
  static_assert(std::is_same_v<decltype(d.num_states), float>);
  static_assert(std::is_same_v<decltype(d.min_state_range), std::vector<float>>);
  static_assert(std::is_same_v<decltype(d.title), std::string>);
  rl_msgs::RLEnvSeedExperience s;
  static_assert(std::is_same_v<decltype(s.action), int32_t>);
  rl_msgs::RLExperimentInfo info;
  static_assert(std::is_same_v<decltype(info.episode_reward), float>);
  EXPECT_EQ(std::string(ros::message_traits::DataType<rl_msgs::RLStateReward>::value()),
            "rl_msgs/RLStateReward");
}

/**
 * spinUntil: the wait loop of the suite's rostests and ROS tools. Spins the global callback
 * queue until `done()` holds, `seconds` of wall time pass or ROS shuts down; returns done().
 */
#pragma once

#include <ros/ros.h>

#include <functional>

namespace rl_common {

inline bool spinUntil(const std::function<bool()>& done, double seconds) {
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(seconds);
  while (!done() && ros::WallTime::now() < end && ros::ok()) {
    ros::spinOnce();
    ros::WallDuration(0.005).sleep();
  }
  return done();
}

}  // namespace rl_common

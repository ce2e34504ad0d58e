// CymbalHitDetector: one hit per rise above the threshold, knocks ignored, the flash fading.
#include "nao_interface/env/cymbal_hit_detector.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "nao_interface/sensors/microphone_model.h"

using namespace nao_interface;

TEST(CymbalHitDetector, OneHitPerRiseAboveTheThreshold) {
  CymbalHitDetector d({800.0, 0.5});
  EXPECT_FALSE(d.onEnergy(20.0, 1.0));   // silence
  EXPECT_FALSE(d.onEnergy(400.0, 1.1));  // a knock
  EXPECT_EQ(d.hits(), 0);
  EXPECT_TRUE(d.onEnergy(3000.0, 1.2));
  EXPECT_FALSE(d.onEnergy(2000.0, 1.25));  // still ringing: the same hit
  EXPECT_FALSE(d.onEnergy(900.0, 1.3));
  EXPECT_FALSE(d.onEnergy(100.0, 1.4));
  EXPECT_TRUE(d.onEnergy(1500.0, 2.0));  // a second hit
  EXPECT_EQ(d.hits(), 2);
}

TEST(CymbalHitDetector, FlashIsOneAtTheHitAndFades) {
  CymbalHitDetector d({800.0, 0.5});
  EXPECT_EQ(d.flash(0.0), 0.0);  // nothing heard yet
  d.onEnergy(3000.0, 10.0);
  EXPECT_DOUBLE_EQ(d.flash(10.0), 1.0);
  EXPECT_NEAR(d.flash(10.25), 0.5, 1e-9);
  EXPECT_EQ(d.flash(10.5), 0.0);
  EXPECT_EQ(d.flash(20.0), 0.0);
}

TEST(CymbalHitDetector, TellsTheSimulatedCymbalFromAKnock) {
  // The default threshold against the microphone model's sounds at full strength.
  MicrophoneModel mic(MicrophoneConfig{}, 5);
  mic.knock(0.0, 1.0);
  mic.cymbalHit(1.0, 1.0);
  CymbalHitDetector d;
  const double dt = mic.bufferDuration();
  long hitsBeforeCymbal = -1;
  for (double t = 0.0; t < 2.0; t += dt) {
    if (t < 1.0 && t + dt > 1.0) hitsBeforeCymbal = d.hits();
    const double e =
        audioEnergy(mic.buffer(t), MicrophoneModel::kChannels, MicrophoneModel::kFrontChannel);
    d.onEnergy(e, t);
  }
  EXPECT_EQ(hitsBeforeCymbal, 0);
  EXPECT_EQ(d.hits(), 1);
}

TEST(CymbalHitDetector, RejectsBadOptions) {
  EXPECT_THROW(CymbalHitDetector({-1.0, 0.5}), std::invalid_argument);
  EXPECT_THROW(CymbalHitDetector({800.0, 0.0}), std::invalid_argument);
}

// MicrophoneModel: buffer layout, energy levels of silence, knocks and cymbal hits, seeding.
#include "nao_interface/sensors/microphone_model.h"

#include <gtest/gtest.h>

using namespace nao_interface;

TEST(MicrophoneModel, BufferLayoutAndSilence) {
  MicrophoneModel mic({}, 1);
  const auto b = mic.buffer(0.0);
  EXPECT_EQ(b.size(), 2048u * 4u);
  EXPECT_EQ(MicrophoneModel::channelMap().size(), 4u);
  const double e = audioEnergy(b, 4, MicrophoneModel::kFrontChannel);
  EXPECT_NEAR(e, 0.8 * 25.0, 3.0);  // mean |N(0, 25)|
}

TEST(MicrophoneModel, CymbalIsLoudKnockIsQuiet) {
  MicrophoneModel mic({}, 2);
  mic.cymbalHit(0.0, 1.0);
  const double cymbal = audioEnergy(mic.buffer(0.0), 4, MicrophoneModel::kFrontChannel);
  EXPECT_GT(cymbal, 2000.0);  // "well above 800"
  EXPECT_LT(cymbal, 4000.0);
  MicrophoneModel mic2({}, 3);
  mic2.knock(0.0, 1.0);
  const double knock = audioEnergy(mic2.buffer(0.0), 4, MicrophoneModel::kFrontChannel);
  EXPECT_GT(knock, 100.0);
  EXPECT_LT(knock, 800.0);
  // The cymbal rings on and dies away.
  const double later = audioEnergy(mic.buffer(0.5), 4, MicrophoneModel::kFrontChannel);
  EXPECT_LT(later, cymbal / 3);
}

TEST(MicrophoneModel, SameSeedSameSamples) {
  MicrophoneModel a({}, 7), b({}, 7), c({}, 8);
  EXPECT_EQ(a.buffer(0.0), b.buffer(0.0));
  EXPECT_NE(a.buffer(0.1), c.buffer(0.1));
}

TEST(MicrophoneModel, EnergyChecksItsArguments) {
  const std::vector<std::int16_t> d = {100, -200, 300, -400, 0, 0, 0, 0};
  EXPECT_DOUBLE_EQ(audioEnergy(d, 4, 1), 100.0);  // (|-200| + |0|) / 2
  EXPECT_THROW(audioEnergy(d, 4, 4), std::invalid_argument);
  EXPECT_THROW(audioEnergy({1, 2, 3}, 2, 0), std::invalid_argument);
}

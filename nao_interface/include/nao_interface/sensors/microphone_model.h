/**
 * MicrophoneModel: the Nao's four microphones as the driver delivers them
 * (naoqi_bridge_msgs/AudioBuffer: 48 kHz, 4 interleaved int16 channels, buffers of 2048
 * frames as ALAudioDevice sends them; shared/spec/NAO.md §2.1), with the sounds of the
 * paper's scene (§5.2): a cymbal hit, a quieter knock when the arm hits the body or the
 * floor, and a small noise floor otherwise.
 *
 * A sound is a burst of Gaussian noise with amplitude A and an exponential decay,
 * s(t) = A exp(-(t - t0) / tau) N(0, 1), heard on every microphone (the front one fully,
 * the others at 80 %), plus independent floor noise N(0, floorNoise) per channel. With the
 * energy of a buffer defined as the mean absolute sample of one channel (audio_energy.h), a
 * cymbal hit gives energies of about 1500-4000, a knock a few hundred and silence about 20.
 * All noise comes from the model's own seeded rl_common::Random.
 */
#pragma once

#include <cstdint>
#include <vector>

#include "rl_common/random.h"

namespace nao_interface {

struct MicrophoneConfig {
  int sampleRate = 48000;
  int framesPerBuffer = 2048;
  double floorNoise = 25.0;         ///< std of the background noise (int16 units)
  double cymbalAmplitude = 4200.0;  ///< std of a full-speed cymbal hit at its start
  double cymbalDecay = 0.35;        ///< seconds
  double knockAmplitude = 550.0;    ///< std of a full-speed knock on the body or floor
  double knockDecay = 0.06;         ///< seconds
};

class MicrophoneModel {
 public:
  /// Channel layout of the buffers: left, right, front, rear microphones
  /// (AudioBuffer CHANNEL_FRONT_LEFT, CHANNEL_FRONT_RIGHT, CHANNEL_FRONT_CENTER,
  /// CHANNEL_REAR_CENTER, one of the driver's two maps).
  static const std::vector<std::uint8_t>& channelMap();
  /// Index of the front microphone in a frame.
  static constexpr int kFrontChannel = 2;
  static constexpr int kChannels = 4;

  MicrophoneModel(MicrophoneConfig config, std::uint64_t seed);

  /// A cymbal hit at time `t` (s); `strength` in [0, 1] scales its amplitude.
  void cymbalHit(double t, double strength);
  /// A knock of the arm on the body or floor at time `t`.
  void knock(double t, double strength);

  /// The buffer covering [start, start + bufferDuration()), interleaved frames of kChannels.
  std::vector<std::int16_t> buffer(double start);
  double bufferDuration() const {
    return static_cast<double>(config_.framesPerBuffer) / config_.sampleRate;
  }
  const MicrophoneConfig& config() const { return config_; }

 private:
  struct Sound {
    double start, amplitude, decay;
  };
  MicrophoneConfig config_;
  rl_common::Random random_;
  std::vector<Sound> sounds_;
};

/// Energy of one channel of an interleaved int16 buffer: the mean absolute sample value, in
/// [0, 32768] like NAOqi's ALAudioDevice.getFrontMicEnergy(). Throws std::invalid_argument if
/// `channel` is not in [0, channels) or the buffer is not whole frames.
double audioEnergy(const std::vector<std::int16_t>& data, int channels, int channel);

}  // namespace nao_interface

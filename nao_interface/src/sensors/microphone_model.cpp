#include "nao_interface/sensors/microphone_model.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace nao_interface {

const std::vector<std::uint8_t>& MicrophoneModel::channelMap() {
  static const std::vector<std::uint8_t> map = {0, 2, 1, 4};
  return map;
}

MicrophoneModel::MicrophoneModel(MicrophoneConfig config, std::uint64_t seed)
    : config_(config), random_(seed) {
  if (config_.sampleRate <= 0 || config_.framesPerBuffer <= 0) {
    throw std::invalid_argument(
        "MicrophoneModel::MicrophoneModel(): sample rate and buffer size must be positive");
  }
}

void MicrophoneModel::cymbalHit(double t, double strength) {
  sounds_.push_back(
      {t, config_.cymbalAmplitude * std::clamp(strength, 0.0, 1.0), config_.cymbalDecay});
}

void MicrophoneModel::knock(double t, double strength) {
  sounds_.push_back(
      {t, config_.knockAmplitude * std::clamp(strength, 0.0, 1.0), config_.knockDecay});
}

std::vector<std::int16_t> MicrophoneModel::buffer(double start) {
  // Forget sounds that have died away (below 1 % of their start) before this buffer.
  sounds_.erase(std::remove_if(sounds_.begin(), sounds_.end(),
                               [start](const Sound& s) {
                                 return start - s.start > s.decay * std::log(100.0);
                               }),
                sounds_.end());
  const int frames = config_.framesPerBuffer;
  std::vector<std::int16_t> data(static_cast<std::size_t>(frames) * kChannels);
  const double gains[kChannels] = {0.8, 0.8, 1.0, 0.8};
  for (int f = 0; f < frames; ++f) {
    const double t = start + static_cast<double>(f) / config_.sampleRate;
    double envelope = 0.0;
    for (const Sound& s : sounds_) {
      if (t >= s.start) {
        const double e = s.amplitude * std::exp(-(t - s.start) / s.decay);
        envelope = std::sqrt(envelope * envelope + e * e);  // independent noises add in power
      }
    }
    const double source = envelope > 0.0 ? envelope * random_.normal() : 0.0;
    for (int c = 0; c < kChannels; ++c) {
      const double x = gains[c] * source + random_.normal(0.0, config_.floorNoise);
      data[static_cast<std::size_t>(f) * kChannels + c] =
          static_cast<std::int16_t>(std::clamp(std::lround(x), -32768L, 32767L));
    }
  }
  return data;
}

double audioEnergy(const std::vector<std::int16_t>& data, int channels, int channel) {
  if (channels <= 0 || channel < 0 || channel >= channels) {
    throw std::invalid_argument("audioEnergy(): channel " + std::to_string(channel) +
                                " outside [0, " + std::to_string(channels) + ")");
  }
  if (data.size() % static_cast<std::size_t>(channels) != 0) {
    throw std::invalid_argument("audioEnergy(): " + std::to_string(data.size()) +
                                " samples are not whole frames of " + std::to_string(channels) +
                                " channels");
  }
  const std::size_t frames = data.size() / channels;
  if (frames == 0) return 0.0;
  double sum = 0.0;
  for (std::size_t f = 0; f < frames; ++f)
    sum += std::abs(static_cast<int>(data[f * channels + channel]));
  return sum / static_cast<double>(frames);
}

}  // namespace nao_interface

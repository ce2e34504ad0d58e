#include "nao_interface/env/cymbal_hit_detector.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace nao_interface {

CymbalHitDetector::CymbalHitDetector(CymbalHitOptions options) : options_(options) {
  if (!(options_.threshold >= 0.0) || !(options_.flashTime > 0.0)) {
    throw std::invalid_argument(
        "CymbalHitDetector::CymbalHitDetector(): threshold must be >= 0 and flashTime > 0");
  }
}

bool CymbalHitDetector::onEnergy(double energy, double t) {
  const bool loud = energy > options_.threshold;
  const bool hit = loud && !ringing_;
  ringing_ = loud;
  if (hit) {
    lastHit_ = t;
    ++hits_;
  }
  return hit;
}

double CymbalHitDetector::flash(double now) const {
  if (hits_ == 0) return 0.0;
  const double age = now - lastHit_;
  if (age < 0.0) return 1.0;
  return std::clamp(1.0 - age / options_.flashTime, 0.0, 1.0);
}

}  // namespace nao_interface

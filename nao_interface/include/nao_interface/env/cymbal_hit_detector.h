/**
 * CymbalHitDetector: tells cymbal hits from the microphone energy the driver's audio gives
 * (one value per audio buffer, audio_energy.h), for the rviz view of the Nao arm (a flash on
 * the cymbal marker), so it works on a real robot's driver as on nao_arm_sim.
 *
 * A hit starts when a buffer's energy rises above `threshold` after a buffer at or below it (a
 * cymbal rings for several buffers: one hit, not one per buffer). The default threshold lies
 * between a knock on the body or the floor (a few hundred) and a cymbal hit (about 1500-4000;
 * MicrophoneModel). The flash is 1 at the hit and falls linearly to 0 over `flashTime` seconds.
 */
#pragma once

namespace nao_interface {

struct CymbalHitOptions {
  double threshold = 800.0;  ///< energy (mean absolute int16 sample) above which the cymbal rang
  double flashTime = 0.6;    ///< seconds the flash takes to fade
};

class CymbalHitDetector {
 public:
  /// Throws std::invalid_argument unless threshold >= 0 and flashTime > 0.
  explicit CymbalHitDetector(CymbalHitOptions options = {});

  /// One audio buffer's energy, heard at time `t` (seconds); true if it starts a hit.
  bool onEnergy(double energy, double t);
  /// The flash brightness at `now`, in [0, 1]: 1 at the last hit, 0 from flashTime after it.
  double flash(double now) const;
  /// Hits heard so far.
  long hits() const { return hits_; }

  const CymbalHitOptions& options() const { return options_; }

 private:
  CymbalHitOptions options_;
  bool ringing_ = false;
  double lastHit_ = 0.0;
  long hits_ = 0;
};

}  // namespace nao_interface

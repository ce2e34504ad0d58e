/**
 * Renderable: an environment that can draw its current state as an image, for a person
 * watching a run (the env node's `--render`, shown in rviz). Optional, like rl_common::TrueModel:
 * an environment offers it by also deriving from this class, and its registry entry carries
 * kRenderFact so programs can say which environments have a view.
 */
#pragma once

#include "rl_env/render/rgb_image.h"

namespace rl_env {

/// The registry fact of the environments that are Renderable.
inline constexpr const char* kRenderFact = "render";

class Renderable {
 public:
  virtual ~Renderable() = default;
  /// The current state, with `lastAction` (the action that led to it, -1 for none) named on
  /// the image. Every call gives an image of the same size.
  virtual RgbImage render(int lastAction) const = 0;
};

}  // namespace rl_env

// nao_arm_survey: walks the 8-degree shoulder grid reachable from the start pose and prints,
// per cell, the hand position, pink pixels, bumper and cymbal contact; then a summary. Used to
// check the scene (head pose, bumper reach, cymbal place) against the paper's domain.
#include <cmath>
#include <iostream>

#include "nao_interface/sim/nao_arm_simulation.h"

int main(int argc, char** argv) {
  using namespace nao_interface;
  NaoArmSimConfig config;
  config.stochastic = false;
  rl_common::OptionParser parser("nao_arm_survey", "[options]");
  addSimOptions(parser, &config);
  bool verbose = false;
  parser.flag("verbose", &verbose, true, "print every cell");
  try {
    if (!parser.parse(argc, argv)) {
      std::cout << parser.help();
      return 0;
    }
  } catch (const std::exception& e) {
    std::cerr << "nao_arm_survey: " << e.what() << "\n";
    return 2;
  }
  NaoArmSimulation sim(config, 1);
  const double step = 8.0 * M_PI / 180.0;
  const auto& pj = sim.body().joint("RShoulderPitch");
  const auto& rj = sim.body().joint("RShoulderRoll");
  int cells = 0, visible = 0, pressed = 0, maxPink = 0;
  for (int i = -40; i <= 40; ++i) {
    const double p = config.startPitch + i * step;
    if (p < pj.lower - 1e-9 || p > pj.upper + 1e-9) continue;
    for (int j = -20; j <= 20; ++j) {
      const double r = config.startRoll + j * step;
      if (r < rj.lower - 1e-9 || r > rj.upper + 1e-9) continue;
      NaoArmSimulation s(config, 1);
      s.setTarget("RShoulderPitch", p, 1.0);
      s.setTarget("RShoulderRoll", r, 1.0);
      s.advance(1.0);
      const int pink = s.countPink();
      const Eigen::Vector3d h = s.handMm();
      ++cells;
      visible += pink > 0;
      pressed += s.bumperPressed();
      maxPink = std::max(maxPink, pink);
      if (verbose || s.bumperPressed() || pink > 0) {
        std::cout << "pitch " << p * 180 / M_PI << " roll " << r * 180 / M_PI << " hand ("
                  << std::lround(h.x()) << ", " << std::lround(h.y()) << ", " << std::lround(h.z())
                  << ") pink " << pink << (s.bumperPressed() ? " BUMPER" : "") << "\n";
      }
    }
  }
  std::cout << cells << " cells, " << visible << " with pink in view (max " << maxPink << "), "
            << pressed << " pressing the bumper\n";
  return 0;
}

#include "rl_env/env/environment_registry.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "rl_env/env/cart_pole.h"
#include "rl_env/env/energy_rooms.h"
#include "rl_env/env/four_rooms.h"
#include "rl_env/env/fuel_rooms.h"
#include "rl_env/env/light_world.h"
#include "rl_env/env/mountain_car.h"
#include "rl_env/env/robot_car_vel.h"
#include "rl_env/env/stocks.h"
#include "rl_env/env/taxi.h"
#include "rl_env/env/two_rooms.h"

namespace rl_env {

namespace {

using Options = const EnvironmentOptions&;
using Ptr = std::unique_ptr<rl_common::Environment>;

const std::vector<std::string> kLagOptions = {"lag", "nolag"};

}  // namespace

void addBuiltinEnvironments(EnvironmentCatalog& catalog) {
  EnvironmentRegistry& r = catalog.registry();
  r.add("taxi",
        [](Options o, std::uint64_t seed) -> Ptr {
          return std::make_unique<Taxi>(seed, o.stochastic);
        },
        "Dietterich's 5x5 taxi: pick the passenger up and put them down at the destination",
        {kTrueModelFact});
  r.add("tworooms",
        [](Options o, std::uint64_t seed) -> Ptr {
          return std::make_unique<TwoRooms>(seed, o.stochastic, o.delay);
        },
        "5x11 two-room gridworld with a doorway; --delay k delays actions by k steps",
        {kTrueModelFact}, {"delay"});
  r.add("fourrooms",
        [](Options o, std::uint64_t seed) -> Ptr {
          return std::make_unique<FourRooms>(seed, o.stochastic);
        },
        "Sutton, Precup & Singh's 11x11 four-room gridworld, goal in the south-east room",
        {kTrueModelFact});
  r.add(
      "energy",
      [](Options o, std::uint64_t seed) -> Ptr {
        return std::make_unique<EnergyRooms>(seed, o.stochastic);
      },
      "four rooms with an energy level recharged on four squares");
  r.add("fuelworld",
        [](Options o, std::uint64_t seed) -> Ptr {
          return std::make_unique<FuelRooms>(seed, o.stochastic, o.highvar);
        },
        "21x31 navigation with fuel stations of varying cost on two rows; --highvar", {},
        {"highvar"});
  r.add("mcar",
        [](Options o, std::uint64_t seed) -> Ptr {
          return std::make_unique<MountainCar>(seed, o.stochastic, o.delay);
        },
        "mountain car; --delay k delays observations by k steps", {}, {"delay"});
  r.add(
      "cartpole",
      [](Options o, std::uint64_t seed) -> Ptr {
        return std::make_unique<CartPole>(seed, o.stochastic);
      },
      "cart-pole balancing (Barto, Sutton & Anderson 1983)");
  r.add(
      "car2to7",
      [](Options o, std::uint64_t seed) -> Ptr {
        return std::make_unique<RobotCarVel>(seed, RobotCarVel::Task::kUp2To7, o.lag);
      },
      "car velocity control from 2 to 7 m/s with throttle and brake; --lag", {}, kLagOptions);
  r.add(
      "car7to2",
      [](Options o, std::uint64_t seed) -> Ptr {
        return std::make_unique<RobotCarVel>(seed, RobotCarVel::Task::kDown7To2, o.lag);
      },
      "car velocity control from 7 to 2 m/s with throttle and brake; --lag", {}, kLagOptions);
  r.add(
      "carrandom",
      [](Options o, std::uint64_t seed) -> Ptr {
        return std::make_unique<RobotCarVel>(seed, RobotCarVel::Task::kRandom, o.lag);
      },
      "car velocity control between random velocities; --lag", {}, kLagOptions);
  r.add("stocks",
        [](Options o, std::uint64_t seed) -> Ptr {
          return std::make_unique<Stocks>(seed, o.stochastic, o.nsectors, o.nstocks);
        },
        "factored stock trading (Strehl et al. 2007); --nsectors, --nstocks", {},
        {"nsectors", "nstocks"});
  r.add("lightworld",
        [](Options o, std::uint64_t seed) -> Ptr {
          return std::make_unique<LightWorld>(seed, o.stochastic);
        },
        "the TEXPLORE-VANIR paper's 4-room key/lock/door world with light sensors",
        {kTrueModelFact, kRenderFact});
}

void EnvironmentCatalog::addOption(ExtraOption option) {
  for (const ExtraOption& o : extraOptions_) {
    if (o.name == option.name) {
      throw std::invalid_argument("EnvironmentCatalog::addOption(): --" + option.name +
                                  " is declared already");
    }
  }
  if (std::find(option.choices.begin(), option.choices.end(), option.defaultValue) ==
      option.choices.end()) {
    throw std::invalid_argument("EnvironmentCatalog::addOption(): the default of --" + option.name +
                                " is not one of its choices");
  }
  extraOptions_.push_back(std::move(option));
}

std::unique_ptr<rl_common::Environment> EnvironmentCatalog::make(
    const EnvironmentOptions& options) const {
  return registry_.create(options.env, options, options.seed);
}

std::string EnvironmentCatalog::trueModelNames() const {
  return rl_common::joinNames(registry_.namesWith(kTrueModelFact));
}

std::string EnvironmentCatalog::renderNames() const {
  return rl_common::joinNames(registry_.namesWith(kRenderFact));
}

const EnvironmentCatalog& builtinEnvironments() {
  static const EnvironmentCatalog catalog = [] {
    EnvironmentCatalog c;
    addBuiltinEnvironments(c);
    return c;
  }();
  return catalog;
}

}  // namespace rl_env

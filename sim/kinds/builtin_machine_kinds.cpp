// The built-in machine kinds, one line each, in the order messages list them.
#include "kinds/machine_registry.hpp"
#include "kinds/machines/cartesian.hpp"
#include "kinds/machines/corexy_plotter.hpp"
#include "kinds/machines/polar_turntable.hpp"

namespace stepdance::sim {

std::vector<const MachineKind*> builtin_machine_kinds() {
  return {
      &corexy_plotter_kind(),
      &cartesian_kind(),
      &polar_turntable_kind(),
  };
}

}  // namespace stepdance::sim

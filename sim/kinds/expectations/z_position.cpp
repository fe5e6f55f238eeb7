// Expectation kind "z_mm": z_mm = z, tolerance_mm — the machine's final z (a cartesian machine
// with a 'z' socket).
#include "kinds/expectations/z_position.hpp"

#include <cmath>
#include <optional>

#include "kinds/expectations/expectation_parts.hpp"
#include "kinds/machines/cartesian.hpp"
#include "models/machine.hpp"

namespace stepdance::sim {
namespace {

bool read(ExpectationReading& reading) {
  ZPositionCheck check;
  const auto z = reading.reader.number("z_mm");
  bool ok = z.has_value() && std::isfinite(*z);
  if (z && !ok) reading.reader.error("z_mm", "'z_mm' must be a finite number");
  if (ok) check.z_mm = *z;
  const auto& machine = reading.context.scenario.machine;
  const auto* cartesian = machine ? machine->settings_as<CartesianConfig>() : nullptr;
  if (machine && (cartesian == nullptr || !cartesian->z)) {
    reading.reader.error("z_mm", "'z_mm' needs a cartesian [machine] with a 'z' socket");
    ok = false;
  }
  const bool tolerance_ok = read_tolerance(reading, "z_mm", check.tolerance_mm);
  reading.settings = check;
  return tolerance_ok && ok;
}

ExpectationResult check(const scenario::Expectation& expectation, const FinishedRun& run) {
  const auto& check = settings_of<ZPositionCheck>(expectation);
  const std::optional<double> z = run.machine() ? run.machine()->axis_mm(MachineAxis::kZ) : std::nullopt;
  if (!z) return {false, "z_mm: the machine has no z axis"};
  return {std::fabs(*z - check.z_mm) <= check.tolerance_mm,
          "z at " + millimetres(check.z_mm) + " mm ± " + millimetres(check.tolerance_mm) + ": got " + millimetres(*z)};
}

}  // namespace

const ExpectationKind& z_position_expectation() {
  static const ExpectationKind kind{"z_mm", {"tolerance_mm"}, read, check};
  return kind;
}

}  // namespace stepdance::sim

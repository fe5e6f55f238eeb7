// Why an image stopped running: the report a crash, a fault or a stall gives.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "common/sim_time.hpp"

namespace stepdance::sim::image {

/// Exit statuses of a run that a stop ends (docs/simulator.md, "When a sketch crashes or hangs").
constexpr int kExitCrash = 5;
constexpr int kExitNoProgress = 6;

/// Why the image stopped running.
struct ImageStop {
  enum class Kind {
    kHardFault,         ///< a fault the firmware could not take as itself (escalated), a BKPT
    kBusFault,          ///< an access to unmapped memory, a block answering with a bus error, a gated block
    kUsageFault,        ///< undefined instruction, divide by zero (CCR.DIV_0_TRP), bad EXC_RETURN
    kMemManage,         ///< an access an enabled MPU region forbids
    kStackOverflow,     ///< the stack pointer went below the stack's bottom (into data)
    kNoProgress,        ///< a branch to itself that no interrupt can ever leave
    kUnmodelledAccess,  ///< a register nobody modelled (the run stops; never a silent zero)
    kBadImage,          ///< the image cannot start (no vector, entry outside memory)
  };
  Kind kind = Kind::kBadImage;
  std::string what;                    ///< one line, e.g. "BusFault: read of 4 bytes at 0x… (…): …"
  uint32_t pc = 0;                     ///< the faulting instruction (the stacked PC, not the handler's)
  std::string symbol;                  ///< the function containing pc, "" if none
  std::vector<std::string> backtrace;  ///< "0x60001234 setup()+0x12", innermost first
  int exit_code = kExitCrash;          ///< kExitCrash, or kExitNoProgress for kNoProgress
  SimTime time_ns = 0;                 ///< simulated time of the stop

  /// The kind's name: "HardFault", "BusFault", … "unmodelled access", "bad image".
  static const char* kind_name(Kind kind);
};

}  // namespace stepdance::sim::image

// The emulated Cortex-M7 of a Teensy 4.x: a firmware ELF running instruction by instruction
// (Debian's unicorn) inside the simulator's discrete-event time.
#pragma once

#include <array>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "common/sim_time.hpp"
#include "image/chip/chip_context.hpp"
#include "image/chip/peripheral_bus.hpp"
#include "image/cpu/core_registers.hpp"
#include "image/cpu/elf_image.hpp"
#include "image/cpu/exception_state.hpp"
#include "image/cpu/image_stop.hpp"
#include "image/rt1062/teensy_model.hpp"
#include "kernel/scheduler/event.hpp"

struct uc_struct;

namespace stepdance::sim::image {

class BlockCache;
class SystemBlocks;
struct ThumbBlock;
struct BlockAccess;

/// One i.MX RT1062 core running one firmware image.
///
/// Memory map (IMXRT1060RM rev 3, 2.2 "memory map"): FlexSPI flash at 0x60000000 (2 MB on a
/// Teensy 4.0, 8 MB on a 4.1; read and execute only; erased, 0xFF, where the image does not
/// fill it), ITCM at 0x00000000 (512 KB), DTCM at
/// 0x20000000 (512 KB), OCRAM at 0x20200000 (1 MB: OCRAM2 and the FlexRAM's OCRAM banks) — the
/// FlexRAM's largest sizes, whatever IOMUXC_GPR14/16/17 say. Peripherals (0x40000000–0x7FFFFFFF
/// outside the flash) reach bus(); the Cortex-M7's system space (0xE0000000–0xE00FFFFF) reaches
/// the NVIC, SCB, SysTick, DWT, MPU, cache, FPU and debug registers modelled here. Any other
/// address is unmapped: a BusFault.
///
/// Time: one instruction retired = one core clock cycle (CPI 1). The CPU runs as one scheduler
/// event: each firing runs from now until the next queued event (at most kMaxSliceNs), then
/// requeues itself at the time its instructions reached. The emulator counts instructions per
/// translation block, so a run ends at the first block boundary at or after its limit: it may
/// overshoot by the rest of one block (a block ends at every branch and holds at most 512
/// instructions). Inside a register access, now_ns()/cycles() are the accessing instruction's:
/// the block's start plus the instructions before it in the block (see docs/simulator.md for
/// how the instruction is found).
///
/// With nothing else queued, one run covers at most kMaxSliceNs: the core may then be up to that
/// far ahead of a scheduler that stops with nothing queued.
///
/// Exceptions are taken at block boundaries: an interrupt pended during a block (by an event
/// between runs, or by a register access) is entered before the next block runs. Nested ones
/// preempt by group priority; PRIMASK, FAULTMASK and BASEPRI mask; a pending interrupt that a
/// mask holds off is taken at the first block boundary after the mask drops. Entry and return
/// take no cycles. WFI/WFE sleep until something pends an exception.
///
/// Faults (ImageStop) stop the image at the moment its fault handler would be entered; the
/// handler does not run. on_stop listeners hear it once, after the run ends.
///
/// Context: the simulator's thread only.
class ImageChip : public ChipContext {
 public:
  /// Longest single CPU run without an event in the queue, ns.
  static constexpr SimTime kMaxSliceNs = 100 * kMicrosecond;
  /// Core clock the boot ROM leaves for a FlexSPI boot: 396 MHz (IMXRT1060RM rev 3, 9.5.2, the
  /// clocks the boot ROM sets; Teensyduino 1.59's teensy4/clockspeed.c starts F_CPU_ACTUAL at
  /// 396000000 for the same reason). The CCM model sets the clock the image then chooses.
  static constexpr uint32_t kBootCoreClockHz = 396000000;

  ImageChip(Scheduler& scheduler, TeensyModel model);
  ~ImageChip() override;
  ImageChip(const ImageChip&) = delete;
  ImageChip& operator=(const ImageChip&) = delete;

  /// Loads `elf_path`: PT_LOAD segments by physical address into flash, ITCM, DTCM or OCRAM;
  /// symbols kept for names. False with `error` (one line) for a file that is not a 32-bit ARM
  /// executable or has a segment outside those memories; nothing is loaded then. Before power_on.
  bool load(const std::string& elf_path, std::string& error);
  /// The peripheral space: the board and the RT1062 models add their blocks before power_on.
  PeripheralBus& bus() { return bus_; }
  /// Boots as the ROM does a FlexSPI image (IMXRT1060RM rev 3, 9.7: it jumps to the IVT's entry,
  /// which is the ELF's entry): PC = the ELF entry, SP = the top of DTCM (images set SP first
  /// thing, as Teensyduino's ResetHandler does); then the CPU runs as a scheduler event from
  /// `time_ns`. A stop (kBadImage) if nothing is loaded or the entry is outside memory.
  void power_on(SimTime time_ns);
  /// The address the boot ROM starts the image at: the IVT's entry when the ELF's entry is the
  /// IVT (Teensyduino's images), else the ELF's entry.
  uint32_t boot_entry();
  /// Called once when the image stops (fault, stall, unmodelled register). Several may listen.
  void on_stop(std::function<void(const ImageStop&)> listener) { stop_listeners_.push_back(std::move(listener)); }
  bool stopped() const { return stopped_; }
  /// The stop's report, or null while the image runs.
  const ImageStop* stop_report() const { return stopped_ ? stop_.get() : nullptr; }
  /// Calls `listener` each time the core starts a block at `address` (a function's entry, e.g.
  /// `setup`), with the instructions retired before it and the time. Costs one comparison per
  /// block per watch. Before or after power_on.
  using ReachListener = std::function<void(uint64_t instructions, SimTime time_ns)>;
  void on_reach(uint32_t address, ReachListener listener) {
    watches_.push_back({address & ~1u, std::move(listener), ~uint64_t{0}});
  }
  /// The CCM model calls this when ARM_PLL or the dividers change; time from now on runs at it.
  void set_core_clock_hz(uint32_t hz);
  /// Instructions retired since power_on (core cycles less those slept in WFI/WFE).
  uint64_t instructions() const { return retired_ - slept_; }

  /// Instructions spent in one exception's handler, nested ones excluded (each instruction
  /// counts for the exception whose handler was running it), and how often it was entered.
  struct HandlerCost {
    uint64_t entries = 0;
    uint64_t instructions = 0;
    SimTime first_entry_ns = -1;  ///< when the handler was first entered (-1: never)
  };
  HandlerCost handler_cost(unsigned exception_number) const;
  const ElfSymbols& symbols() const { return image_.symbols; }
  /// The exception the core is handling (IPSR), 0 in thread mode.
  unsigned current_exception() const { return current_exception_; }
  /// The core's own registers (0xE0000000–0xE00FFFFF): the CPU's accesses go here; tests
  /// drive them directly.
  PeripheralBus& system_bus() { return system_bus_; }
  /// The system-space state (for tests and reports).
  const CoreRegisters& core_registers() const { return core_; }
  ExceptionState& exceptions() { return exceptions_; }
  /// Reads a core register (a uc_arm_reg number) — for tests and reports.
  uint32_t read_register(int uc_register) const;

  // ---- ChipContext ----
  SimTime now_ns() const override;
  uint64_t cycles() const override;
  uint32_t core_clock_hz() const override { return core_hz_; }
  Scheduler& scheduler() override { return scheduler_; }
  void set_irq_level(unsigned irq, bool high) override;
  void stop_cpu_run() override { end_run_ = true; }
  bool read_memory(uint32_t address, void* data, size_t bytes) override;
  bool write_memory(uint32_t address, const void* data, size_t bytes) override;

  /// Pends exception `number` (SysTick, PendSV, NMI from the system blocks). Context: any.
  void pend_exception(unsigned number);
  /// Simulated time of core cycle `cycle` at the current clock (for timers that count cycles).
  SimTime time_of_cycle(uint64_t cycle) const;

  /// A debugger's call (cpu_call.cpp): runs the image's function at `function` (a Thumb address)
  /// with `args` in R0–R3 until it returns, below the current stack pointer, with time stopped,
  /// nothing counted and no exception taken; every core register is put back afterwards. A
  /// function pointer kCalloutAddress | 1 handed to it calls `on_callout` (R0–R3 and the stack
  /// are the callout's arguments: read them with read_register and read_memory) and returns.
  /// False with `error` if the function faults, touches a register, runs past kMaxCallInstructions
  /// or the image is running, stopped or not powered. Context: between runs.
  static constexpr uint32_t kCallReturnAddress = 0x9FFF0000;
  static constexpr uint32_t kCalloutAddress = 0x9FFF0010;
  static constexpr uint64_t kMaxCallInstructions = 10000000;
  bool call_function(uint32_t function, const std::array<uint32_t, 4>& args, const std::function<void()>& on_callout,
                     std::string& error);

 private:
  struct CpuEvent : Event {
    explicit CpuEvent(ImageChip* owner) : Event(&fire), chip(owner) {}
    static void fire(Event& event, Scheduler& scheduler);
    ImageChip* chip;
  };
  struct PendingFault;

  // memory map (cpu_memory.cpp)
  void map_memory();
  bool place_segment(const ElfSegment& segment, std::string& error);
  /// One register window the emulator calls back for (the two peripheral windows, the system space).
  struct MmioWindow {
    ImageChip* chip = nullptr;
    uint32_t base = 0;
    bool system = false;
  };
  bool in_memory(uint32_t address, size_t bytes) const;
  /// RAM and flash: base, size and protection without an MPU (UC_PROT_*).
  struct MemoryWindow {
    uint32_t base;
    uint32_t size_bytes;
    uint32_t natural;
  };
  std::vector<MemoryWindow> memories() const;

  // MPU (cpu_mpu.cpp)
  uint32_t page_protection(uint64_t page, uint64_t page_bytes, uint32_t natural) const;
  void apply_mpu();
  void protection_fault(int type, uint32_t address, int size);
  static uint64_t mmio_read(uc_struct* uc, uint64_t offset, unsigned size, void* user);
  static void mmio_write(uc_struct* uc, uint64_t offset, unsigned size, uint64_t value, void* user);
  void access(bool system, uint32_t address, unsigned size, bool is_write, uint32_t& value);
  uint32_t note_access_position(uint32_t address);
  bool could_access(const BlockAccess& access, uint32_t address) const;

  // debugger's calls (cpu_call.cpp)
  bool run_call(uint32_t pc, const std::function<void()>& on_callout, std::string& error);
  bool call_fetch(uint32_t address);
  void call_went_wrong(const std::string& what);

  // running (cpu_run.cpp)
  void run();
  void run_slice();
  void install_hooks();
  static void on_block(uc_struct* uc, uint64_t address, uint32_t size, void* user);
  bool block_must_stop(const ThumbBlock& block, uint32_t address);
  bool spin(uint32_t address);
  void sleep_until_interrupt();
  void wake();
  void shorten_run();
  uint64_t cycles_at(SimTime time_ns) const;
  Masks masks() const;

  // exceptions (exception_entry.cpp)
  bool take_pending_exception();
  void enter_exception(unsigned number, uint32_t return_pc);
  void activate(unsigned number);
  void return_from_exception(uint32_t exc_return);
  void unstack(const std::array<uint32_t, 26>& words, bool fp_frame, uint32_t sp_after, bool to_psp);
  bool stack_overflows(uint32_t sp) const;
  void stack_fault(uint32_t sp, uint32_t pc);
  void write_ipsr(unsigned number);
  static void on_interrupt(uc_struct* uc, uint32_t intno, void* user);

  // faults (cpu_faults.cpp)
  static bool on_unmapped(uc_struct* uc, int type, uint64_t address, int size, int64_t value, void* user);
  static bool on_invalid_instruction(uc_struct* uc, void* user);
  void fault(unsigned exception, const std::string& what, uint32_t pc);
  void raise_fault(ImageStop::Kind kind, const std::string& what, uint32_t pc);
  void finish_stop();
  std::vector<std::string> backtrace(uint32_t pc, uint32_t lr, uint32_t sp) const;
  uint32_t stack_limit() const;
  uint32_t compute_stack_limit() const;
  bool stack_pointer_overflowed(uint32_t address);
  void step_through_block();

  /// Once any code hook exists (uc_emu_start's own count adds one: step_through_block), unicorn
  /// 2.0.1 no longer puts the PC back at the start of a block the block hook stopped the run
  /// before (qemu/accel/tcg/cpu-exec.c syncs it only without UC_HOOK_CODE): the PC would be where
  /// it was last synchronised and the next run would repeat instructions already done. Puts it
  /// there (cpu_run.cpp).
  void restore_stopped_block_pc();

  Scheduler& scheduler_;
  TeensyModel model_;
  uc_struct* uc_ = nullptr;
  uint32_t flash_bytes_;
  ElfImage image_;
  bool loaded_ = false;
  PeripheralBus bus_;
  PeripheralBus system_bus_;
  std::unique_ptr<SystemBlocks> system_blocks_;
  std::unique_ptr<BlockCache> blocks_;
  std::array<MmioWindow, 3> windows_{};
  CoreRegisters core_;
  ExceptionState exceptions_;
  CpuEvent event_{this};
  std::vector<std::function<void(const ImageStop&)>> stop_listeners_;
  struct Watch {
    uint32_t address;
    ReachListener listener;
    uint64_t fired_at = ~uint64_t{0};  ///< retired_ at the last call
  };
  std::vector<Watch> watches_;

  // time
  uint32_t core_hz_ = kBootCoreClockHz;
  uint64_t base_cycle_ = 0;            ///< cycle count at which the current clock began
  SimTime base_ns_ = 0;                ///< … and its time
  uint64_t retired_ = 0;               ///< core cycles: instructions retired (counted at each block's start) and slept
  uint64_t block_start_ = 0;           ///< retired_ before the block running now
  uint64_t run_limit_ = 0;             ///< the run ends at the first block boundary at or past this
  const ThumbBlock* block_ = nullptr;  ///< the block running now
  size_t access_cursor_ = 0;           ///< next candidate access of block_ (note_access_position)
  uint32_t block_address_ = 0;
  bool in_run_ = false;
  bool in_access_ = false;  ///< inside a register access: cycles() is access_cycles_
  uint64_t access_cycles_ = 0;

  // run control
  bool end_run_ = false;      ///< stop_cpu_run() or a clock change: back to the scheduler at the next block
  bool recheck_ = false;      ///< something was pended or unmasked: take it at the next block
  bool we_stopped_ = false;   ///< the last emulator return was our own uc_emu_stop
  bool yielded_ = false;      ///< … or a YIELD hint: run on
  uint64_t slept_ = 0;        ///< cycles spent asleep (WFI, WFE)
  bool asleep_ = false;       ///< in WFI/WFE: no event queued until something pends
  bool check_masks_ = false;  ///< something pending is masked: re-check at every block
  bool stopped_ = false;
  bool powered_ = false;
  std::unique_ptr<ImageStop> stop_;  ///< a stop found inside a run, reported when it ends
  unsigned current_exception_ = 0;
  uint32_t mpu_applied_ = 0;  ///< core_.mpu_generation last applied to the pages
  mutable uint32_t stack_limit_generation_ = ~0u;
  mutable uint32_t stack_limit_ = 0;        ///< cached stack_limit() for that MPU generation
  bool check_sp_ = false;                   ///< the previous block lowered SP: check it at this one
  const ThumbBlock* step_block_ = nullptr;  ///< a block with a divide to run one instruction at a time
  uint32_t step_address_ = 0;
  bool stepping_ = false;
  std::array<HandlerCost, kExceptionCount> handler_costs_{};
  uint32_t block_stop_pc_ = 0;  ///< the block (| 1) the block hook stopped the run before, or 0
  bool calling_ = false;        ///< inside call_function
  uint64_t call_instructions_ = 0;
  uint32_t call_reached_ = 0;  ///< kCallReturnAddress or kCalloutAddress when the call stopped there
  std::string call_problem_;   ///< why the call went wrong ("" if it did not)
};

}  // namespace stepdance::sim::image

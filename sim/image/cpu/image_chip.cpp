// The emulated core: construction, loading, power-on, time and the ChipContext services.
#include "image/cpu/image_chip.hpp"

#include <unicorn/unicorn.h>

#include <stdexcept>

#include "image/cpu/block_cache.hpp"
#include "image/cpu/system_blocks.hpp"
#include "kernel/scheduler/scheduler.hpp"

namespace stepdance::sim::image {
namespace {

__extension__ using Wide = unsigned __int128;

/// Top of DTCM: the stack the core starts on (the boot ROM's own is in OCRAM; every image sets
/// SP itself first thing, as Teensyduino's ResetHandler does).
constexpr uint32_t kBootStack = 0x20080000;

bool read_code(void* context, uint32_t address, uint8_t* bytes, size_t size) {
  return static_cast<ImageChip*>(context)->read_memory(address, bytes, size);
}

}  // namespace

ImageChip::ImageChip(Scheduler& scheduler, TeensyModel model)
    : scheduler_(scheduler), model_(model), flash_bytes_(model == TeensyModel::kTeensy41 ? 8u << 20 : 2u << 20) {
  // Thumb only, not UC_MODE_MCLASS: unicorn 2.0.1 forces a Cortex-M33 (single-precision FPU,
  // so every double-precision instruction is undefined) on any engine opened with MCLASS,
  // whatever model uc_ctl_set_cpu_model asks for (qemu/target/arm/cpu.c, cpu_arm_init). The M7
  // model is M-profile by its own features.
  if (uc_open(UC_ARCH_ARM, UC_MODE_THUMB, &uc_) != UC_ERR_OK) {
    throw std::runtime_error("unicorn: cannot open an ARM M-profile engine");
  }
  if (uc_ctl_set_cpu_model(uc_, UC_CPU_ARM_CORTEX_M7) != UC_ERR_OK) {
    throw std::runtime_error("unicorn: no Cortex-M7 model");
  }
  system_blocks_ = std::make_unique<SystemBlocks>(*this, exceptions_, core_);
  system_blocks_->add_to(system_bus_);
  blocks_ = std::make_unique<BlockCache>(&read_code, this);
  map_memory();
  install_hooks();
}

ImageChip::~ImageChip() {
  scheduler_.cancel(event_);
  system_blocks_.reset();
  if (uc_ != nullptr) uc_close(uc_);
}

bool ImageChip::load(const std::string& elf_path, std::string& error) {
  ElfImage image;
  if (!image.load(elf_path, error)) return false;
  for (const ElfSegment& segment : image.segments) {
    if (!place_segment(segment, error)) {
      error = elf_path + ": " + error;
      return false;
    }
  }
  for (const ElfSegment& segment : image.segments)
    write_memory(segment.physical_address, segment.bytes.data(), segment.bytes.size());
  image_ = std::move(image);
  loaded_ = true;
  return true;
}

void ImageChip::power_on(SimTime time_ns) {
  base_ns_ = time_ns;
  base_cycle_ = 0;
  retired_ = 0;
  slept_ = 0;
  powered_ = true;
  uint32_t probe = 0;
  if (!loaded_ || !read_memory(image_.entry & ~1u, &probe, 2)) {
    base_ns_ = time_ns;
    raise_fault(ImageStop::Kind::kBadImage,
                loaded_ ? "bad image: its entry point is outside memory" : "bad image: no image loaded", image_.entry);
    finish_stop();
    return;
  }
  uint32_t sp = kBootStack, pc = boot_entry() | 1u;
  uc_reg_write(uc_, UC_ARM_REG_SP, &sp);
  uc_reg_write(uc_, UC_ARM_REG_PC, &pc);
  scheduler_.schedule(event_, time_ns);
}

// Where the boot ROM starts a FlexSPI image (IMXRT1060RM 9.7.1.1): the image vector table at
// flash + 0x1000 (header tag 0xD1) names the entry. Teensyduino's ELF entry is that table itself;
// an ELF whose entry is code (the CI stand-in's) starts there when the table names it too.
uint32_t ImageChip::boot_entry() {
  constexpr uint32_t kIvtAddress = 0x60001000u;
  constexpr uint8_t kIvtTag = 0xD1;
  uint32_t ivt[2] = {0, 0};
  if ((image_.entry & ~1u) == kIvtAddress && read_memory(kIvtAddress, ivt, sizeof ivt) && (ivt[0] & 0xFF) == kIvtTag) {
    return ivt[1];
  }
  return image_.entry;
}

void ImageChip::set_core_clock_hz(uint32_t hz) {
  if (hz == 0 || hz == core_hz_) return;
  const uint64_t cycle = cycles();
  base_ns_ = time_of_cycle(cycle);  // at the old clock
  base_cycle_ = cycle;
  core_hz_ = hz;
  system_blocks_->systick().clock_changed();
  end_run_ = true;  // the run's limit was in cycles of the old clock
}

SimTime ImageChip::time_of_cycle(uint64_t cycle) const {
  const Wide elapsed = static_cast<Wide>(cycle - base_cycle_) * 1000000000u / core_hz_;
  return base_ns_ + static_cast<SimTime>(elapsed);
}

uint64_t ImageChip::cycles_at(SimTime time_ns) const {
  if (time_ns <= base_ns_) return base_cycle_;
  const Wide scaled = static_cast<Wide>(time_ns - base_ns_) * core_hz_;
  return base_cycle_ + static_cast<uint64_t>((scaled + 999999999u) / 1000000000u);
}

uint64_t ImageChip::cycles() const {
  if (in_access_) return access_cycles_;
  if (asleep_) {  // the core's clock runs on while it sleeps
    const uint64_t now = cycles_at(scheduler_.now());
    return now > retired_ ? now : retired_;
  }
  return retired_;
}

SimTime ImageChip::now_ns() const {
  if (in_access_) return time_of_cycle(access_cycles_);
  return in_run_ ? time_of_cycle(retired_) : scheduler_.now();
}

void ImageChip::set_irq_level(unsigned irq, bool high) {
  if (irq >= kIrqCount) return;
  exceptions_.set_line(irq, high);
  if (high) pend_exception(0);
}

void ImageChip::pend_exception(unsigned number) {
  if (number > 0 && number < kExceptionCount) exceptions_.set_pending(number, true);
  recheck_ = true;
  if (asleep_ && !in_run_) wake();
}

ImageChip::HandlerCost ImageChip::handler_cost(unsigned exception_number) const {
  return exception_number < kExceptionCount ? handler_costs_[exception_number] : HandlerCost{};
}

uint32_t ImageChip::read_register(int uc_register) const {
  uint32_t value = 0;
  uc_reg_read(uc_, uc_register, &value);
  return value;
}

const char* ImageStop::kind_name(Kind kind) {
  switch (kind) {
    case Kind::kHardFault: return "HardFault";
    case Kind::kBusFault: return "BusFault";
    case Kind::kUsageFault: return "UsageFault";
    case Kind::kMemManage: return "MemManage";
    case Kind::kStackOverflow: return "stack overflow";
    case Kind::kNoProgress: return "no progress";
    case Kind::kUnmodelledAccess: return "unmodelled register";
    case Kind::kBadImage: return "bad image";
  }
  return "stop";
}

}  // namespace stepdance::sim::image

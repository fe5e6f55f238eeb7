// USB1's registers as the firmware reads and writes them (RM ch. 42, USB_n* register map).
#include "image/usb/usb_controller.hpp"

#include "kernel/scheduler/scheduler.hpp"

namespace stepdance::sim::image::usb {
namespace {

constexpr SimTime kMicroframeNs = 125 * kMicrosecond;  // USB 2.0 §8.4.3.1: high-speed microframe
constexpr SimTime kFrameNs = kMillisecond;             // USB 2.0 §8.4.3.1: full-speed frame

}  // namespace

UsbController::SofTick::SofTick(UsbController& owner) : Event(&UsbController::on_sof), controller(owner) {}

UsbController::UsbController(ChipContext& chip, const UsbPhy& phy)
    : chip_(chip),
      phy_(phy),
      queues_(chip),
      timer0_(chip, &on_timer0, this),
      timer1_(chip, &on_timer1, this),
      sof_(*this) {
  endpoint_control_[0] = kCtrl0ResetValue;
}

UsbController::~UsbController() { chip_.scheduler().cancel(sof_); }

void UsbController::on_timer0(void* context) { static_cast<UsbController*>(context)->raise(kStsTi0); }
void UsbController::on_timer1(void* context) { static_cast<UsbController*>(context)->raise(kStsTi1); }

Access UsbController::read(uint32_t offset, uint8_t bytes, uint32_t& value) {
  uint32_t word = 0;
  if (!read_register(offset & ~3u, word)) return Access::kUnmodelled;
  // Narrow reads see their part of the word (no register here has read side effects).
  const unsigned shift = 8 * (offset & 3u);
  value = bytes == 4 ? word : (word >> shift) & ((1u << (8 * bytes)) - 1u);
  return Access::kOk;
}

Access UsbController::write(uint32_t offset, uint8_t bytes, uint32_t value) {
  if (bytes != 4) return Access::kUnmodelled;  // every USB1 register is written as a word
  return write_register(offset, value) ? Access::kOk : Access::kUnmodelled;
}

bool UsbController::read_register(uint32_t offset, uint32_t& value) {
  if (offset >= kEndptCtrl0 && offset < kEndptCtrl0 + 4 * kEndpoints) {
    value = endpoint_control_[(offset - kEndptCtrl0) / 4];
    return true;
  }
  switch (offset) {
    case kGpTimer0Ld: value = timer0_.load(); return true;
    case kGpTimer0Ctrl: value = timer0_.read_control(); return true;
    case kGpTimer1Ld: value = timer1_.load(); return true;
    case kGpTimer1Ctrl: value = timer1_.read_control(); return true;
    case kUsbCmd: value = command_; return true;
    case kUsbSts: value = status_; return true;
    case kUsbIntr: value = interrupt_enable_; return true;
    case kFrIndex: value = frame_index(); return true;
    case kDeviceAddr: value = device_address_register_; return true;
    case kEndptListAddr: value = queues_.list_address(); return true;
    case kBurstSize: value = burst_size_; return true;
    case kTxFillTuning: value = tx_fill_tuning_; return true;
    case kPortSc1: value = port_status(); return true;
    case kUsbMode: value = mode_; return true;
    case kEndptSetupStat: value = setup_status_; return true;
    case kEndptPrime: value = 0; return true;  // priming completes within the write
    case kEndptFlush: value = 0; return true;  // so does flushing
    case kEndptStat: value = endpoint_status_; return true;
    case kEndptComplete: value = endpoint_complete_; return true;
    default: return false;
  }
}

bool UsbController::write_register(uint32_t offset, uint32_t value) {
  if (offset >= kEndptCtrl0 || offset == kEndptPrime || offset == kEndptFlush || offset == kEndptStat ||
      offset == kEndptSetupStat || offset == kEndptComplete) {
    return write_endpoint_register(offset, value);
  }
  switch (offset) {
    case kGpTimer0Ld: timer0_.write_load(value); return true;
    case kGpTimer0Ctrl: timer0_.write_control(value); return true;
    case kGpTimer1Ld: timer1_.write_load(value); return true;
    case kGpTimer1Ctrl: timer1_.write_control(value); return true;
    case kUsbCmd: write_command(value); return true;
    case kUsbSts:
      status_ &= ~(value & kStsClearable);
      update_irq();
      return true;
    case kUsbIntr: write_interrupt_enable(value); return true;
    case kDeviceAddr:
      device_address_register_ = value & 0xFF000000u;
      // Without USBADRA the address applies at once; with it, after the next EP0 IN (the
      // SET_ADDRESS status stage), in in().
      address_pending_ = (value & kDeviceAddrAdvance) != 0;
      if (!address_pending_) address_ = static_cast<uint8_t>(value >> kDeviceAddrShift);
      return true;
    case kEndptListAddr: queues_.set_list_address(value & 0xFFFFF800u); return true;
    case kBurstSize: burst_size_ = value & 0xFFFFu; return true;
    case kTxFillTuning: tx_fill_tuning_ = value & 0x003F1FFFu; return true;
    case kPortSc1: port_writable_ = value & kPortWritable; return true;
    case kUsbMode:
      mode_ = value & kModeWritable;
      notify_activity();
      return true;
    default: return false;
  }
}

bool UsbController::write_endpoint_register(uint32_t offset, uint32_t value) {
  if (offset >= kEndptCtrl0 + 4 * kEndpoints) return false;
  if (offset >= kEndptCtrl0) {
    const unsigned endpoint = (offset - kEndptCtrl0) / 4;
    // Endpoint 0 is always an enabled control endpoint: only its stall bits are writable.
    endpoint_control_[endpoint] =
        endpoint == 0 ? kCtrl0ResetValue | (value & (kCtrlRxStall | kCtrlTxStall)) : value & kCtrlWritable;
    return true;
  }
  switch (offset) {
    case kEndptSetupStat: setup_status_ &= ~(value & 0xFFFFu); return true;
    case kEndptPrime: prime(value); return true;
    case kEndptFlush: flush(value); return true;
    case kEndptStat: return true;  // read only: writes are ignored
    case kEndptComplete: endpoint_complete_ &= ~value; return true;
    default: return false;
  }
}

void UsbController::write_command(uint32_t value) {
  if (value & kCmdReset) {
    reset_controller();  // RST reads back 0 at once: the reset is done within the write
    return;
  }
  const bool was_running = (command_ & kCmdRunStop) != 0;
  command_ = value & kCmdWritable;
  const bool running = (command_ & kCmdRunStop) != 0;
  if (was_running && !running) {
    port_enabled_ = in_reset_ = false;  // the pull-up is gone: the host sees a disconnect
  }
  if (was_running != running) notify_activity();
}

void UsbController::write_interrupt_enable(uint32_t value) {
  const bool sof_was_on = (interrupt_enable_ & kStsSri) != 0;
  interrupt_enable_ = value & kIntrWritable;
  if (!sof_was_on && (interrupt_enable_ & kStsSri)) schedule_sof();
  update_irq();
}

void UsbController::prime(uint32_t bits) {
  bool primed = false;
  for (unsigned queue = 0; queue < EndpointQueues::kQueues; ++queue) {
    const uint32_t bit = queue_bit(queue);
    if (!(bits & bit) || !queues_.prime(queue)) continue;
    endpoint_status_ |= bit;
    primed = true;
  }
  if (!queues_.error().empty()) raise(kStsSei);
  if (primed) notify_activity();
}

void UsbController::flush(uint32_t bits) {
  for (unsigned queue = 0; queue < EndpointQueues::kQueues; ++queue) {
    if (bits & queue_bit(queue)) queues_.flush(queue);
  }
  endpoint_status_ &= ~bits;
}

void UsbController::reset_controller() {
  const bool was_running = (command_ & kCmdRunStop) != 0;
  command_ = kCmdResetValue;
  status_ = interrupt_enable_ = device_address_register_ = tx_fill_tuning_ = 0;
  burst_size_ = 0x00000808u;
  port_writable_ = kPortPtw;
  mode_ = setup_status_ = endpoint_status_ = endpoint_complete_ = 0;
  endpoint_control_.fill(0);
  endpoint_control_[0] = kCtrl0ResetValue;
  queues_.set_list_address(0);
  queues_.clear();
  timer0_.reset();
  timer1_.reset();
  chip_.scheduler().cancel(sof_);
  in_reset_ = port_enabled_ = high_speed_ = false;
  address_ = 0;
  address_pending_ = false;
  update_irq();
  if (was_running) notify_activity();
}

uint32_t UsbController::port_status() const {
  uint32_t value = port_writable_;
  if (attached()) value |= kPortCcs;
  if (port_enabled_) value |= kPortPe;
  if (in_reset_) value |= kPortPr;
  if (port_enabled_ && high_speed_) value |= kPortHsp | (2u << kPortPspdShift);
  return value;
}

uint32_t UsbController::frame_index() const {
  if (!port_enabled_) return 0;
  const SimTime since = chip_.now_ns() - port_up_ns_;
  // Device mode: FRINDEX 13:3 is the frame number of the last SOF, 2:0 the microframe (RM
  // USB_nFRINDEX); at full speed the microframe bits stay 0.
  const uint64_t microframes =
      high_speed_ ? static_cast<uint64_t>(since / kMicroframeNs) : static_cast<uint64_t>(since / kFrameNs) << 3;
  return static_cast<uint32_t>(microframes & 0x3FFFu);
}

void UsbController::raise(uint32_t status_bits) {
  status_ |= status_bits;
  update_irq();
}

void UsbController::update_irq() {
  const bool level = (status_ & interrupt_enable_ & kStsClearable) != 0;
  if (level == irq_level_) return;
  irq_level_ = level;
  chip_.set_irq_level(kIrqUsb1, level);
}

void UsbController::schedule_sof() {
  if (!port_enabled_ || !(interrupt_enable_ & kStsSri)) return;
  const SimTime period = high_speed_ ? kMicroframeNs : kFrameNs;
  const SimTime since = chip_.now_ns() - port_up_ns_;
  chip_.scheduler().schedule(sof_, port_up_ns_ + (since / period + 1) * period);
}

void UsbController::on_sof(Event& event, Scheduler&) {
  UsbController& controller = static_cast<SofTick&>(event).controller;
  if (!controller.port_enabled_ || !(controller.interrupt_enable_ & kStsSri)) return;
  controller.raise(kStsSri);
  controller.schedule_sof();
}

void UsbController::notify_activity() {
  if (activity_) activity_();
}

}  // namespace stepdance::sim::image::usb

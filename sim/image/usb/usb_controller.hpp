// USB1: the RT1062's USB OTG controller (ChipIdea, EHCI-compatible) in device mode.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <string>

#include "image/chip/chip_context.hpp"
#include "image/chip/peripheral.hpp"
#include "image/usb/endpoint_queues.hpp"
#include "image/usb/gp_timer.hpp"
#include "image/usb/usb_bus.hpp"
#include "image/usb/usb_phy.hpp"
#include "kernel/scheduler/event.hpp"

namespace stepdance::sim::image::usb {

/// The controller's registers (RM ch. 42, usb_registers.hpp) on the firmware side and a
/// UsbDevicePort on the cable side. Transfers run through the dQHs and dTDs in the image's
/// memory (EndpointQueues). USB1's interrupt line (IRQ 113) is the level of
/// USBSTS & USBINTR. Host mode, OTG, ULPI, the NAK registers and isochronous timing are not
/// modelled: their registers answer kUnmodelled. Simulator thread only.
class UsbController : public Peripheral, public UsbDevicePort {
 public:
  UsbController(ChipContext& chip, const UsbPhy& phy);
  ~UsbController() override;

  // ---- Peripheral ----
  const char* name() const override { return "USB1"; }
  uint32_t base() const override { return kUsb1Base; }
  uint32_t size_bytes() const override { return kUsb1SizeBytes; }
  ClockGate gate() const override { return {kUsbGateCcgr, kUsbGateField}; }
  Access read(uint32_t offset, uint8_t bytes, uint32_t& value) override;
  Access write(uint32_t offset, uint8_t bytes, uint32_t value) override;

  // ---- UsbDevicePort ----
  bool attached() const override;
  std::string detached_reason() const override;
  void bus_reset_begin() override;
  BusSpeed bus_reset_end() override;
  Handshake setup(uint8_t address, const uint8_t request[8]) override;
  Handshake out(uint8_t address, uint8_t endpoint, const uint8_t* data, size_t length) override;
  Handshake in(uint8_t address, uint8_t endpoint, uint8_t* data, size_t capacity, size_t& length) override;

  /// Called whenever the device side changes what the host may find: attach/detach (RS) and
  /// every successful prime. The host uses it to wake from idle polling.
  void set_activity_listener(std::function<void()> listener) { activity_ = std::move(listener); }
  /// The first DMA failure ("" if none): the controller stops answering after one.
  const std::string& dma_error() const { return queues_.error(); }
  /// The address the device answers to now (0 until SET_ADDRESS takes effect).
  uint8_t address() const { return address_; }

 private:
  struct SofTick : Event {
    explicit SofTick(UsbController& owner);
    UsbController& controller;
  };
  static void on_sof(Event& event, Scheduler& scheduler);
  static void on_timer0(void* context);
  static void on_timer1(void* context);

  bool read_register(uint32_t offset, uint32_t& value);
  bool write_register(uint32_t offset, uint32_t value);
  bool write_endpoint_register(uint32_t offset, uint32_t value);
  void write_command(uint32_t value);
  void write_interrupt_enable(uint32_t value);
  void prime(uint32_t bits);
  void flush(uint32_t bits);
  void reset_controller();
  uint32_t port_status() const;
  uint32_t frame_index() const;
  void raise(uint32_t status_bits);
  void update_irq();
  void schedule_sof();
  void notify_activity();
  bool answers(uint8_t address) const;
  Handshake endpoint_gate(unsigned endpoint, bool in) const;
  void finish_packet(unsigned queue, const PacketResult& result);

  ChipContext& chip_;
  const UsbPhy& phy_;
  EndpointQueues queues_;
  GpTimer timer0_;
  GpTimer timer1_;
  SofTick sof_;
  std::function<void()> activity_;

  uint32_t command_ = kCmdResetValue;
  uint32_t status_ = 0;
  uint32_t interrupt_enable_ = 0;
  uint32_t device_address_register_ = 0;
  uint32_t burst_size_ = 0x00000808u;  // RM: USB_nBURSTSIZE reset value (RX/TX bursts of 8)
  uint32_t tx_fill_tuning_ = 0;
  uint32_t port_writable_ = kPortPtw;
  uint32_t mode_ = 0;
  uint32_t setup_status_ = 0;
  uint32_t endpoint_status_ = 0;
  uint32_t endpoint_complete_ = 0;
  std::array<uint32_t, kEndpoints> endpoint_control_{};

  // Port state as the host left it.
  bool in_reset_ = false;
  bool port_enabled_ = false;
  bool high_speed_ = false;
  SimTime port_up_ns_ = 0;        ///< when the last bus reset ended: microframe 0
  uint8_t address_ = 0;           ///< the address in effect
  bool address_pending_ = false;  ///< DEVICEADDR written with USBADRA, not yet in effect
  bool irq_level_ = false;
};

}  // namespace stepdance::sim::image::usb

/* The stand-in core's USB serial: a minimal USB CDC-ACM device on the i.MX RT1062's USB1
   controller, written by us from the reference manual (chapter 42, device operation and data
   structures) and the USB 2.0, CDC 1.2 and PSTN 1.2 specifications. It is what the stand-in's
   `Serial` (usb_serial_class in Arduino.h) reads and writes. Enumerates as a Teensy serial
   (VID:PID 16C0:0483), high speed (512-byte bulk packets) or full speed (64). */
#pragma once

#ifdef __cplusplus
extern "C" {
#endif

/** Powers PLL_USB1 if it is not already running, turns on the USB clock gate, brings USBPHY1
    and USB1 up in device mode and attaches to the bus; from then on everything runs in the USB1
    interrupt (IRQ 113, priority 128). The start-up calls it once after the clocks, SysTick and
    the RAM vector table are in place (C linkage: the start-up's hook of the same name, which
    this definition replaces); Serial's methods also call it on first use. Only the first call
    does anything. Context: thread mode. */
void stand_in_usb_serial_start(void);

#ifdef __cplusplus
}
#endif

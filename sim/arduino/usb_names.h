/* Teensyduino's usb_names.h on the host: the USB string descriptor type a sketch's name.c fills
   in to rename the board's USB manufacturer, product and serial number. The simulator has no USB,
   so the strings are only compiled; nothing reads them. */
#pragma once

#include <stdint.h>

/** One USB string descriptor: its length in bytes (2 + 2 per character), type 3, UTF-16 text. */
struct usb_string_descriptor_struct {
  uint8_t bLength;
  uint8_t bDescriptorType;
  uint16_t wString[];
};

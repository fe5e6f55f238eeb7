/* The board's USB identity: plotter software looks for an EiBotBoard. Teensyduino reads these
   descriptors (by these names) when the board enumerates; the strings are UTF-16 characters.
   The AxiDraw software matches the product name "EiBotBoard"; saxi the manufacturer
   "SchmalzHaus". (The vendor and product ids, 04D8:FD92, can only be changed in Teensyduino's
   core, not from a sketch: see docs/axidraw.md.) */
#include "usb_names.h"

struct usb_string_descriptor_struct usb_string_manufacturer_name = {
    2 + 11 * 2, 3, {'S', 'c', 'h', 'm', 'a', 'l', 'z', 'H', 'a', 'u', 's'}};

struct usb_string_descriptor_struct usb_string_product_name = {
    2 + 10 * 2, 3, {'E', 'i', 'B', 'o', 't', 'B', 'o', 'a', 'r', 'd'}};

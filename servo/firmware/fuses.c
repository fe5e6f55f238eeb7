/* fuses.c: the ATtiny84 fuse bytes this firmware needs, stored in the ELF's .fuse section. */
/* avr/io.h first: avr/fuse.h sizes FUSES by the device's fuse count, which avr/io.h defines. */
#include <avr/io.h> /* device fuse bit names */

#include <avr/fuse.h> /* FUSES */

/* low 0xE2: internal 8 MHz RC (CKSEL 0010, SUT 10), clock not divided by 8, no clock output.
 * high 0xDD: brown-out reset at 2.7 V (BODLEVEL 101), SPI programming on, reset pin kept.
 * extended 0xFF: self-programming off (there is no bootloader).
 * docs/servo-driver.md explains each choice; keep both in step. */
FUSES = {
    .low = 0xE2,
    .high = 0xDD,
    .extended = 0xFF,
};

# servo_firmware.cmake: builds the ATtiny84 servo driver firmware with avr-gcc (servo_add_firmware).

option(STEPDANCE_SERVO_FIRMWARE "Build the ATtiny84 servo driver firmware (needs avr-gcc)" ON)

find_program(SERVO_AVR_GCC avr-gcc)
find_program(SERVO_AVR_OBJCOPY avr-objcopy)
find_program(SERVO_AVR_SIZE avr-size)
find_path(SERVO_AVR_LIBC_INCLUDE avr/io.h PATHS /usr/lib/avr/include /usr/avr/include NO_DEFAULT_PATH)
if(STEPDANCE_SERVO_FIRMWARE AND (NOT SERVO_AVR_GCC OR NOT SERVO_AVR_OBJCOPY OR NOT SERVO_AVR_SIZE OR NOT SERVO_AVR_LIBC_INCLUDE))
  message(FATAL_ERROR
    "The servo driver firmware needs the AVR toolchain (avr-gcc, avr-objcopy, avr-size, avr-libc).\n"
    "On Debian/Ubuntu: sudo apt-get install gcc-avr avr-libc binutils-avr\n"
    "(or configure with -DSTEPDANCE_SERVO_FIRMWARE=OFF to skip the firmware and its simavr tests)")
endif()

set(SERVO_FIRMWARE_DIR ${CMAKE_CURRENT_SOURCE_DIR}/firmware)
set(SERVO_PULSE_DIR ${CMAKE_CURRENT_SOURCE_DIR}/pulse)
set(SERVO_FIRMWARE_SOURCES
  ${SERVO_FIRMWARE_DIR}/main.c
  ${SERVO_FIRMWARE_DIR}/step_input.c
  ${SERVO_FIRMWARE_DIR}/step_input_isr.S
  ${SERVO_FIRMWARE_DIR}/servo_pwm.c
  ${SERVO_FIRMWARE_DIR}/fuses.c
  ${SERVO_PULSE_DIR}/servo_pulse.c)
file(GLOB SERVO_FIRMWARE_HEADERS CONFIGURE_DEPENDS ${SERVO_FIRMWARE_DIR}/*.h ${SERVO_PULSE_DIR}/*.h)

# 8 MHz internal RC (low fuse 0xE2); LTO lets the constant settings fold into main().
set(SERVO_AVR_FLAGS
  -mmcu=attiny84 -DF_CPU=8000000UL -std=gnu99 -Os -flto
  -Wall -Wextra -Werror -Wundef -Wshadow
  -ffunction-sections -fdata-sections -Wl,--gc-sections)

# servo_add_firmware(<name> [DEFINES NAME=value ...])
# Builds servo_driver_<name>.elf/.hex/.map in the current binary directory, prints avr-size, and
# sets SERVO_FIRMWARE_<name>_ELF in the caller's scope.
function(servo_add_firmware name)
  cmake_parse_arguments(PARSE_ARGV 1 ARG "" "" "DEFINES")
  set(base ${CMAKE_CURRENT_BINARY_DIR}/servo_driver_${name})
  list(TRANSFORM ARG_DEFINES PREPEND -D OUTPUT_VARIABLE defines)
  add_custom_command(
    OUTPUT ${base}.elf ${base}.map
    COMMAND ${SERVO_AVR_GCC} ${SERVO_AVR_FLAGS} ${defines}
            -I${SERVO_FIRMWARE_DIR} -I${SERVO_PULSE_DIR}
            -Wl,-Map=${base}.map -o ${base}.elf ${SERVO_FIRMWARE_SOURCES}
    COMMAND ${SERVO_AVR_SIZE} --format=avr --mcu=attiny84 ${base}.elf
    DEPENDS ${SERVO_FIRMWARE_SOURCES} ${SERVO_FIRMWARE_HEADERS}
    COMMENT "Building servo firmware servo_driver_${name}.elf (ATtiny84)"
    VERBATIM)
  add_custom_command(
    OUTPUT ${base}.hex
    COMMAND ${SERVO_AVR_OBJCOPY} -O ihex -j .text -j .data ${base}.elf ${base}.hex
    DEPENDS ${base}.elf
    COMMENT "Writing servo_driver_${name}.hex"
    VERBATIM)
  add_custom_target(servo_firmware_${name} ALL DEPENDS ${base}.elf ${base}.hex)
  set(SERVO_FIRMWARE_${name}_ELF ${base}.elf PARENT_SCOPE)
endfunction()

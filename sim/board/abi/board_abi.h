/* The C ABI between the simulator (host) and one simulated board's shared object (sketch + core).
 *
 * A board .so exports exactly one symbol, stepdance_board_attach(). The host passes it a table of
 * callbacks (StepdanceHostV1) through which the board's HAL backend reaches simulated time, pins
 * and ports; the board answers with a table of entry points (StepdanceBoardV1) the host's
 * scheduler calls at each timer tick, loop pass and captured pulse. Plain C types only, so the
 * two sides never share C++ objects, allocators or globals.
 *
 * Status codes are the values of stepdance::Status (0 = ok). Pins are Teensy pin numbers, ports
 * 0..3 = A..D, encoders 0..1 = ENC1..ENC2. All callbacks run on the simulator's single thread. */
#ifndef STEPDANCE_SIM_BOARD_ABI_H
#define STEPDANCE_SIM_BOARD_ABI_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Bump when either table changes shape. The board refuses a host of another version. */
#define STEPDANCE_BOARD_ABI_VERSION 9u

/* Which hardware timer a timer_start() call is for. */
enum StepdanceTimerId { STEPDANCE_TIMER_FRAME = 0, STEPDANCE_TIMER_KHZ = 1 };
/* The STEP edge at which an input port samples DIR. */
enum StepdanceDirEdge { STEPDANCE_DIR_AT_RISING = 0, STEPDANCE_DIR_AT_FALLING = 1 };
/* Digital pin configurations (same order as stepdance::hal::PinMode). */
enum StepdancePinMode {
  STEPDANCE_PIN_INPUT = 0,
  STEPDANCE_PIN_INPUT_PULLUP = 1,
  STEPDANCE_PIN_INPUT_PULLDOWN = 2,
  STEPDANCE_PIN_OUTPUT = 3
};
/* How a storage file is opened (same order as stepdance::FileMode). */
enum StepdanceFileMode { STEPDANCE_FILE_READ = 0, STEPDANCE_FILE_WRITE = 1, STEPDANCE_FILE_APPEND = 2 };

/* One captured STEP pulse as the board's capture unit reports it (150 ticks per µs, 16 bits),
 * with the counter periods beyond the wrapped width (protocol::CapturedPulse::extra_periods). */
typedef struct StepdanceCapturedPulseV1 {
  uint32_t rise_ticks;
  uint32_t fall_ticks;
  uint8_t dir_high;
  uint32_t extra_periods;
} StepdanceCapturedPulseV1;

/* What a board reports about itself at the end of a run (or whenever asked). */
typedef struct StepdanceBoardStatsV1 {
  uint32_t frames;             /* frames run since dance_start() */
  uint32_t frame_overruns;     /* frames over their CPU budget (see docs: not modelled) */
  uint8_t fault_reason;        /* stepdance::FaultReason, 0 = none */
  const char* fault_name;      /* its name ("registry full", …); static */
  uint32_t fault_count;        /* fault() calls */
  const char* fault_detail;    /* "" if none; valid until the next call into the board */
  uint32_t load_peak_cycles;   /* the engine's frame load (the simulator's cost model) */
  uint32_t load_budget_cycles; /* cycles in one frame (24,000) */
  uint64_t load_total_cycles;
  uint64_t load_frames;
} StepdanceBoardStatsV1; /* per-block statistics come as named counters (read_counters) */

/* One named counter of one block (Block::report_counters): the block's class name, its instance
 * among blocks of that class (registration order), the counter's name and value. Strings are
 * static. */
typedef void (*StepdanceCounterFnV1)(void* context, const char* block, uint32_t instance, const char* name,
                                     uint64_t value);

/* One kind of warning on the board's fault path (stepdance::WarningTally): its source (a block
 * or interface), its reason's name, the first report's detail ("" if none) and how often it came
 * since dance_start() or the last clear_fault(). Strings are valid during the call. */
typedef void (*StepdanceWarningFnV1)(void* context, const char* source, const char* reason, const char* detail,
                                     uint32_t count);

/* Callbacks from the board into the simulator. `context` is the host_context given to attach. */
typedef struct StepdanceHostV1 {
  uint32_t abi_version;

  /* ---- timers (time itself comes with every entry point of StepdanceBoardV1) ---- */
  int (*timer_start)(void* context, int timer_id, uint32_t period_us);
  void (*timers_stop)(void* context);
  /* Arduino delay(): runs the rest of the simulation for duration_ns; returns the time then. */
  int64_t (*delay_ns)(void* context, int64_t duration_ns);

  /* ---- motion-stream ports ---- */
  int (*port_out_begin)(void* context, uint8_t port);
  /* The words of the frame just computed; played on the wire from the next frame tick. */
  void (*port_out_frame)(void* context, uint8_t port, uint32_t step_bits, uint32_t dir_bits);
  int (*port_in_begin)(void* context, uint8_t port, int dir_edge);

  /* ---- quadrature, ADC, GPIO ---- */
  int (*quadrature_begin)(void* context, uint8_t index);
  int32_t (*quadrature_read)(void* context, uint8_t index);
  void (*quadrature_write)(void* context, uint8_t index, int32_t count);
  int (*adc_begin)(void* context, uint8_t pin);
  uint16_t (*adc_read)(void* context, uint8_t pin);
  uint32_t (*adc_sample_count)(void* context, uint8_t pin);
  int (*gpio_mode)(void* context, uint8_t pin, int mode);
  int (*gpio_read)(void* context, uint8_t pin);
  void (*gpio_write)(void* context, uint8_t pin, int high);

  /* ---- faults and console ---- */
  void (*enter_safe_state)(void* context);
  void (*log_fault)(void* context, const char* reason, const char* detail);
  size_t (*console_write)(void* context, const uint8_t* data, size_t length);
  size_t (*console_available)(void* context);
  int (*console_read)(void* context); /* next byte, or -1 */

  /* ---- file storage (a folder on the host) ---- */
  int (*file_open)(void* context, const char* name, int mode, int* handle);
  int (*file_read)(void* context, int handle, uint8_t* data, size_t length, size_t* read);
  int (*file_write)(void* context, int handle, const uint8_t* data, size_t length);
  int (*file_close)(void* context, int handle);

  /* ---- I2C on the QWIIC connectors (bus 0 = QWIIC0, 1 = QWIIC1) ---- */
  int (*i2c_begin)(void* context, uint8_t bus, uint32_t clock_hz);
  /* One whole transfer against the devices on the bus: write, then (read_length > 0) a repeated
   * start and read. Returns a stepdance::hal::I2cResult final value (2 = ok, 3 = address nack,
   * …) and the transfer's time on the wire in *wire_ns; simulated time does not move. */
  int (*i2c_transfer)(void* context, uint8_t bus, uint8_t address, const uint8_t* write, size_t write_length,
                      uint8_t* read, size_t read_length, int64_t* wire_ns);

  /* ---- the sketch ended the program: exit(), abort() and their kin, called by sketch code ----
   * `how` is a StepdanceSketchEnd, `status` the exit status (0 for abort). The board then escapes
   * from the entry point it is in (see StepdanceBoardV1.escape); outside any entry point the
   * host must end the process itself, so this call does not return there. */
  void (*sketch_ended)(void* context, int how, int status);
} StepdanceHostV1;

/* How a sketch ended the program. */
enum StepdanceSketchEnd { STEPDANCE_END_EXIT = 0, STEPDANCE_END_QUICK_EXIT = 1, STEPDANCE_END_ABORT = 2 };

/* Entry points of one board, called by the simulator's scheduler. Each takes the current
 * simulated time (ns), which the board keeps for hal::micros_now() and cycles_now() until the
 * next entry: within one entry time only moves through delay_ns().
 *
 * The five run_ and deliver_ entries return 0 when the sketch's code returned, or the non-zero
 * code passed to escape() when the simulator stopped it there (the run ended inside a delay, the
 * sketch crashed, hung, exited or was interrupted). Entries nest (a delay() inside loop() runs
 * the frame ticks), and escape() leaves the innermost one only. */
typedef struct StepdanceBoardV1 {
  uint32_t abi_version;
  /* The name of the board table the sketch selected (stepdance::BoardDefinition::name, e.g.
   * "Driver Module v1.0"); static. The host finds the same table in its board registry. */
  const char* board_name;
  int (*run_setup)(int64_t now_ns);
  int (*run_frame_tick)(int64_t now_ns);
  int (*run_khz_tick)(int64_t now_ns);
  int (*run_loop)(int64_t now_ns);
  /* The port's capture ISR: hands one pulse to the sink registered by port_in_begin(). */
  int (*deliver_pulse)(int64_t now_ns, uint8_t port, const StepdanceCapturedPulseV1* pulse);
  void (*read_stats)(StepdanceBoardStatsV1* stats);
  /* Calls emit once per counter of every registered block. */
  void (*read_counters)(StepdanceCounterFnV1 emit, void* context);
  /* Calls emit once per kind of warning tallied (in the order first seen). */
  void (*read_warnings)(StepdanceWarningFnV1 emit, void* context);
  /* Leaves the innermost entry point now, which then returns `code` (non-zero). Called by the
   * host from inside the board's code: a host callback the sketch called, or a signal handler
   * that interrupted the sketch's own code (never one that interrupted a C library call). Does
   * nothing outside every entry point. */
  void (*escape)(int code);
} StepdanceBoardV1;

/* The one exported symbol. Returns NULL if host->abi_version differs from the board's. */
typedef const StepdanceBoardV1* (*StepdanceBoardAttachFn)(const StepdanceHostV1* host, void* host_context);
#define STEPDANCE_BOARD_ATTACH_SYMBOL "stepdance_board_attach"

#ifdef __cplusplus
}
#endif

#endif /* STEPDANCE_SIM_BOARD_ABI_H */

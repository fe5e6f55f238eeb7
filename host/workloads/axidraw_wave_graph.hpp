// The AxiDrawWave example's graph on the manual host backend, plotting: its EiBotBoard replays
// the recorded saxi plot of examples/AxiDrawWave/saxi-plot.ebb over and over, with the pedal
// down, for the frame benchmarks ("frame cost of AxiDrawWave while plotting", docs/axidraw.md).
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "axidraw_plot_commands.hpp"  // generated: kAxiDrawPlotCommands (cmake/embed_text.cmake)
#include "hal_manual.hpp"
#include "stepdance/boards/board.hpp"
#include "stepdance/core/byte_stream.hpp"
#include "stepdance/core/dance.hpp"
#include "stepdance/core/engine.hpp"
#include "stepdance/core/fault.hpp"
#include "stepdance/interfaces/ebb/eibotboard.hpp"
#include "stepdance/io/analog_input.hpp"
#include "stepdance/io/output_port.hpp"
#include "stepdance/motion/channel.hpp"
#include "stepdance/motion/kinematics_core_xy.hpp"
#include "stepdance/motion/vector_2d_to_angle.hpp"
#include "stepdance/motion/wave_generator_2d.hpp"

namespace stepdance::workloads {

/// The plotter software's side of the link: the recorded commands, from the start again after
/// the last (the plot ends where it began); the board's replies are read and dropped.
class ReplayedPlotStream final : public ByteStream {
 public:
  size_t bytes_available() override { return 1; }
  int read_byte() override {
    if (kAxiDrawPlotCommands[next_] == '\0') {
      next_ = 0;
      ++plots_sent_;
    }
    const char c = kAxiDrawPlotCommands[next_++];
    return c == '\n' ? '\r' : static_cast<uint8_t>(c);  // EBB clients end commands with CR
  }
  size_t write_bytes(const uint8_t*, size_t length) override { return length; }
  size_t write_space() override { return 512; }
  /// Times the whole plot was sent.
  uint32_t plots_sent() const { return plots_sent_; }

 private:
  size_t next_ = 0;
  uint32_t plots_sent_ = 0;
};

/// examples/AxiDrawWave built without a sketch: Eibotboard → CoreXY → channels A/B, the pen servo
/// on channel C, and the wave (Vector2DToAngle, MoveDurationToFrequency, WaveGenerator2D) summed
/// into the kinematics at the pedal's full 3 mm.
class AxiDrawWaveGraph {
 public:
  AxiDrawWaveGraph() {
    hal_manual::reset();
    engine().clear();
    clear_fault();
    output_a.begin(OUTPUT_A);
    output_b.begin(OUTPUT_B);
    output_c.begin(OUTPUT_C);
    channel_a.begin(&output_a, SIGNAL_E);
    channel_a.set_ratio(25.4, 2032);
    channel_b.begin(&output_b, SIGNAL_E);
    channel_b.set_ratio(25.4, 2032);
    channel_z.begin(&output_c, SIGNAL_E);
    channel_z.set_ratio(1, 50);
    axidraw.begin(&link);
    axidraw.output_x.map(&kinematics.input_x);
    axidraw.output_y.map(&kinematics.input_y);
    axidraw.output_z.map(&channel_z.input_target_position);
    axidraw.output_parameter.map(&wave.input_t, ABSOLUTE);
    direction.input_x.map(&axidraw.output_x);
    direction.input_y.map(&axidraw.output_y);
    direction.output_theta.map(&wave.input_theta, ABSOLUTE);
    direction.begin();
    half_waves.input_move_duration.map(&axidraw.output_duration, ABSOLUTE);
    half_waves.output_frequency.map(&wave.input_frequency, ABSOLUTE);
    half_waves.target_frequency = 10.0;
    half_waves.begin();
    wave.output_x.map(&kinematics.input_x);
    wave.output_y.map(&kinematics.input_y);
    wave.begin();
    pedal.set_floor(0, 0);
    pedal.set_ceiling(3, 1023);
    pedal.map(&wave.amplitude);
    pedal.begin(kDriverModuleV1.io_a[0]);
    kinematics.begin();
    kinematics.output_a.map(&channel_a.input_target_position);
    kinematics.output_b.map(&channel_b.input_target_position);
    dance_start();
    hal_manual::set_adc(kDriverModuleV1.io_a[0], 1023);  // pedal down: the full 3 mm wave
    engine().run_kilohertz_tick();
  }

  /// The loop (the link, outside the frame) then one frame; every 25th frame also the kilohertz
  /// tick, as on the board.
  void run_busy_frame(uint32_t frame) {
    engine().run_loop();
    engine().run_frame();
    if (frame % 25 == 24) engine().run_kilohertz_tick();
  }

  ReplayedPlotStream link;
  OutputPort output_a, output_b, output_c;
  Channel channel_a, channel_b, channel_z;
  KinematicsCoreXY kinematics;
  Eibotboard axidraw;
  Vector2DToAngle direction;
  MoveDurationToFrequency half_waves;
  WaveGenerator2D wave;
  AnalogInput pedal;
};

}  // namespace stepdance::workloads

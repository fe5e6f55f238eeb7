// Stepdance umbrella header: include this from a sketch, after `#define module_driver` or
// `#define module_basic`, to get the whole public API under the original library's names.
#pragma once

#include "stepdance/boards/board.hpp"
#include "stepdance/core/block_port.hpp"
#include "stepdance/core/dance.hpp"
#include "stepdance/core/engine.hpp"
#include "stepdance/core/fault.hpp"
#include "stepdance/core/units.hpp"
#include "stepdance/io/analog_input.hpp"
#include "stepdance/io/button.hpp"
#include "stepdance/io/encoder.hpp"
#include "stepdance/io/input_port.hpp"
#include "stepdance/io/output_port.hpp"
#include "stepdance/motion/channel.hpp"
#include "stepdance/motion/kinematics_core_xy.hpp"
#include "stepdance/motion/position_generator.hpp"
#include "stepdance/motion/attractor_2d.hpp"
#include "stepdance/motion/circle_generator.hpp"
#include "stepdance/motion/kinematics_five_bar.hpp"
#include "stepdance/motion/kinematics_polar_to_cartesian.hpp"
#include "stepdance/motion/path_length_generator.hpp"
#include "stepdance/motion/scaling_filter.hpp"
#include "stepdance/motion/threshold_generator.hpp"
#include "stepdance/motion/vector_2d_to_angle.hpp"
#include "stepdance/motion/velocity_generator.hpp"
#include "stepdance/motion/wave_generator_1d.hpp"
#include "stepdance/motion/wave_generator_2d.hpp"
#include "stepdance/motion/time_based_interpolator.hpp"
#include "stepdance/interfaces/gcode_interface.hpp"
#include "stepdance/interfaces/eibotboard.hpp"
#include "stepdance/interfaces/rpc.hpp"
#include "stepdance/protocol/signals.hpp"
#include "stepdance/homing/homing.hpp"
#include "stepdance/homing/safety_inputs.hpp"
#include "stepdance/recording/four_track_player.hpp"
#include "stepdance/recording/four_track_recorder.hpp"
#include "stepdance/qwiic/oled_display.hpp"
#include "stepdance/qwiic/qwiic_twist.hpp"
#include "stepdance/qwiic/status_menu.hpp"

#include "stepdance/sketch_board.hpp"

// Teensyduino ships CMSIS's arm_math.h; sketches written for the original get float32_t and
// float64_t from it through the library's headers. (The host Arduino API defines both itself.)
#if defined(__IMXRT1062__) && defined(__has_include)
#if __has_include(<arm_math.h>)
#include <arm_math.h>
#endif
#endif

// The original library lived in the global namespace; sketches name its classes unqualified.
using stepdance::AnalogInput;
using stepdance::Block;
using stepdance::BlockPort;
using stepdance::Button;
using stepdance::Attractor2D;
using stepdance::Channel;
using stepdance::CircleGenerator;
using stepdance::KinematicsFiveBarForward;
using stepdance::KinematicsFiveBarInverse;
using stepdance::KinematicsLever;
using stepdance::KinematicsPolarToCartesian;
using stepdance::MoveDurationToFrequency;
using stepdance::PathLengthGenerator2D;
using stepdance::PathLengthGenerator3D;
using stepdance::ScalingFilter1D;
using stepdance::ScalingFilter2D;
using stepdance::ThresholdGenerator;
using stepdance::Vector2DToAngle;
using stepdance::VelocityGenerator;
using stepdance::WaveGenerator1D;
using stepdance::WaveGenerator2D;
using stepdance::ControlParameter;
using stepdance::DecimalPosition;
using stepdance::Encoder;
using stepdance::FourTrackPlayer;
using stepdance::Homing;
using stepdance::HomingAxis;
using stepdance::SafetyInputs;
using stepdance::FourTrackRecorder;
using stepdance::RecorderTrack;
using stepdance::RECORDING_FORMAT_ORIGINAL;
using stepdance::RECORDING_FORMAT_STEPDANCE;
using stepdance::Eibotboard;
using stepdance::GCodeInterface;
using stepdance::InputPort;
using stepdance::KinematicsCoreXY;
using stepdance::OutputPort;
using stepdance::Plugin;
using stepdance::PositionGenerator;
using stepdance::RPC;
using stepdance::TimeBasedInterpolator;
// Board-mounted display and knob (new in this library; the original drove neither).
using stepdance::OledDisplay;
using stepdance::QwiicTwist;
using stepdance::StatusMenu;
using stepdance::QWIIC_0;
using stepdance::QWIIC_1;
using stepdance::disable_drivers;
using stepdance::enable_drivers;
using stepdance::iterate_across_all_output_ports;
using stepdance::transmit_frames_on_all_output_ports;

// Constants the original exposed globally.
using stepdance::ABSOLUTE;
using stepdance::BLOCKPORT_INPUT;
using stepdance::BLOCKPORT_OUTPUT;
using stepdance::BLOCKPORT_UNDEFINED;
using stepdance::BUTTON_MODE_MULTIPRESS;
using stepdance::BUTTON_MODE_STANDARD;
using stepdance::BUTTON_MODE_TOGGLE;
using stepdance::BUTTON_MODE_TOGGLE_THREE_STATE;
using stepdance::BUTTON_STATE_PRESSED;
using stepdance::BUTTON_STATE_RELEASED;
using stepdance::DIRECTION_FORWARD;
using stepdance::DIRECTION_REVERSE;
using stepdance::ENCODER_1;
using stepdance::ENCODER_2;
using stepdance::ENCODER_A;
using stepdance::GLOBAL;
using stepdance::INCREMENTAL;
using stepdance::INPUT_A;
using stepdance::INPUT_B;
using stepdance::INPUT_B_LEGACY;
using stepdance::INPUT_C;
using stepdance::INPUT_C_LEGACY;
using stepdance::INPUT_D;
using stepdance::INPUT_MODE_STEP_DIR;
using stepdance::INPUT_MODE_STEPDANCE;
using stepdance::MAX;
using stepdance::MIN;
using stepdance::NUM_AVAILABLE_INPUT_PORTS;
using stepdance::NUM_AVAILABLE_OUTPUT_PORTS;
using stepdance::NUM_SIGNALS;
using stepdance::OUTPUT_A;
using stepdance::OUTPUT_A_LEGACY;
using stepdance::OUTPUT_B;
using stepdance::OUTPUT_B_LEGACY;
using stepdance::OUTPUT_C;
using stepdance::OUTPUT_D;
using stepdance::OUTPUT_FRAME_16US;
using stepdance::OUTPUT_FRAME_32US;
using stepdance::OUTPUT_FRAME_4US;
using stepdance::OUTPUT_FRAME_8US;
using stepdance::OUTPUT_TRANSMIT_MANUAL;
using stepdance::OUTPUT_TRANSMIT_ON_FRAME;
using stepdance::SIGNAL_E;
using stepdance::SIGNAL_R;
using stepdance::SIGNAL_T;
using stepdance::SIGNAL_X;
using stepdance::SIGNAL_Y;
using stepdance::SIGNAL_Z;
using stepdance::STANDARD_RATIO_IN;
using stepdance::STANDARD_RATIO_MM;

// Runs on the test-only board (test_module.hpp): knob 1 on ENC1 drives the stepper in socket B
// one step per count; A1 is printed twice a second; pin 45 (a Teensy 4.1 pin, not a 4.0 one) is
// driven high, which the board's Teensy 4.0 must refuse.
#include "test_module.hpp"
#define STEPDANCE_BOARD stepdance::test::kTestModule
#include "stepdance.hpp"

OutputPort output_b;
Channel channel_b;
Encoder encoder_1;

void setup() {
  Serial.begin(115200);
  output_b.begin(OUTPUT_B);
  output_b.enable_driver();
  channel_b.begin(&output_b, SIGNAL_E);
  channel_b.set_ratio(1, 1);
  encoder_1.begin(ENCODER_1);
  encoder_1.set_ratio(1, 1);
  encoder_1.output.map(&channel_b.input_target_position);
  pinMode(45, OUTPUT);
  digitalWrite(45, HIGH);
  pinMode(IO_D1, OUTPUT);
  digitalWrite(IO_D1, HIGH);
  dance_start();
}

void loop() {
  static uint32_t last_ms = 0;
  if (millis() - last_ms >= 500) {
    last_ms = millis();
    Serial.print("A1 ");
    Serial.println(analogRead(IO_A1));
  }
  dance_loop();
}

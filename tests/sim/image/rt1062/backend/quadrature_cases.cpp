// The Teensy backend's own quadrature.cpp (register-model build) on the XBAR1 and ENC models:
// quadrature_begin() routes the pads through XBAR1, and quadrature_read/write see the knob's
// counts as the world reports them.
#include <gtest/gtest.h>

#include "backend_rig.hpp"
#include "stepdance/hal/hal.hpp"

namespace {

namespace hal = stepdance::hal;
using stepdance::Status;

TEST(BackendQuadrature, ReadsTheKnobsCountsFromTheBegin) {
  auto& w = backend_rig::reset();
  w.io.encoders[0] = 1000;  // turned before the sketch began
  w.io.encoders[1] = -3;
  ASSERT_EQ(hal::quadrature_begin(0), Status::kOk);
  ASSERT_EQ(hal::quadrature_begin(1), Status::kOk);
  EXPECT_EQ(hal::quadrature_read(0), 0);
  w.io.encoders[0] = 1012;
  w.io.encoders[1] = -10;
  EXPECT_EQ(hal::quadrature_read(0), 12);
  EXPECT_EQ(hal::quadrature_read(1), -7);
  hal::quadrature_write(1, 100000);
  w.io.encoders[1] = -8;
  EXPECT_EQ(hal::quadrature_read(1), 100002);
  EXPECT_EQ(hal::quadrature_read(0), 12);
}

}  // namespace

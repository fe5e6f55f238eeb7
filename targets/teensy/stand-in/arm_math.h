// Stand-in for CMSIS's arm_math.h as Teensyduino ships it: only the two floating-point type names
// Stepdance sketches use (written from the public CMSIS-DSP type definitions).
#pragma once

typedef float float32_t;
typedef double float64_t;

// Registers the stand-in core programs that the backend's regs_*.hpp do not define.
//
// "RM" is the i.MX RT1060 Processor Reference Manual (IMXRT1060RM rev 3); "ARMv7-M ARM" the ARMv7-M
// Architecture Reference Manual. Each address or field carries the section it comes from. Only for
// the stand-in's own sources: Teensyduino's core has its own definitions.
#pragma once

#include <stdint.h>

#include "stepdance/platform/teensy/regs_common.hpp"

namespace stand_in {

/// A 32-bit memory-mapped register, as the backend's register headers access them: a volatile
/// reference on the target, the host register model in tests (STEPDANCE_TEENSY_REGISTER_MODEL).
using Reg32 = stepdance::platform::teensy::regs::Reg32;
/// The 32-bit register at `address`.
inline Reg32 reg32(uint32_t address) { return stepdance::platform::teensy::regs::reg32(address); }

/// Waits for every earlier memory access, then refetches the pipeline (ARMv7-M ARM §A3.8.3).
inline void barrier() {
#if defined(STEPDANCE_TEENSY_REGISTER_MODEL)
  stepdance::platform::teensy::regs::data_sync_barrier();
#else
  __asm__ volatile("dsb\n\tisb" ::: "memory");
#endif
}

// ---- System control block, ARMv7-M ARM §B3.2 ---------------------------------------------------
namespace scb {
constexpr uint32_t kIcsr = 0xE000ED04u;              // §B3.2.4 ICSR
constexpr uint32_t kIcsrPendSysTick = 1u << 26;      //   PENDSTSET: SysTick pending
constexpr uint32_t kVtor = 0xE000ED08u;              // §B3.2.5 VTOR
constexpr uint32_t kCcr = 0xE000ED14u;               // §B3.2.8 CCR
constexpr uint32_t kCcrDataCache = 1u << 16;         //   DC (Cortex-M7 cache enables, §B2.2.7)
constexpr uint32_t kCcrInstructionCache = 1u << 17;  //   IC
constexpr uint32_t kShpr3 = 0xE000ED20u;             // §B3.2.12 SHPR3: PendSV 23:16, SysTick 31:24
constexpr uint32_t kShcsr = 0xE000ED24u;             // §B3.2.13 SHCSR
constexpr uint32_t kShcsrFaultsEnabled = 7u << 16;   //   MEMFAULTENA, BUSFAULTENA, USGFAULTENA
constexpr uint32_t kCpacr = 0xE000ED88u;             // §B3.2.20 CPACR
constexpr uint32_t kCpacrFpuFull = 0xFu << 20;       //   CP10 and CP11 full access: the FPU
constexpr uint32_t kIciallu = 0xE000EF50u;           // §B2.2.7 ICIALLU: invalidate all I-cache
constexpr uint32_t kDcisw = 0xE000EF60u;             // §B2.2.7 DCISW: invalidate D-cache by set/way
}  // namespace scb

// ---- SysTick, ARMv7-M ARM §B3.3 ----------------------------------------------------------------
namespace systick {
constexpr uint32_t kCsr = 0xE000E010u;       // §B3.3.3 SYST_CSR
constexpr uint32_t kCsrEnable = 1u << 0;     //   ENABLE
constexpr uint32_t kCsrTickInt = 1u << 1;    //   TICKINT: exception 15 on each wrap
constexpr uint32_t kCsrCoreClock = 1u << 2;  //   CLKSOURCE = 1: the processor clock
constexpr uint32_t kRvr = 0xE000E014u;       // §B3.3.4 SYST_RVR, 24-bit reload value
constexpr uint32_t kCvr = 0xE000E018u;       // §B3.3.5 SYST_CVR, current value (counts down)
}  // namespace systick

// ---- NVIC, ARMv7-M ARM §B3.4 -------------------------------------------------------------------
namespace nvic {
constexpr uint32_t kIpr0 = 0xE000E400u;  // §B3.4.9 NVIC_IPRn: one priority byte per interrupt
}  // namespace nvic

// ---- MPU, ARMv7-M ARM §B3.5 --------------------------------------------------------------------
namespace mpu {
constexpr uint32_t kCtrl = 0xE000ED94u;           // §B3.5.5 MPU_CTRL
constexpr uint32_t kCtrlEnable = 1u << 0;         //   ENABLE (PRIVDEFENA = 0: region 0 is the map)
constexpr uint32_t kRbar = 0xE000ED9Cu;           // §B3.5.7 MPU_RBAR
constexpr uint32_t kRbarValid = 1u << 4;          //   VALID: REGION (3:0) selects the region
constexpr uint32_t kRasr = 0xE000EDA0u;           // §B3.5.8 MPU_RASR
constexpr uint32_t kRasrEnable = 1u << 0;         //   ENABLE
constexpr uint32_t kRasrExecuteNever = 1u << 28;  //   XN
constexpr uint32_t rasr_size(unsigned log2_bytes) { return (log2_bytes - 1u) << 1; }  // SIZE 5:1
constexpr uint32_t rasr_access(uint32_t ap) { return ap << 24; }                      // AP 26:24
constexpr uint32_t rasr_type(uint32_t tex, uint32_t c, uint32_t b) {                  // §B3.5.9
  return (tex << 19) | (c << 17) | (b << 16);
}
}  // namespace mpu

// ---- DWT cycle counter: regs_dwt.hpp (ARMv7-M ARM §C1.8) ---------------------------------------

// ---- IOMUXC_GPR, RM §11.4 (FlexRAM set-up; GPR26..29 are in regs_iomuxc.hpp) -------------------
namespace gpr {
constexpr uint32_t kBase = 0x400AC000u;
constexpr uint32_t kGpr14 = kBase + 0x38u;  // CM7_CFGITCMSZ 19:16, CM7_CFGDTCMSZ 23:20
constexpr uint32_t kGpr16 = kBase + 0x40u;  // INIT_ITCM_EN 0, INIT_DTCM_EN 1, FLEXRAM_BANK_CFG_SEL 2
constexpr uint32_t kGpr17 = kBase + 0x44u;  // FLEXRAM_BANK_CFG: 2 bits per 32 KB bank
}  // namespace gpr

// ---- CCM, RM §14.7 (CCGRn, CSCMR1 and CSCDR2's neighbours are in regs_ccm.hpp) -----------------
namespace ccm {
constexpr uint32_t kBase = 0x400FC000u;
constexpr uint32_t kCacrr = kBase + 0x10u;                // CACRR: ARM_PODF 2:0
constexpr uint32_t kCbcdr = kBase + 0x14u;                // CBCDR
constexpr uint32_t kCbcdrIpgPodfMask = 3u << 8;           //   IPG_PODF 9:8
constexpr uint32_t kCbcdrAhbPodfMask = 7u << 10;          //   AHB_PODF 12:10
constexpr uint32_t kCbcdrPeriphClkSel = 1u << 25;         //   PERIPH_CLK_SEL: 1 = periph_clk2
constexpr uint32_t kCbcdrPeriphClk2PodfMask = 7u << 27;   //   PERIPH_CLK2_PODF 29:27
constexpr uint32_t kCbcmr = kBase + 0x18u;                // CBCMR
constexpr uint32_t kCbcmrPeriphClk2SelMask = 3u << 12;    //   PERIPH_CLK2_SEL 13:12
constexpr uint32_t kCbcmrPeriphClk2SelOsc = 1u << 12;     //     1 = the 24 MHz oscillator
constexpr uint32_t kCbcmrPrePeriphClkSelMask = 3u << 18;  //   PRE_PERIPH_CLK_SEL 19:18
constexpr uint32_t kCbcmrPrePeriphArmPll = 3u << 18;      //     3 = divided PLL1 (ARM PLL / ARM_PODF)
constexpr uint32_t kCscdr2 = kBase + 0x38u;               // CSCDR2
constexpr uint32_t kCscdr2Lpi2cOsc = 1u << 18;            //   LPI2C_CLK_SEL: 1 = 24 MHz oscillator
constexpr uint32_t kCscdr2Lpi2cPodfMask = 0x3Fu << 19;    //   LPI2C_CLK_PODF 24:19
constexpr uint32_t kCdhipr = kBase + 0x48u;               // CDHIPR: handshake busy flags
constexpr uint32_t kCdhiprAhbPodfBusy = 1u << 1;
constexpr uint32_t kCdhiprPeriph2ClkSelBusy = 1u << 3;
constexpr uint32_t kCdhiprPeriphClkSelBusy = 1u << 5;
constexpr uint32_t kCdhiprArmPodfBusy = 1u << 16;
}  // namespace ccm

// ---- CCM_ANALOG (PLLs), RM §14.8 ---------------------------------------------------------------
namespace analog {
constexpr uint32_t kBase = 0x400D8000u;
constexpr uint32_t kPllArm = kBase + 0x00u;              // CCM_ANALOG_PLL_ARM
constexpr uint32_t kPllArmDivSelectMask = 0x7Fu;         //   DIV_SELECT 6:0: Fout = 24 MHz × DIV_SELECT / 2
constexpr uint32_t kPllArmPowerDown = 1u << 12;          //   POWERDOWN
constexpr uint32_t kPllArmEnable = 1u << 13;             //   ENABLE (output)
constexpr uint32_t kPllArmBypass = 1u << 16;             //   BYPASS
constexpr uint32_t kPllLock = 1u << 31;                  //   LOCK (all PLLs)
constexpr uint32_t kPllUsb1 = kBase + 0x10u;             // CCM_ANALOG_PLL_USB1
constexpr uint32_t kPllUsb1Set = kBase + 0x14u;          //   its SET alias
constexpr uint32_t kPllUsb1Clr = kBase + 0x18u;          //   its CLR alias
constexpr uint32_t kPllUsb1DivSelect = 1u << 1;          //   DIV_SELECT: 0 = 20 × 24 MHz = 480 MHz
constexpr uint32_t kPllUsb1EnUsbClks = 1u << 6;          //   EN_USB_CLKS
constexpr uint32_t kPllUsb1Power = 1u << 12;             //   POWER
constexpr uint32_t kPllUsb1Enable = 1u << 13;            //   ENABLE
constexpr uint32_t kPllUsb1BypassClkSrcMask = 3u << 14;  // BYPASS_CLK_SRC: 0 = 24 MHz oscillator
constexpr uint32_t kPllUsb1Bypass = 1u << 16;            //   BYPASS
}  // namespace analog

// ---- PMU, RM "Power Management Unit" chapter (PMU_MISC0 at the CCM_ANALOG base + 0x150) --------
namespace pmu {
constexpr uint32_t kMisc0Set = 0x400D8154u;            // PMU_MISC0_SET
constexpr uint32_t kMisc0RefTopSelfBiasOff = 1u << 3;  // REFTOP_SELFBIASOFF: bandgap bias currents
}  // namespace pmu

// ---- DCDC converter, RM "DCDC Converter" chapter -----------------------------------------------
namespace dcdc {
constexpr uint32_t kBase = 0x40080000u;
constexpr uint32_t kReg0 = kBase + 0x00u;    // DCDC_REG0
constexpr uint32_t kReg0StsDcOk = 1u << 31;  //   STS_DC_OK: output has settled
constexpr uint32_t kReg3 = kBase + 0x0Cu;    // DCDC_REG3
constexpr uint32_t kReg3TrgMask = 0x1Fu;     //   TRG 4:0: VDD_SOC = 0.8 V + TRG × 25 mV
}  // namespace dcdc

// ---- LPI2C, RM "Low Power Inter-Integrated Circuit" chapter ------------------------------------
namespace lpi2c {
constexpr uint32_t kLpi2c1Base = 0x403F0000u;
constexpr uint32_t kLpi2c3Base = 0x403F8000u;
constexpr uint32_t kMcr = 0x10u;                    // MCR
constexpr uint32_t kMcrEnable = 1u << 0;            //   MEN
constexpr uint32_t kMcrReset = 1u << 1;             //   RST
constexpr uint32_t kMcrResetTxFifo = 1u << 8;       //   RTF
constexpr uint32_t kMcrResetRxFifo = 1u << 9;       //   RRF
constexpr uint32_t kMsr = 0x14u;                    // MSR (flags write 1 to clear)
constexpr uint32_t kMsrStopDetected = 1u << 9;      //   SDF
constexpr uint32_t kMsrNack = 1u << 10;             //   NDF
constexpr uint32_t kMsrArbitrationLost = 1u << 11;  // ALF
constexpr uint32_t kMsrFifoError = 1u << 12;        //   FEF
constexpr uint32_t kMsrPinLowTimeout = 1u << 13;    // PLTF
constexpr uint32_t kMsrClearable = 0x7Fu << 8;      //   EPF..DMF, bits 14:8
constexpr uint32_t kMsrMasterBusy = 1u << 24;       //   MBF
constexpr uint32_t kMsrBusBusy = 1u << 25;          //   BBF
constexpr uint32_t kMcfgr0 = 0x20u;                 // MCFGR0
constexpr uint32_t kMcfgr1 = 0x24u;                 // MCFGR1: PRESCALE 2:0
constexpr uint32_t kMcfgr2 = 0x28u;                 // MCFGR2: BUSIDLE 11:0, FILTSCL 19:16, FILTSDA 27:24
constexpr uint32_t kMcfgr3 = 0x2Cu;                 // MCFGR3: PINLOW 19:8
constexpr uint32_t kMccr0 = 0x48u;                  // MCCR0: CLKLO 5:0, CLKHI 13:8, SETHOLD 21:16, DATAVD 29:24
constexpr uint32_t kMccr1 = 0x50u;                  // MCCR1 (high-speed mode timing)
constexpr uint32_t kMfcr = 0x58u;                   // MFCR: TXWATER 1:0, RXWATER 17:16
constexpr uint32_t kMfsr = 0x5Cu;                   // MFSR: TXCOUNT 2:0, RXCOUNT 18:16
constexpr uint32_t kMtdr = 0x60u;                   // MTDR: DATA 7:0, CMD 10:8
constexpr uint32_t kCmdTransmit = 0u << 8;
constexpr uint32_t kCmdReceive = 1u << 8;  //   receive DATA + 1 bytes
constexpr uint32_t kCmdStop = 2u << 8;
constexpr uint32_t kCmdStart = 4u << 8;  //   (repeated) START, then the address byte in DATA
constexpr uint32_t kMrdr = 0x70u;        // MRDR: DATA 7:0, RXEMPTY 14
constexpr uint32_t kMrdrEmpty = 1u << 14;
constexpr unsigned kFifoWords = 4;  // PARAM: MTXFIFO = MRXFIFO = 4 words on the RT1062
}  // namespace lpi2c

// ---- IOMUXC daisy chain (input selects) for LPI2C1 and LPI2C3, RM §11.7 ------------------------
namespace daisy {
constexpr uint16_t kLpi2c1Scl = 0x4CC;  // IOMUXC_LPI2C1_SCL_SELECT_INPUT: 1 = GPIO_AD_B1_00
constexpr uint16_t kLpi2c1Sda = 0x4D0;  // IOMUXC_LPI2C1_SDA_SELECT_INPUT: 1 = GPIO_AD_B1_01
constexpr uint16_t kLpi2c3Scl = 0x4DC;  // IOMUXC_LPI2C3_SCL_SELECT_INPUT: 2 = GPIO_AD_B1_07
constexpr uint16_t kLpi2c3Sda = 0x4E0;  // IOMUXC_LPI2C3_SDA_SELECT_INPUT: 2 = GPIO_AD_B1_06
}  // namespace daisy

}  // namespace stand_in

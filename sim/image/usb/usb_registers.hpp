// The USB1 OTG controller's device-mode registers and data structures, as offsets and bits.
//
// "RM" is the i.MX RT1060 Processor Reference Manual (IMXRT1060RM rev 3): chapter 42 "Universal
// Serial Bus Controller (USB)" (register map USB_n*, and the device data structures: endpoint
// queue head and transfer descriptor), and chapter 43 "USB PHY" (USBPHYn_*). Teensyduino 1.59's
// usb.c programs the same registers (its comments cite rev-2 page numbers).
#pragma once

#include <cstdint>

namespace stepdance::sim::image::usb {

constexpr uint32_t kUsb1Base = 0x402E0000u;     // RM ch. 2 memory map: USB1 (USBOTG1) 0x402E_0000
constexpr uint32_t kUsb1SizeBytes = 0x200u;     // USB1 registers end at 0x402E_01FF (USB2 follows)
constexpr uint32_t kUsbPhy1Base = 0x400D9000u;  // RM ch. 2 memory map: USBPHY1
constexpr uint32_t kUsbPhy1SizeBytes = 0x1000u;
constexpr unsigned kIrqUsb1 = 113;  // RM ch. 4, CM7 interrupt 113: USB OTG1
constexpr int8_t kUsbGateCcgr = 6;  // CCM_CCGR6 CG0: usboh3_clk_enable (RM 14.7.27)
constexpr int8_t kUsbGateField = 0;

// ---- USB_n register offsets (RM 42.7 register map) ----
constexpr uint32_t kGpTimer0Ld = 0x080;      // USB_nGPTIMER0LD: load value, µs − 1 (bits 23:0)
constexpr uint32_t kGpTimer0Ctrl = 0x084;    // USB_nGPTIMER0CTRL: RUN 31, RST 30, MODE 24, CNT 23:0
constexpr uint32_t kGpTimer1Ld = 0x088;      // USB_nGPTIMER1LD
constexpr uint32_t kGpTimer1Ctrl = 0x08C;    // USB_nGPTIMER1CTRL
constexpr uint32_t kUsbCmd = 0x140;          // USB_nUSBCMD
constexpr uint32_t kUsbSts = 0x144;          // USB_nUSBSTS (write 1 to clear)
constexpr uint32_t kUsbIntr = 0x148;         // USB_nUSBINTR
constexpr uint32_t kFrIndex = 0x14C;         // USB_nFRINDEX (read only in device mode)
constexpr uint32_t kDeviceAddr = 0x154;      // USB_nDEVICEADDR (device mode)
constexpr uint32_t kEndptListAddr = 0x158;   // USB_nENDPTLISTADDR (device mode)
constexpr uint32_t kBurstSize = 0x160;       // USB_nBURSTSIZE
constexpr uint32_t kTxFillTuning = 0x164;    // USB_nTXFILLTUNING
constexpr uint32_t kPortSc1 = 0x184;         // USB_nPORTSC1
constexpr uint32_t kUsbMode = 0x1A8;         // USB_nUSBMODE
constexpr uint32_t kEndptSetupStat = 0x1AC;  // USB_nENDPTSETUPSTAT (write 1 to clear)
constexpr uint32_t kEndptPrime = 0x1B0;      // USB_nENDPTPRIME
constexpr uint32_t kEndptFlush = 0x1B4;      // USB_nENDPTFLUSH
constexpr uint32_t kEndptStat = 0x1B8;       // USB_nENDPTSTAT (read only)
constexpr uint32_t kEndptComplete = 0x1BC;   // USB_nENDPTCOMPLETE (write 1 to clear)
constexpr uint32_t kEndptCtrl0 = 0x1C0;      // USB_nENDPTCTRL0..7, 4 bytes apart
constexpr unsigned kEndpoints = 8;           // endpoints 0..7 in each direction

// ---- USBCMD bits (RM 42.7, USB_nUSBCMD) ----
constexpr uint32_t kCmdRunStop = 1u << 0;          // RS: attach (device mode: pull-up on D+)
constexpr uint32_t kCmdReset = 1u << 1;            // RST: controller reset, cleared when done
constexpr uint32_t kCmdSetupTripwire = 1u << 13;   // SUTW: cleared by hardware when a setup lands
constexpr uint32_t kCmdAddDtdTripwire = 1u << 14;  // ATDTW
constexpr uint32_t kCmdResetValue = 0x00080000u;   // ITC = 8 microframes
constexpr uint32_t kCmdWritable = 0x00FFEB7Fu;     // ITC 23:16, FS2, ATDTW, SUTW, ASPE, ASP, IAA..RS

// ---- USBSTS / USBINTR bits (RM 42.7, USB_nUSBSTS and USB_nUSBINTR share positions) ----
constexpr uint32_t kStsUi = 1u << 0;    // USBINT: a transfer with IOC completed, or a setup landed
constexpr uint32_t kStsUei = 1u << 1;   // USBERRINT
constexpr uint32_t kStsPci = 1u << 2;   // port change: device mode, end of bus reset / resume
constexpr uint32_t kStsSei = 1u << 4;   // system error
constexpr uint32_t kStsUri = 1u << 6;   // USB reset received
constexpr uint32_t kStsSri = 1u << 7;   // SOF received
constexpr uint32_t kStsSli = 1u << 8;   // DCSuspend
constexpr uint32_t kStsTi0 = 1u << 24;  // general-purpose timer 0 expired
constexpr uint32_t kStsTi1 = 1u << 25;  // general-purpose timer 1 expired
/// The status bits a write of 1 clears (R/WC in the RM) and that can interrupt.
constexpr uint32_t kStsClearable = kStsUi | kStsUei | kStsPci | (1u << 3) | kStsSei | (1u << 5) | kStsUri | kStsSri |
                                   kStsSli | (1u << 10) | kStsTi0 | kStsTi1;
/// USBINTR's implemented enables: UE..SLE 8:0, ULPIE 10, NAKE 16, UAIE 18, UPIE 19, TIE0/1 25:24.
constexpr uint32_t kIntrWritable = 0x030D05FFu;

// ---- DEVICEADDR (RM 42.7, USB_nDEVICEADDR) ----
constexpr unsigned kDeviceAddrShift = 25;          // USBADR 31:25
constexpr uint32_t kDeviceAddrAdvance = 1u << 24;  // USBADRA: take the address after the next EP0 IN

// ---- PORTSC1 (RM 42.7, USB_nPORTSC1), device-mode view ----
constexpr uint32_t kPortCcs = 1u << 0;    // current connect status: attached (RS) and reset done
constexpr uint32_t kPortPe = 1u << 2;     // port enabled: always 1 in device mode after reset
constexpr uint32_t kPortSusp = 1u << 7;   // suspend
constexpr uint32_t kPortPr = 1u << 8;     // port reset: 1 while the host drives reset
constexpr uint32_t kPortHsp = 1u << 9;    // high-speed port
constexpr uint32_t kPortPhcd = 1u << 23;  // PHY low-power suspend (clock disable), R/W
constexpr uint32_t kPortPfsc = 1u << 24;  // port force full-speed connect, R/W
constexpr unsigned kPortPspdShift = 26;   // PSPD 27:26: 0 full speed, 2 high speed
constexpr uint32_t kPortPtw = 1u << 28;   // parallel transceiver width: 1 = 16 bit (UTMI, reset 1)
/// Bits software may write in device mode: PTC 19:16, PHCD, PFSC, STS 29, PTW.
constexpr uint32_t kPortWritable = 0x000F0000u | kPortPhcd | kPortPfsc | (1u << 29) | kPortPtw;

// ---- USBMODE (RM 42.7, USB_nUSBMODE) ----
constexpr uint32_t kModeCmMask = 3u;  // CM: 0 idle, 2 device, 3 host
constexpr uint32_t kModeCmDevice = 2u;
constexpr uint32_t kModeWritable = 0x1Fu;  // CM 1:0, ES 2, SLOM 3, SDIS 4

// ---- ENDPTCTRLn (RM 42.7, USB_nENDPTCTRLn): receive half 7:0, transmit half 23:16 ----
constexpr uint32_t kCtrlRxStall = 1u << 0;
constexpr uint32_t kCtrlRxReset = 1u << 6;  // data toggle reset, write only
constexpr uint32_t kCtrlRxEnable = 1u << 7;
constexpr uint32_t kCtrlTxStall = 1u << 16;
constexpr uint32_t kCtrlTxReset = 1u << 22;
constexpr uint32_t kCtrlTxEnable = 1u << 23;
constexpr uint32_t kCtrlWritable = 0x00AD00ADu;     // per half: stall 0, type 3:2, toggle inhibit 5, enable 7
constexpr uint32_t kCtrl0ResetValue = 0x00800080u;  // control endpoint 0: both halves enabled

// ---- General-purpose timers (RM 42.7, USB_nGPTIMERnCTRL) ----
constexpr uint32_t kGptRun = 1u << 31;
constexpr uint32_t kGptReset = 1u << 30;   // write 1: reload the counter from GPTLD
constexpr uint32_t kGptRepeat = 1u << 24;  // GPTMODE: 0 one-shot, 1 repeat
constexpr uint32_t kGptCountMask = 0x00FFFFFFu;

// ---- Device endpoint queue head, dQH (RM 42.5.x "Endpoint Queue Head"): 48 bytes, 64 apart ----
constexpr uint32_t kDqhStrideBytes = 64;
constexpr uint32_t kDqhCapabilities = 0x00;  // MULT 31:30, ZLT 29 (1 = no zero-length end), MPL 26:16, IOS 15
constexpr uint32_t kDqhCurrentDtd = 0x04;    // written by the controller
constexpr uint32_t kDqhOverlay = 0x08;       // the active dTD's copy: next, token, five pages
constexpr uint32_t kDqhSetupBuffer = 0x28;   // the last setup packet, 8 bytes
constexpr uint32_t kCapIos = 1u << 15;
constexpr uint32_t kCapZltDisabled = 1u << 29;
constexpr unsigned kCapMaxPacketShift = 16;
constexpr uint32_t kCapMaxPacketMask = 0x7FFu;

// ---- Device transfer descriptor, dTD (RM 42.5.x "Endpoint Transfer Descriptor"): 28 bytes ----
constexpr uint32_t kDtdNext = 0x00;   // next dTD pointer 31:5, T (terminate) bit 0
constexpr uint32_t kDtdToken = 0x04;  // total bytes 30:16, IOC 15, MultO 11:10, status 7:0
constexpr uint32_t kDtdPages = 0x08;  // buffer pointers 0..4; page 0 carries the offset 11:0
constexpr uint32_t kDtdBytes = 28;
constexpr uint32_t kDtdTerminate = 1u << 0;
constexpr uint32_t kTokenActive = 1u << 7;
constexpr uint32_t kTokenHalted = 1u << 6;
constexpr uint32_t kTokenBufferError = 1u << 5;
constexpr uint32_t kTokenIoc = 1u << 15;
constexpr unsigned kTokenTotalShift = 16;
constexpr uint32_t kTokenTotalMask = 0x7FFFu;

}  // namespace stepdance::sim::image::usb

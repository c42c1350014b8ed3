# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""The motor-control board as data: every part, its library symbol and footprint, its order codes,
and which net each pin joins. The schematic and the board are both generated from this table.

Board: one CAN node driving two brushed DC motors (one iCub joint pair), built three times for the
head. Nets named here become local labels; GND, +3V3, +5V and +12V are power symbols.
"""
from dataclasses import dataclass, field

POWER_NETS = ("GND", "+3V3", "+5V", "+12V")
# The board's revision: the schematic's and the board's title blocks, the silkscreen, the Gerber job file and
# the catalog's bare-board entry all carry it (tests/electronics/test_revision.py reads them all).
REVISION = "D"
NC = None  # pin deliberately left open: gets a no-connect flag


@dataclass
class Part:
    ref: str
    lib_id: str
    value: str
    footprint: str
    mpn: str
    manufacturer: str
    pins: dict  # pin number -> net name, or NC
    block: str
    description: str = ""
    in_bom: bool = True
    extra: dict = field(default_factory=dict)


def _r(ref, value, a, b, block, mpn, footprint="Resistor_SMD:R_0603_1608Metric", manufacturer="Yageo"):
    return Part(ref, "Device:R", value, footprint, mpn, manufacturer, {"1": a, "2": b}, block)


def _c(ref, value, a, b, block, mpn, footprint="Capacitor_SMD:C_0603_1608Metric", manufacturer="Murata"):
    return Part(ref, "Device:C", value, footprint, mpn, manufacturer, {"1": a, "2": b}, block)


JST_PH = "Connector_JST:JST_PH_B{n}B-PH-K_1x0{n}_P2.00mm_Vertical"
JST_VH2 = "Connector_JST:JST_VH_B2P-VH_1x02_P3.96mm_Vertical"


def _power_parts():
    b = "power"
    return [
        # Daisy chain: J1 takes the supply in, J5 passes it on to the next board. The pass-through is the
        # raw input (before this board's fuse), so each board's fuse carries only its own current.
        Part("J1", "Connector_Generic:Conn_01x02", "12V_IN", JST_VH2, "B2P-VH(LF)(SN)", "JST",
             {"1": "VIN_RAW", "2": "GND"}, b, "supply input, 12 V (daisy chain in)"),
        Part("J5", "Connector_Generic:Conn_01x02", "12V_OUT", JST_VH2, "B2P-VH(LF)(SN)", "JST",
             {"1": "VIN_RAW", "2": "GND"}, b, "supply output to the next board (daisy chain out)"),
        Part("F1", "Device:Fuse", "5A", "Fuse:Fuse_Littelfuse-NANO2-451_453", "0451005.MRL", "Littelfuse",
             {"1": "VIN_RAW", "2": "VIN_FUSED"}, b),
        # Reverse-polarity protection first: P-MOSFET in the positive rail, drain to the input, gate pulled
        # to GND, Vgs clamped. A reversed supply leaves it off (its body diode is reversed too), so no current
        # flows and the fuse survives. The TVS sits after it, on +12V: in rev B it sat before the FET, and a
        # reversed supply forward-biased it through the soldered fuse.
        Part("Q1", "Transistor_FET:DMP3013SFV", "DMP3013SFV", "Package_SON:Diodes_PowerDI3333-8",
             "DMP3013SFV-7", "Diodes Incorporated",
             {"1": "+12V", "2": "+12V", "3": "+12V", "4": "Q1_GATE", "5": "VIN_FUSED"}, b),
        _r("R1", "10k", "Q1_GATE", "GND", b, "RC0603FR-0710KL"),
        Part("D2", "Device:D_Zener", "BZT52C10", "Diode_SMD:D_SOD-123", "BZT52C10-7-F", "Diodes Incorporated",
             {"1": "+12V", "2": "Q1_GATE"}, b, "gate clamp"),
        Part("D1", "Diode:SMAJ15A", "SMAJ15A", "Diode_SMD:D_SMA", "SMAJ15A", "Littelfuse",
             {"1": "+12V", "2": "GND"}, b, "TVS, after the reverse-polarity FET"),
        Part("C1", "Device:C_Polarized", "47u/25V", "Capacitor_SMD:CP_Elec_6.3x7.7", "EEE-FK1E470P", "Panasonic",
             {"1": "+12V", "2": "GND"}, b),
        _r("R2", "47k", "+12V", "VBUS_SENSE", b, "RC0603FR-0747KL"),
        _r("R3", "10k", "VBUS_SENSE", "GND", b, "RC0603FR-0710KL"),
        _c("C2", "100n", "VBUS_SENSE", "GND", b, "GCM188R71H104KA57D"),
        # The buck takes its input through a ferrite bead: it keeps the drivers' switching current off the
        # buck, and it lets the motor rail (+12V, wide copper) and the buck's small-pad input be separate nets.
        Part("FB1", "Device:FerriteBead_Small", "600R@100MHz", "Inductor_SMD:L_0805_2012Metric", "BLM21PG601SN1D",
             "Murata", {"1": "+12V", "2": "VIN_BUCK"}, b, "buck input filter"),
        # 12 V -> 5 V buck (encoders, level shifter), then 5 V -> 3.3 V LDO (logic, CAN, current amplifiers).
        Part("U2", "Regulator_Switching:AP63205WU", "AP63205WU", "Package_TO_SOT_SMD:TSOT-23-6",
             "AP63205WU-7", "Diodes Incorporated",
             {"1": "+5V", "2": "VIN_BUCK", "3": "VIN_BUCK", "4": "GND", "5": "SW_5V", "6": "BST_5V"}, b),
        _c("C3", "10u/25V", "VIN_BUCK", "GND", b, "GRM31CR61E106KA12L", "Capacitor_SMD:C_1206_3216Metric"),
        _c("C4", "100n", "BST_5V", "SW_5V", b, "GCM188R71H104KA57D"),
        Part("L1", "Device:L", "4.7u", "Inductor_SMD:L_Bourns-SRN4018", "SRN4018-4R7M", "Bourns",
             {"1": "SW_5V", "2": "+5V"}, b),
        _c("C5", "22u/10V", "+5V", "GND", b, "GRM31CR61A226KE19L", "Capacitor_SMD:C_1206_3216Metric"),
        _c("C6", "22u/10V", "+5V", "GND", b, "GRM31CR61A226KE19L", "Capacitor_SMD:C_1206_3216Metric"),
        Part("U3", "Regulator_Linear:AP2112K-3.3", "AP2112K-3.3", "Package_TO_SOT_SMD:SOT-23-5",
             "AP2112K-3.3TRG1", "Diodes Incorporated",
             {"1": "+5V", "2": "GND", "3": "+5V", "4": NC, "5": "+3V3"}, b),
        _c("C7", "1u", "+5V", "GND", b, "GRM188R71C105KA12D"),
        _c("C8", "1u", "+3V3", "GND", b, "GRM188R71C105KA12D"),
    ]


def _mcu_parts():
    b = "mcu"
    # Rev D: every GPIO of the LQFP-32 is taken, so the two brake gates take PB5 (AEA MOSI, which only ever
    # sent 0xFFFF: R11 now holds it high alone) and PA4 (the LED, which moves to PB8-BOOT0: the pin is BOOT0
    # only while reset is released, and the LED's 1k and R4 keep it low then).
    pins = {
        "1": "+3V3", "17": "+3V3", "15": "+3V3", "16": "GND", "32": "GND", "14": "GND",
        "4": "NRST", "2": "HSE_IN", "3": "HSE_OUT", "13": "VBUS_SENSE",
        "26": "AEA_CLK", "27": "AEA_DO", "28": "M1_BRAKE", "29": "M2_QA", "30": "M2_QB", "31": "BOOT0",
        "5": "M1_QA", "6": "M1_QB", "7": "M2_IN1", "8": "M2_IN2", "9": "M2_BRAKE", "10": "M2_AEA_CS",
        "11": "M1_ISENSE", "12": "M2_ISENSE", "18": "M1_IN1", "19": "M1_IN2", "20": "MOT_FAULT",
        "21": "CAN_RX", "22": "CAN_TX", "23": "SWDIO", "24": "SWCLK", "25": "M1_AEA_CS",
    }
    return [
        Part("U1", "MCU_ST_STM32G4:STM32G431KBTx", "STM32G431KBT6", "Package_QFP:LQFP-32_7x7mm_P0.8mm",
             "STM32G431KBT6", "STMicroelectronics", pins, b, "Cortex-M4 with FDCAN"),
        _c("C9", "100n", "+3V3", "GND", b, "GCM188R71H104KA57D"),
        _c("C10", "100n", "+3V3", "GND", b, "GCM188R71H104KA57D"),
        _c("C11", "1u", "+3V3", "GND", b, "GRM188R71C105KA12D"),
        _c("C12", "4.7u", "+3V3", "GND", b, "GRM188R61A475KE15D"),
        _r("R4", "10k", "BOOT0", "GND", b, "RC0603FR-0710KL"),
        _c("C13", "100n", "NRST", "GND", b, "GCM188R71H104KA57D"),
        Part("Y1", "Device:Crystal_GND24", "8MHz", "Crystal:Crystal_SMD_3225-4Pin_3.2x2.5mm",
             "ABM8-8.000MHZ-B2-T", "Abracon", {"1": "HSE_IN", "2": "GND", "3": "HSE_OUT", "4": "GND"}, b),
        _c("C14", "10p", "HSE_IN", "GND", b, "GRM1885C1H100JA01D"),
        _c("C15", "10p", "HSE_OUT", "GND", b, "GRM1885C1H100JA01D"),
        _r("R5", "1k", "BOOT0", "LED_A", b, "RC0603FR-071KL"),
        Part("D3", "Device:LED", "green", "LED_SMD:LED_0603_1608Metric", "150060GS75000", "Wurth Elektronik",
             {"1": "GND", "2": "LED_A"}, b, "status LED"),
        # Programming and recovery on a right-angle header at the board's edge, reachable from the side when
        # the boards are stacked. Pins 1-5 follow ST-LINK's 6-pin SWD connector (VDD, SWCLK, GND, SWDIO, NRST);
        # pin 6 is BOOT0 (an ST-LINK pin 6 is SWO, a probe input, so a probe never drives it). Tie pin 6 to
        # pin 1 and pulse NRST to start the STM32G4's ROM bootloader, which also listens on FDCAN1 (PA11/PA12).
        Part("J4", "Connector_Generic:Conn_01x06", "SWD/BOOT", "Connector_PinHeader_2.54mm:PinHeader_1x06_P2.54mm_Horizontal",
             "TSW-106-08-G-S-RA", "Samtec",
             {"1": "+3V3", "2": "SWCLK", "3": "GND", "4": "SWDIO", "5": "NRST", "6": "BOOT0"}, b,
             "programming header at the edge (SWD, reset, BOOT0)"),
    ]


def _can_parts():
    b = "can"
    jst3 = JST_PH.format(n=3)
    return [
        Part("U4", "Interface_CAN_LIN:SN65HVD230", "SN65HVD230", "Package_SO:SOIC-8_3.9x4.9mm_P1.27mm",
             "SN65HVD230DR", "Texas Instruments",
             {"1": "CAN_TX", "2": "GND", "3": "+3V3", "4": "CAN_RX", "5": NC, "6": "CANL", "7": "CANH", "8": "GND"}, b),
        _c("C16", "100n", "+3V3", "GND", b, "GCM188R71H104KA57D"),
        Part("D4", "Power_Protection:NUP2105L", "NUP2105L", "Package_TO_SOT_SMD:SOT-23",
             "NUP2105LT1G", "onsemi", {"1": "CANH", "2": "CANL", "3": "GND"}, b, "CAN ESD"),
        Part("J2", "Connector_Generic:Conn_01x03", "CAN", jst3, "B3B-PH-K-S(LF)(SN)", "JST",
             {"1": "CANH", "2": "CANL", "3": "GND"}, b, "CAN bus in"),
        Part("J3", "Connector_Generic:Conn_01x03", "CAN", jst3, "B3B-PH-K-S(LF)(SN)", "JST",
             {"1": "CANH", "2": "CANL", "3": "GND"}, b, "CAN bus out (daisy chain)"),
        # Termination only on the last node of the chain: fit the jumper there.
        Part("JP1", "Jumper:Jumper_2_Open", "TERM", "Connector_PinHeader_2.54mm:PinHeader_1x02_P2.54mm_Vertical",
             "61300211121", "Wurth Elektronik", {"1": "CANH", "2": "CAN_TERM"}, b, "120 ohm termination on/off"),
        _r("R6", "120", "CAN_TERM", "CANL", b, "RC1206FR-07120RL", "Resistor_SMD:R_1206_3216Metric"),
    ]


def _axis_parts(n, first):
    """One motor channel: H-bridge, inline shunt + amplifier, motor and encoder connectors, and the
    buffer between the quadrature encoder and the MCU."""
    b = f"axis{n}"
    m = f"M{n}_"
    u_drv, u_amp, u_buf = f"U{first}", f"U{first + 1}", f"U{8 + n}"
    return [
        Part(u_drv, "Driver_Motor:DRV8872DDA", "DRV8872DDA", "Package_SO:Texas_HTSOP-8-1EP_3.9x4.9mm_P1.27mm_EP2.95x4.9mm_Mask2.4x3.1mm_ThermalVias",
             "DRV8872DDAR", "Texas Instruments",
             {"1": "GND", "9": "GND", "2": m + "IN2", "3": m + "IN1", "4": "MOT_FAULT", "5": "+12V",
              "6": m + "OUT1", "8": m + "OUT2", "7": "GND"}, b, f"H-bridge, motor {n}"),
        _c(f"C{20 + 10 * n}", "10u/25V", "+12V", "GND", b, "GRM31CR61E106KA12L", "Capacitor_SMD:C_1206_3216Metric"),
        _c(f"C{21 + 10 * n}", "100n", "+12V", "GND", b, "GCM188R71H104KA57D"),
        # Four-terminal (Kelvin) shunt: the motor current flows through pads 1 and 4 on wide copper; the
        # amplifier reads pads 2 and 3 on their own thin nets, so no motor current has to pass the
        # amplifier's 0.65 mm-pitch pins (rev B ran it there, on 0.45 mm tracks).
        Part(f"R{20 + 10 * n}", "Device:R_Shunt", "20m", "Resistor_SMD:R_Shunt_Vishay_WSK2512_6332Metric_T1.19mm",
             "WSK2512R0200FEA", "Vishay", {"1": m + "OUT1", "4": m + "MA", "2": m + "SNS_P", "3": m + "SNS_N"}, b,
             f"current shunt, motor {n} (Kelvin)"),
        # Inline (motor-lead) sensing gives the signed motor current in every decay mode;
        # REF1=3V3, REF2=GND puts zero current at mid-scale.
        Part(u_amp, "Amplifier_Current:INA240A1PW", "INA240A1PW", "Package_SO:TSSOP-8_4.4x3mm_P0.65mm",
             "INA240A1PWR", "Texas Instruments",
             {"1": "GND", "4": "GND", "2": m + "SNS_P", "3": m + "SNS_N", "5": "+3V3", "6": "GND", "7": "+3V3",
              "8": m + "ISENSE"}, b, f"current sense amplifier, motor {n}"),
        _c(f"C{22 + 10 * n}", "100n", "+3V3", "GND", b, "GCM188R71H104KA57D"),
        Part(f"J{10 + 10 * n}", "Connector_Generic:Conn_01x02", "MOTOR", JST_VH2, "B2P-VH(LF)(SN)", "JST",
             {"1": m + "MA", "2": m + "OUT2"}, b, f"motor {n}"),
        Part(f"J{11 + 10 * n}", "Connector_Generic:Conn_01x04", "QENC", JST_PH.format(n=4), "B4B-PH-K-S(LF)(SN)", "JST",
             {"1": "+5V", "2": m + "ENC_A", "3": m + "ENC_B", "4": "GND"}, b, f"motor encoder {n} (quadrature)",
             extra={"external": {"2": ("faulhaber-IE2-512", "A"), "3": ("faulhaber-IE2-512", "B")}}),
        # The encoder runs on 5 V and drives its outputs to 5 V. The MCU pins must not see that: PA0/PA1
        # are 3.6 V-tolerant analog pins, and no pin may be driven while 3.3 V is down. The buffer runs on
        # 3.3 V, its inputs take 5.5 V with or without supply (Ioff), and its Schmitt inputs square up
        # slow edges. The pull-downs hold the inputs low when no encoder is plugged in.
        Part(u_buf, "74xGxx:74LVC2G17", "74LVC2G17", "Package_TO_SOT_SMD:SOT-23-6", "SN74LVC2G17DBVR",
             "Texas Instruments", {"1": m + "ENC_A", "6": m + "QA", "3": m + "ENC_B", "4": m + "QB",
                                   "5": "+3V3", "2": "GND"}, b, f"encoder buffer, motor {n} (5 V in, 3.3 V out)"),
        _c(f"C{23 + 10 * n}", "100n", "+3V3", "GND", b, "GCM188R71H104KA57D"),
        _r(f"R{21 + 10 * n}", "10k", m + "ENC_A", "GND", b, "RC0603FR-0710KL"),
        _r(f"R{22 + 10 * n}", "10k", m + "ENC_B", "GND", b, "RC0603FR-0710KL"),
        # The absolute encoder (AS5048A, SPI mode, 5 V) needs CLK, CS and MOSI at 5 V logic (VIH 0.7 VDD =
        # 3.5 V): they come from the 5 V level shifter U12. MOSI idles high, which is the read-angle command.
        Part(f"J{12 + 10 * n}", "Connector_Generic:Conn_01x06", "AEA", JST_PH.format(n=6), "B6B-PH-K-S(LF)(SN)", "JST",
             {"1": "+5V", "2": "AEA_CLK_5V", "3": m + "AEA_CS_5V", "4": "AEA_ENC_DO", "5": "AEA_MOSI_5V", "6": "GND"}, b,
             f"joint encoder {n} (absolute, AS5048A SPI)", extra={"external": {
                 "2": ("ams-AS5048A", "CLK"), "3": ("ams-AS5048A", "CSn"), "4": ("ams-AS5048A", "MISO"),
                 "5": ("ams-AS5048A", "MOSI")}}),
    ]


def _brake_parts(n):
    """One holding-brake output (rev D): the motor's power-off brake is released while its 12 V coil is
    powered. A low-side logic-level N-MOSFET switches the coil's return, its gate straight from an MCU pin
    (it switches only when the axis is enabled or disabled, so no gate resistor is needed to tame the edges,
    and the level check sees the MCU pin and the gate on one net); the pull-down holds the gate low, the
    brake applied, while the MCU is in reset or its pin is still an input. The flyback diode takes the coil's
    current when the switch opens (the brake then engages as that current decays, within milliseconds)."""
    b = f"axis{n}"
    m = f"M{n}_"
    return [
        Part(f"Q{20 + 10 * n}", "Transistor_FET:AO3400A", "AO3400A", "Package_TO_SOT_SMD:SOT-23", "AO3400A",
             "Alpha & Omega Semiconductor", {"1": m + "BRAKE", "2": "GND", "3": m + "BRAKE_N"}, b,
             f"brake switch, motor {n} (low side)"),
        _r(f"R{23 + 10 * n}", "100k", m + "BRAKE", "GND", b, "RC0603FR-07100KL"),
        Part(f"D{20 + 10 * n}", "Device:D", "MBR0540", "Diode_SMD:D_SOD-123", "MBR0540T1G", "onsemi",
             {"1": "+12V", "2": m + "BRAKE_N"}, b, f"brake coil flyback, motor {n}"),
        Part(f"J{13 + 10 * n}", "Connector_Generic:Conn_01x02", "BRAKE", JST_PH.format(n=2), "B2B-PH-K-S(LF)(SN)",
             "JST", {"1": "+12V", "2": m + "BRAKE_N"}, b, f"holding brake {n} (12 V coil, switched low side)"),
    ]


def _aea_parts():
    """The absolute encoders' shared data line (each encoder drives it while its chip select is low)
    reaches PB4 through a single Schmitt buffer of the same kind as the quadrature encoders' buffers; their
    clock, chip selects and MOSI leave the MCU through a 3.3 V -> 5 V level shifter."""
    b = "aea"
    return [
        # The encoders run on 5 V and drive DO to 5 V. PB4 is 5 V-tolerant only while 3.3 V is up, and the
        # encoders have 5 V before 3.3 V rises and after it falls. The buffer runs on 3.3 V, its input
        # takes 5.5 V with or without supply (Ioff), and its output is off while it is unpowered. The
        # pull-down holds the input low when no encoder is plugged in or none is selected (DO tri-stated).
        Part("U11", "74xGxx:74LVC1G17", "74LVC1G17", "Package_TO_SOT_SMD:SOT-23-5", "SN74LVC1G17DBVR",
             "Texas Instruments", {"2": "AEA_ENC_DO", "4": "AEA_DO", "5": "+3V3", "3": "GND"}, b,
             "absolute-encoder data buffer (5 V in, 3.3 V out)"),
        _c("C17", "100n", "+3V3", "GND", b, "GCM188R71H104KA57D"),
        _r("R8", "10k", "AEA_ENC_DO", "GND", b, "RC0603FR-0710KL"),
        # 3.3 V -> 5 V for the encoders' inputs: a 74AHCT125 on 5 V has TTL input levels (VIH 2.0 V), so the
        # MCU's 3.3 V outputs drive it, and its outputs swing to 5 V (AS5048A VIH 3.5 V). Always enabled.
        Part("U12", "74xx:74AHCT125", "74AHCT125", "Package_SO:TSSOP-14_4.4x5mm_P0.65mm", "SN74AHCT125PWR",
             "Texas Instruments",
             {"1": "GND", "2": "AEA_CLK", "3": "AEA_CLK_5V", "4": "GND", "5": "M1_AEA_CS", "6": "M1_AEA_CS_5V",
              "10": "GND", "9": "M2_AEA_CS", "8": "M2_AEA_CS_5V", "13": "GND", "12": "AEA_MOSI", "11": "AEA_MOSI_5V",
              "14": "+5V", "7": "GND"}, b, "encoder level shifter (3.3 V in, 5 V out)"),
        _c("C18", "100n", "+5V", "GND", b, "GCM188R71H104KA57D"),
        # While the MCU pins are still inputs (reset, boot) the pull-ups keep both chip selects inactive; the
        # level shifter's CMOS inputs never float. MOSI has no MCU pin since rev D (PB5 switches brake 1): the
        # firmware only ever sent 0xFFFF (read angle), which R11 holding the input high sends on every frame.
        _r("R9", "10k", "+3V3", "M1_AEA_CS", b, "RC0603FR-0710KL"),
        _r("R10", "10k", "+3V3", "M2_AEA_CS", b, "RC0603FR-0710KL"),
        _r("R11", "10k", "+3V3", "AEA_MOSI", b, "RC0603FR-0710KL"),
    ]


def _shared_motor_parts():
    return [_r("R7", "10k", "+3V3", "MOT_FAULT", "mcu", "RC0603FR-0710KL")]


def _mounting_holes():
    return [Part(f"H{i}", "Mechanical:MountingHole", "M3", "MountingHole:MountingHole_3.2mm_M3", "", "", {},
                 "mech", in_bom=False) for i in range(1, 5)]


def parts():
    return (_power_parts() + _mcu_parts() + _shared_motor_parts() + _can_parts()
            + _axis_parts(1, 5) + _axis_parts(2, 7) + _brake_parts(1) + _brake_parts(2) + _aea_parts()
            + _mounting_holes())

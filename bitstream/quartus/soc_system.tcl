# soc_system: the Platform Designer system of the Skylux DE1-SoC bitstream.
#
#   qsys-script --script=soc_system.tcl      (writes soc_system.qsys)
#   qsys-generate soc_system.qsys --synthesis=VERILOG
#
# build.sh runs both. soc_system_blackbox.v lists the ports this system generates.
#
# Contents:
#   clk_0        clock source: CLOCK_50 (50 MHz), exported as clk / reset
#   pll_0        altera_pll from clk_0: outclk0 100 MHz (system clock), outclk1 25 MHz
#                (D5M XCLKIN, the Terasic value, hardware-facts.md sections 1.2 and 1.8)
#   sys_clk_src  clock source fed back from the top with the 100 MHz system clock; it clocks
#                every FPGA-side HPS interface so the core, the LW bridge host and the
#                f2sdram ports share one clock (ARCHITECTURE.md "Clock domains")
#   hps_0        altera_hps: DE1-SoC DDR3 and pin muxing (values below), LW H2F bridge,
#                f2sdram port 0 = 64-bit Avalon-MM write-only (frame DMA),
#                f2sdram port 1 = 64-bit Avalon-MM bidirectional (ray-box unit),
#                f2h_irq0 exported
#   lw_bridge    altera_avalon_mm_bridge (pipeline bridge) on the LW H2F master at 0x0,
#                21-bit byte address = the whole 2 MiB window (hardware-facts.md 3.1)
#
# HPS parameters: the DDR3 timing and board values and the pin muxing are those of the
# Terasic DE1-SoC reference system (as captured in the public DE1-SoC soc_system.tcl of
# VCTLabs/DE1_SOC_Linux_FB @046f8c28, derived from Terasic's DE1-SoC demos; the GPIO list
# 9/35/40/48/53/54/61 and the peripheral sets match Terasic's DE1-SoC GHRD top). Parameters
# not set here keep the altera_hps defaults of the Quartus version in use.

package require -exact qsys 16.1

create_system {soc_system}
set_project_property DEVICE_FAMILY {Cyclone V}
set_project_property DEVICE {5CSEMA5F31C6}

# ---------------------------------------------------------------------------- clocks
add_instance clk_0 clock_source
set_instance_parameter_value clk_0 {clockFrequency} {50000000.0}
set_instance_parameter_value clk_0 {clockFrequencyKnown} {1}
set_instance_parameter_value clk_0 {resetSynchronousEdges} {NONE}

add_instance pll_0 altera_pll
set_instance_parameter_value pll_0 {gui_reference_clock_frequency} {50.0}
set_instance_parameter_value pll_0 {gui_operation_mode} {normal}
set_instance_parameter_value pll_0 {gui_use_locked} {1}
set_instance_parameter_value pll_0 {gui_number_of_clocks} {2}
set_instance_parameter_value pll_0 {gui_output_clock_frequency0} {100.0}
set_instance_parameter_value pll_0 {gui_phase_shift0} {0}
set_instance_parameter_value pll_0 {gui_duty_cycle0} {50}
set_instance_parameter_value pll_0 {gui_output_clock_frequency1} {25.0}
set_instance_parameter_value pll_0 {gui_phase_shift1} {0}
set_instance_parameter_value pll_0 {gui_duty_cycle1} {50}

add_instance sys_clk_src clock_source
set_instance_parameter_value sys_clk_src {clockFrequency} {100000000.0}
set_instance_parameter_value sys_clk_src {clockFrequencyKnown} {1}
set_instance_parameter_value sys_clk_src {resetSynchronousEdges} {DEASSERT}

# ------------------------------------------------------------------------------- HPS
add_instance hps_0 altera_hps

# DDR3: 2 x 256M x 16 = 1 GB, 32-bit bus (hardware-facts.md section 2), 400 MHz.
set_instance_parameter_value hps_0 {HPS_PROTOCOL} {DDR3}
set_instance_parameter_value hps_0 {MEM_VENDOR} {JEDEC}
set_instance_parameter_value hps_0 {MEM_FORMAT} {DISCRETE}
set_instance_parameter_value hps_0 {DISCRETE_FLY_BY} {1}
set_instance_parameter_value hps_0 {DEVICE_DEPTH} {1}
set_instance_parameter_value hps_0 {MEM_CLK_FREQ_MAX} {800.0}
set_instance_parameter_value hps_0 {MEM_CLK_FREQ} {400.0}
set_instance_parameter_value hps_0 {REF_CLK_FREQ} {25.0}
set_instance_parameter_value hps_0 {RATE} {Full}
set_instance_parameter_value hps_0 {MEM_VOLTAGE} {1.5V DDR3}
set_instance_parameter_value hps_0 {MEM_ROW_ADDR_WIDTH} {15}
set_instance_parameter_value hps_0 {MEM_COL_ADDR_WIDTH} {10}
set_instance_parameter_value hps_0 {MEM_BANKADDR_WIDTH} {3}
set_instance_parameter_value hps_0 {MEM_DQ_WIDTH} {32}
set_instance_parameter_value hps_0 {MEM_DQ_PER_DQS} {8}
set_instance_parameter_value hps_0 {MEM_IF_DM_PINS_EN} {1}
set_instance_parameter_value hps_0 {MEM_IF_DQSN_EN} {1}
set_instance_parameter_value hps_0 {MEM_CK_WIDTH} {1}
set_instance_parameter_value hps_0 {MEM_CS_WIDTH} {1}
set_instance_parameter_value hps_0 {MEM_CLK_EN_WIDTH} {1}
set_instance_parameter_value hps_0 {MEM_NUMBER_OF_DIMMS} {1}
set_instance_parameter_value hps_0 {MEM_NUMBER_OF_RANKS_PER_DIMM} {1}
set_instance_parameter_value hps_0 {MEM_NUMBER_OF_RANKS_PER_DEVICE} {1}
set_instance_parameter_value hps_0 {MEM_BL} {OTF}
set_instance_parameter_value hps_0 {MEM_BT} {Sequential}
set_instance_parameter_value hps_0 {MEM_ASR} {Manual}
set_instance_parameter_value hps_0 {MEM_SRT} {Normal}
set_instance_parameter_value hps_0 {MEM_PD} {DLL off}
set_instance_parameter_value hps_0 {MEM_DRV_STR} {RZQ/7}
set_instance_parameter_value hps_0 {MEM_DLL_EN} {1}
set_instance_parameter_value hps_0 {MEM_RTT_NOM} {RZQ/4}
set_instance_parameter_value hps_0 {MEM_RTT_WR} {RZQ/4}
set_instance_parameter_value hps_0 {MEM_WTCL} {8}
set_instance_parameter_value hps_0 {MEM_ATCL} {Disabled}
set_instance_parameter_value hps_0 {MEM_TCL} {11}
set_instance_parameter_value hps_0 {MEM_AUTO_LEVELING_MODE} {1}
set_instance_parameter_value hps_0 {MEM_USER_LEVELING_MODE} {Leveling}
set_instance_parameter_value hps_0 {TIMING_TIS} {180}
set_instance_parameter_value hps_0 {TIMING_TIH} {140}
set_instance_parameter_value hps_0 {TIMING_TDS} {30}
set_instance_parameter_value hps_0 {TIMING_TDH} {65}
set_instance_parameter_value hps_0 {TIMING_TDQSQ} {125}
set_instance_parameter_value hps_0 {TIMING_TQHS} {300}
set_instance_parameter_value hps_0 {TIMING_TQH} {0.38}
set_instance_parameter_value hps_0 {TIMING_TDQSCK} {255}
set_instance_parameter_value hps_0 {TIMING_TDQSCKDS} {450}
set_instance_parameter_value hps_0 {TIMING_TDQSCKDM} {900}
set_instance_parameter_value hps_0 {TIMING_TDQSCKDL} {1200}
set_instance_parameter_value hps_0 {TIMING_TDQSS} {0.25}
set_instance_parameter_value hps_0 {TIMING_TDQSH} {0.35}
set_instance_parameter_value hps_0 {TIMING_TQSH} {0.4}
set_instance_parameter_value hps_0 {TIMING_TDSH} {0.2}
set_instance_parameter_value hps_0 {TIMING_TDSS} {0.2}
set_instance_parameter_value hps_0 {MEM_TINIT_US} {500}
set_instance_parameter_value hps_0 {MEM_TMRD_CK} {4}
set_instance_parameter_value hps_0 {MEM_TRAS_NS} {35.0}
set_instance_parameter_value hps_0 {MEM_TRCD_NS} {13.75}
set_instance_parameter_value hps_0 {MEM_TRP_NS} {13.75}
set_instance_parameter_value hps_0 {MEM_TREFI_US} {7.8}
set_instance_parameter_value hps_0 {MEM_TRFC_NS} {260.0}
set_instance_parameter_value hps_0 {CFG_TCCD_NS} {2.5}
set_instance_parameter_value hps_0 {MEM_TWR_NS} {15.0}
set_instance_parameter_value hps_0 {MEM_TWTR} {4}
set_instance_parameter_value hps_0 {MEM_TFAW_NS} {30.0}
set_instance_parameter_value hps_0 {MEM_TRRD_NS} {7.5}
set_instance_parameter_value hps_0 {MEM_TRTP_NS} {7.5}
set_instance_parameter_value hps_0 {TIMING_BOARD_MAX_CK_DELAY} {0.03}
set_instance_parameter_value hps_0 {TIMING_BOARD_MAX_DQS_DELAY} {0.02}
set_instance_parameter_value hps_0 {TIMING_BOARD_SKEW_CKDQS_DIMM_MIN} {0.09}
set_instance_parameter_value hps_0 {TIMING_BOARD_SKEW_CKDQS_DIMM_MAX} {0.16}
set_instance_parameter_value hps_0 {TIMING_BOARD_SKEW_BETWEEN_DIMMS} {0.05}
set_instance_parameter_value hps_0 {TIMING_BOARD_SKEW_WITHIN_DQS} {0.01}
set_instance_parameter_value hps_0 {TIMING_BOARD_SKEW_BETWEEN_DQS} {0.08}
set_instance_parameter_value hps_0 {TIMING_BOARD_DQ_TO_DQS_SKEW} {0.0}
set_instance_parameter_value hps_0 {TIMING_BOARD_AC_SKEW} {0.03}
set_instance_parameter_value hps_0 {TIMING_BOARD_AC_TO_CK_SKEW} {0.0}

# Bridges and FPGA interfaces.
set_instance_parameter_value hps_0 {LWH2F_Enable} {true}
set_instance_parameter_value hps_0 {S2F_Width} {0}
set_instance_parameter_value hps_0 {F2S_Width} {0}
set_instance_parameter_value hps_0 {F2SDRAM_Type} {Avalon-MM\ Write-Only Avalon-MM\ Bidirectional}
set_instance_parameter_value hps_0 {F2SDRAM_Width} {64 64}
set_instance_parameter_value hps_0 {F2SINTERRUPT_Enable} {1}
set_instance_parameter_value hps_0 {BOOTFROMFPGA_Enable} {0}

# Peripheral pin muxing (Terasic DE1-SoC GHRD).
set_instance_parameter_value hps_0 {EMAC1_PinMuxing} {HPS I/O Set 0}
set_instance_parameter_value hps_0 {EMAC1_Mode} {RGMII}
set_instance_parameter_value hps_0 {QSPI_PinMuxing} {HPS I/O Set 0}
set_instance_parameter_value hps_0 {QSPI_Mode} {1 SS}
set_instance_parameter_value hps_0 {SDIO_PinMuxing} {HPS I/O Set 0}
set_instance_parameter_value hps_0 {SDIO_Mode} {4-bit Data}
set_instance_parameter_value hps_0 {USB1_PinMuxing} {HPS I/O Set 0}
set_instance_parameter_value hps_0 {USB1_Mode} {SDR}
set_instance_parameter_value hps_0 {SPIM1_PinMuxing} {HPS I/O Set 0}
set_instance_parameter_value hps_0 {SPIM1_Mode} {Single Slave Select}
set_instance_parameter_value hps_0 {UART0_PinMuxing} {HPS I/O Set 0}
set_instance_parameter_value hps_0 {UART0_Mode} {No Flow Control}
set_instance_parameter_value hps_0 {I2C0_PinMuxing} {HPS I/O Set 0}
set_instance_parameter_value hps_0 {I2C0_Mode} {I2C}
set_instance_parameter_value hps_0 {I2C1_PinMuxing} {HPS I/O Set 0}
set_instance_parameter_value hps_0 {I2C1_Mode} {I2C}
# GPIO 9, 35, 40, 48, 53, 54, 61 (HPS_CONV_USB_N, HPS_ENET_INT_N, HPS_LTC_GPIO,
# HPS_I2C_CONTROL, HPS_LED, HPS_KEY, HPS_GSENSOR_INT).
set gpio {}
for {set i 0} {$i < 71} {incr i} {
    if {[lsearch -exact {9 35 40 48 53 54 61} $i] >= 0} { lappend gpio Yes } else { lappend gpio No }
}
set_instance_parameter_value hps_0 {GPIO_Enable} $gpio

# --------------------------------------------------------- LW H2F pipeline bridge
add_instance lw_bridge altera_avalon_mm_bridge
set_instance_parameter_value lw_bridge {DATA_WIDTH} {32}
set_instance_parameter_value lw_bridge {SYMBOL_WIDTH} {8}
set_instance_parameter_value lw_bridge {ADDRESS_WIDTH} {21}
set_instance_parameter_value lw_bridge {USE_AUTO_ADDRESS_WIDTH} {0}
set_instance_parameter_value lw_bridge {ADDRESS_UNITS} {SYMBOLS}
set_instance_parameter_value lw_bridge {MAX_BURST_SIZE} {1}
set_instance_parameter_value lw_bridge {MAX_PENDING_RESPONSES} {4}
set_instance_parameter_value lw_bridge {LINEWRAPBURSTS} {0}
set_instance_parameter_value lw_bridge {PIPELINE_COMMAND} {1}
set_instance_parameter_value lw_bridge {PIPELINE_RESPONSE} {1}
set_instance_parameter_value lw_bridge {USE_RESPONSE} {0}

# ------------------------------------------------------------------------ exports
add_interface clk clock sink
set_interface_property clk EXPORT_OF clk_0.clk_in
add_interface reset reset sink
set_interface_property reset EXPORT_OF clk_0.clk_in_reset
add_interface pll_0_outclk0 clock source
set_interface_property pll_0_outclk0 EXPORT_OF pll_0.outclk0
add_interface pll_0_outclk1 clock source
set_interface_property pll_0_outclk1 EXPORT_OF pll_0.outclk1
add_interface pll_0_locked conduit end
set_interface_property pll_0_locked EXPORT_OF pll_0.locked
add_interface sys_clk clock sink
set_interface_property sys_clk EXPORT_OF sys_clk_src.clk_in
add_interface sys_reset reset sink
set_interface_property sys_reset EXPORT_OF sys_clk_src.clk_in_reset
add_interface hps_0_h2f_reset reset source
set_interface_property hps_0_h2f_reset EXPORT_OF hps_0.h2f_reset
add_interface hps_0_f2h_irq0 interrupt receiver
set_interface_property hps_0_f2h_irq0 EXPORT_OF hps_0.f2h_irq0
add_interface lw_bridge_m0 avalon master
set_interface_property lw_bridge_m0 EXPORT_OF lw_bridge.m0
add_interface hps_0_f2h_sdram0_data avalon slave
set_interface_property hps_0_f2h_sdram0_data EXPORT_OF hps_0.f2h_sdram0_data
add_interface hps_0_f2h_sdram1_data avalon slave
set_interface_property hps_0_f2h_sdram1_data EXPORT_OF hps_0.f2h_sdram1_data
add_interface memory conduit end
set_interface_property memory EXPORT_OF hps_0.memory
add_interface hps_0_hps_io conduit end
set_interface_property hps_0_hps_io EXPORT_OF hps_0.hps_io

# -------------------------------------------------------------------- connections
add_connection clk_0.clk pll_0.refclk
add_connection clk_0.clk_reset pll_0.reset

add_connection sys_clk_src.clk hps_0.h2f_lw_axi_clock
add_connection sys_clk_src.clk hps_0.f2h_sdram0_clock
add_connection sys_clk_src.clk hps_0.f2h_sdram1_clock
add_connection sys_clk_src.clk lw_bridge.clk
add_connection sys_clk_src.clk_reset lw_bridge.reset

add_connection hps_0.h2f_lw_axi_master lw_bridge.s0
set_connection_parameter_value hps_0.h2f_lw_axi_master/lw_bridge.s0 baseAddress {0x00000000}

save_system {soc_system.qsys}

/* verilator lint_off DECLFILENAME */ // stub file name ends in _blackbox on purpose
// soc_system: black-box stub of the Platform Designer system that soc_system.tcl creates, with
// the port list Platform Designer generates for it (interface name + "_" + signal name).
// Used only to lint skylux_top.v with verilator; Quartus compiles the generated
// soc_system/synthesis/soc_system.v instead (this file is not in skylux.qsf).
//
// Exported interfaces (soc_system.tcl):
//   clk, reset              clk_0 clock source: CLOCK_50 (50 MHz) and its reset
//   pll_0_outclk0/1, _locked altera_pll: 100 MHz system clock, 25 MHz D5M XCLKIN
//   sys_clk, sys_reset      clock source for every FPGA-side HPS interface (100 MHz)
//   hps_0_h2f_reset         HPS-to-FPGA reset (high while the HPS runs)
//   hps_0_f2h_irq0          FPGA-to-HPS interrupts f2h_irq0[31:0] (GIC SPI 40..71)
//   lw_bridge_m0            altera_avalon_mm_bridge host behind the lightweight H2F bridge
//                           (byte address, 21 bits = 2 MiB; hardware-facts.md section 3.1)
//   hps_0_f2h_sdram0_data   f2sdram port 0: 64-bit Avalon-MM write-only (frame DMA)
//   hps_0_f2h_sdram1_data   f2sdram port 1: 64-bit Avalon-MM bidirectional (ray-box)
//                           word addresses, 29 bits (hardware-facts.md section 3.2)
//   memory                  HPS DDR3 pins
//   hps_0_hps_io            HPS peripheral pins (Terasic DE1-SoC GHRD pin muxing)

/* verilator lint_off UNUSED */
// Stub only: inputs are not read and outputs are tied off, by design.
module soc_system (
    input  wire         clk_clk,
    input  wire         reset_reset_n,
    output wire         pll_0_outclk0_clk,
    output wire         pll_0_outclk1_clk,
    output wire         pll_0_locked_export,
    input  wire         sys_clk_clk,
    input  wire         sys_reset_reset_n,
    output wire         hps_0_h2f_reset_reset_n,
    input  wire [31:0]  hps_0_f2h_irq0_irq,
    input  wire         lw_bridge_m0_waitrequest,
    input  wire [31:0]  lw_bridge_m0_readdata,
    input  wire         lw_bridge_m0_readdatavalid,
    output wire [0:0]   lw_bridge_m0_burstcount,
    output wire [31:0]  lw_bridge_m0_writedata,
    output wire [20:0]  lw_bridge_m0_address,
    output wire         lw_bridge_m0_write,
    output wire         lw_bridge_m0_read,
    output wire [3:0]   lw_bridge_m0_byteenable,
    output wire         lw_bridge_m0_debugaccess,
    input  wire [28:0]  hps_0_f2h_sdram0_data_address,
    input  wire [7:0]   hps_0_f2h_sdram0_data_burstcount,
    output wire         hps_0_f2h_sdram0_data_waitrequest,
    input  wire [63:0]  hps_0_f2h_sdram0_data_writedata,
    input  wire [7:0]   hps_0_f2h_sdram0_data_byteenable,
    input  wire         hps_0_f2h_sdram0_data_write,
    input  wire [28:0]  hps_0_f2h_sdram1_data_address,
    input  wire [7:0]   hps_0_f2h_sdram1_data_burstcount,
    output wire         hps_0_f2h_sdram1_data_waitrequest,
    output wire [63:0]  hps_0_f2h_sdram1_data_readdata,
    output wire         hps_0_f2h_sdram1_data_readdatavalid,
    input  wire         hps_0_f2h_sdram1_data_read,
    input  wire [63:0]  hps_0_f2h_sdram1_data_writedata,
    input  wire [7:0]   hps_0_f2h_sdram1_data_byteenable,
    input  wire         hps_0_f2h_sdram1_data_write,
    output wire [14:0]  memory_mem_a,
    output wire [2:0]   memory_mem_ba,
    output wire         memory_mem_ck,
    output wire         memory_mem_ck_n,
    output wire         memory_mem_cke,
    output wire         memory_mem_cs_n,
    output wire         memory_mem_ras_n,
    output wire         memory_mem_cas_n,
    output wire         memory_mem_we_n,
    output wire         memory_mem_reset_n,
    inout  wire [31:0]  memory_mem_dq,
    inout  wire [3:0]   memory_mem_dqs,
    inout  wire [3:0]   memory_mem_dqs_n,
    output wire         memory_mem_odt,
    output wire [3:0]   memory_mem_dm,
    input  wire         memory_oct_rzqin,
    output wire         hps_0_hps_io_hps_io_emac1_inst_TX_CLK,
    output wire         hps_0_hps_io_hps_io_emac1_inst_TXD0,
    output wire         hps_0_hps_io_hps_io_emac1_inst_TXD1,
    output wire         hps_0_hps_io_hps_io_emac1_inst_TXD2,
    output wire         hps_0_hps_io_hps_io_emac1_inst_TXD3,
    input  wire         hps_0_hps_io_hps_io_emac1_inst_RXD0,
    inout  wire         hps_0_hps_io_hps_io_emac1_inst_MDIO,
    output wire         hps_0_hps_io_hps_io_emac1_inst_MDC,
    input  wire         hps_0_hps_io_hps_io_emac1_inst_RX_CTL,
    output wire         hps_0_hps_io_hps_io_emac1_inst_TX_CTL,
    input  wire         hps_0_hps_io_hps_io_emac1_inst_RX_CLK,
    input  wire         hps_0_hps_io_hps_io_emac1_inst_RXD1,
    input  wire         hps_0_hps_io_hps_io_emac1_inst_RXD2,
    input  wire         hps_0_hps_io_hps_io_emac1_inst_RXD3,
    inout  wire         hps_0_hps_io_hps_io_qspi_inst_IO0,
    inout  wire         hps_0_hps_io_hps_io_qspi_inst_IO1,
    inout  wire         hps_0_hps_io_hps_io_qspi_inst_IO2,
    inout  wire         hps_0_hps_io_hps_io_qspi_inst_IO3,
    output wire         hps_0_hps_io_hps_io_qspi_inst_SS0,
    output wire         hps_0_hps_io_hps_io_qspi_inst_CLK,
    inout  wire         hps_0_hps_io_hps_io_sdio_inst_CMD,
    inout  wire         hps_0_hps_io_hps_io_sdio_inst_D0,
    inout  wire         hps_0_hps_io_hps_io_sdio_inst_D1,
    output wire         hps_0_hps_io_hps_io_sdio_inst_CLK,
    inout  wire         hps_0_hps_io_hps_io_sdio_inst_D2,
    inout  wire         hps_0_hps_io_hps_io_sdio_inst_D3,
    inout  wire         hps_0_hps_io_hps_io_usb1_inst_D0,
    inout  wire         hps_0_hps_io_hps_io_usb1_inst_D1,
    inout  wire         hps_0_hps_io_hps_io_usb1_inst_D2,
    inout  wire         hps_0_hps_io_hps_io_usb1_inst_D3,
    inout  wire         hps_0_hps_io_hps_io_usb1_inst_D4,
    inout  wire         hps_0_hps_io_hps_io_usb1_inst_D5,
    inout  wire         hps_0_hps_io_hps_io_usb1_inst_D6,
    inout  wire         hps_0_hps_io_hps_io_usb1_inst_D7,
    input  wire         hps_0_hps_io_hps_io_usb1_inst_CLK,
    output wire         hps_0_hps_io_hps_io_usb1_inst_STP,
    input  wire         hps_0_hps_io_hps_io_usb1_inst_DIR,
    input  wire         hps_0_hps_io_hps_io_usb1_inst_NXT,
    output wire         hps_0_hps_io_hps_io_spim1_inst_CLK,
    output wire         hps_0_hps_io_hps_io_spim1_inst_MOSI,
    input  wire         hps_0_hps_io_hps_io_spim1_inst_MISO,
    output wire         hps_0_hps_io_hps_io_spim1_inst_SS0,
    input  wire         hps_0_hps_io_hps_io_uart0_inst_RX,
    output wire         hps_0_hps_io_hps_io_uart0_inst_TX,
    inout  wire         hps_0_hps_io_hps_io_i2c0_inst_SDA,
    inout  wire         hps_0_hps_io_hps_io_i2c0_inst_SCL,
    inout  wire         hps_0_hps_io_hps_io_i2c1_inst_SDA,
    inout  wire         hps_0_hps_io_hps_io_i2c1_inst_SCL,
    inout  wire         hps_0_hps_io_hps_io_gpio_inst_GPIO09,
    inout  wire         hps_0_hps_io_hps_io_gpio_inst_GPIO35,
    inout  wire         hps_0_hps_io_hps_io_gpio_inst_GPIO40,
    inout  wire         hps_0_hps_io_hps_io_gpio_inst_GPIO48,
    inout  wire         hps_0_hps_io_hps_io_gpio_inst_GPIO53,
    inout  wire         hps_0_hps_io_hps_io_gpio_inst_GPIO54,
    inout  wire         hps_0_hps_io_hps_io_gpio_inst_GPIO61
);
    assign pll_0_outclk0_clk = 1'b0;
    assign pll_0_outclk1_clk = 1'b0;
    assign pll_0_locked_export = 1'b0;
    assign hps_0_h2f_reset_reset_n = 1'b0;
    assign lw_bridge_m0_burstcount = {1{1'b0}};
    assign lw_bridge_m0_writedata = {32{1'b0}};
    assign lw_bridge_m0_address = {21{1'b0}};
    assign lw_bridge_m0_write = 1'b0;
    assign lw_bridge_m0_read = 1'b0;
    assign lw_bridge_m0_byteenable = {4{1'b0}};
    assign lw_bridge_m0_debugaccess = 1'b0;
    assign hps_0_f2h_sdram0_data_waitrequest = 1'b0;
    assign hps_0_f2h_sdram1_data_waitrequest = 1'b0;
    assign hps_0_f2h_sdram1_data_readdata = {64{1'b0}};
    assign hps_0_f2h_sdram1_data_readdatavalid = 1'b0;
    assign memory_mem_a = {15{1'b0}};
    assign memory_mem_ba = {3{1'b0}};
    assign memory_mem_ck = 1'b0;
    assign memory_mem_ck_n = 1'b0;
    assign memory_mem_cke = 1'b0;
    assign memory_mem_cs_n = 1'b0;
    assign memory_mem_ras_n = 1'b0;
    assign memory_mem_cas_n = 1'b0;
    assign memory_mem_we_n = 1'b0;
    assign memory_mem_reset_n = 1'b0;
    assign memory_mem_odt = 1'b0;
    assign memory_mem_dm = {4{1'b0}};
    assign hps_0_hps_io_hps_io_emac1_inst_TX_CLK = 1'b0;
    assign hps_0_hps_io_hps_io_emac1_inst_TXD0 = 1'b0;
    assign hps_0_hps_io_hps_io_emac1_inst_TXD1 = 1'b0;
    assign hps_0_hps_io_hps_io_emac1_inst_TXD2 = 1'b0;
    assign hps_0_hps_io_hps_io_emac1_inst_TXD3 = 1'b0;
    assign hps_0_hps_io_hps_io_emac1_inst_MDC = 1'b0;
    assign hps_0_hps_io_hps_io_emac1_inst_TX_CTL = 1'b0;
    assign hps_0_hps_io_hps_io_qspi_inst_SS0 = 1'b0;
    assign hps_0_hps_io_hps_io_qspi_inst_CLK = 1'b0;
    assign hps_0_hps_io_hps_io_sdio_inst_CLK = 1'b0;
    assign hps_0_hps_io_hps_io_usb1_inst_STP = 1'b0;
    assign hps_0_hps_io_hps_io_spim1_inst_CLK = 1'b0;
    assign hps_0_hps_io_hps_io_spim1_inst_MOSI = 1'b0;
    assign hps_0_hps_io_hps_io_spim1_inst_SS0 = 1'b0;
    assign hps_0_hps_io_hps_io_uart0_inst_TX = 1'b0;
endmodule
/* verilator lint_on UNUSED */

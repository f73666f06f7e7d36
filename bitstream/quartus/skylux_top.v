// skylux_top: DE1-SoC board top for Skylux (hand-written Verilog-2001).
//
// It instantiates the Platform Designer system `soc_system` (HPS with DDR3, lightweight
// HPS-to-FPGA bridge exported through an Avalon-MM pipeline bridge, two 64-bit f2sdram
// Avalon-MM ports, f2h_irq0, and the PLL) next to the rust-hdl core `skylux_core`, and wires
// both to the board pins. Nothing here holds product logic: only pins, clocks, the Avalon
// read-latency glue, the open-drain SDATA buffer, a key synchroniser and status LEDs.
//
// Sources for every pin: skylux.qsf (D5M: hardware-facts.md section 1.8 / Terasic
// DE1_SoC_CAMERA S12; CLOCK_50, KEY, LEDR, GPIO_0: the same Terasic S12 qsf; HPS pins: the
// names of Terasic's DE1-SoC golden top). The core's interface is core_ports.md.
//
// Clocks (see skylux.sdc):
//   CLOCK_50    50 MHz board oscillator, reference of the PLL inside soc_system.
//   sys_clk     100 MHz PLL output: the core's system clock and every FPGA-side HPS
//               interface (LW bridge, f2sdram ports), so no clock crossing between them.
//   xclk        25 MHz PLL output to D5M_XCLKIN (Terasic uses 25 MHz; the sensor accepts
//               6-27 MHz, hardware-facts.md section 1.2).
//   D5M_PIXLCLK up to 96 MHz from the sensor; the core's capture FIFO crosses it to sys_clk.
//
// Reset: rust-hdl has no reset nets; the core's registers start from power-up values. The
// Platform Designer interconnect is held in reset until the PLL locks.

module skylux_top (
    // Board clock and user I/O (Terasic DE1-SoC, S12 qsf)
    input  wire        CLOCK_50,
    input  wire [0:0]  KEY,           // KEY[0]: external sequence trigger (active low)
    output wire [9:0]  LEDR,          // status, see the LED map below

    // TRDB-D5M on GPIO_1 (hardware-facts.md section 1.8)
    input  wire        D5M_PIXLCLK,
    input  wire [11:0] D5M_D,
    input  wire        D5M_FVAL,
    input  wire        D5M_LVAL,
    input  wire        D5M_STROBE,
    output wire        D5M_XCLKIN,
    output wire        D5M_RESET_N,
    output wire        D5M_TRIGGER,
    output wire        D5M_SCLK,
    inout  wire        D5M_SDATA,

    // Lens-shield stepper driver on GPIO_0 (pins are a project choice, see skylux.qsf)
    output wire        SHIELD_STEP,
    output wire        SHIELD_DIR,
    output wire        SHIELD_ENABLE_N,

    // HPS DDR3 (names of Terasic's DE1-SoC golden top; pins come from Platform Designer)
    output wire [14:0] HPS_DDR3_ADDR,
    output wire [2:0]  HPS_DDR3_BA,
    output wire        HPS_DDR3_CAS_N,
    output wire        HPS_DDR3_CKE,
    output wire        HPS_DDR3_CK_N,
    output wire        HPS_DDR3_CK_P,
    output wire        HPS_DDR3_CS_N,
    output wire [3:0]  HPS_DDR3_DM,
    inout  wire [31:0] HPS_DDR3_DQ,
    inout  wire [3:0]  HPS_DDR3_DQS_N,
    inout  wire [3:0]  HPS_DDR3_DQS_P,
    output wire        HPS_DDR3_ODT,
    output wire        HPS_DDR3_RAS_N,
    output wire        HPS_DDR3_RESET_N,
    input  wire        HPS_DDR3_RZQ,
    output wire        HPS_DDR3_WE_N,

    // HPS peripherals (DE1-SoC GHRD pin muxing)
    inout  wire        HPS_CONV_USB_N,
    output wire        HPS_ENET_GTX_CLK,
    inout  wire        HPS_ENET_INT_N,
    output wire        HPS_ENET_MDC,
    inout  wire        HPS_ENET_MDIO,
    input  wire        HPS_ENET_RX_CLK,
    input  wire [3:0]  HPS_ENET_RX_DATA,
    input  wire        HPS_ENET_RX_DV,
    output wire [3:0]  HPS_ENET_TX_DATA,
    output wire        HPS_ENET_TX_EN,
    inout  wire [3:0]  HPS_FLASH_DATA,
    output wire        HPS_FLASH_DCLK,
    output wire        HPS_FLASH_NCSO,
    inout  wire        HPS_GSENSOR_INT,
    inout  wire        HPS_I2C1_SCLK,
    inout  wire        HPS_I2C1_SDAT,
    inout  wire        HPS_I2C2_SCLK,
    inout  wire        HPS_I2C2_SDAT,
    inout  wire        HPS_I2C_CONTROL,
    inout  wire        HPS_KEY,
    inout  wire        HPS_LED,
    inout  wire        HPS_LTC_GPIO,
    output wire        HPS_SD_CLK,
    inout  wire        HPS_SD_CMD,
    inout  wire [3:0]  HPS_SD_DATA,
    output wire        HPS_SPIM_CLK,
    input  wire        HPS_SPIM_MISO,
    output wire        HPS_SPIM_MOSI,
    inout  wire        HPS_SPIM_SS,
    input  wire        HPS_UART_RX,
    output wire        HPS_UART_TX,
    input  wire        HPS_USB_CLKOUT,
    inout  wire [7:0]  HPS_USB_DATA,
    input  wire        HPS_USB_DIR,
    input  wire        HPS_USB_NXT,
    output wire        HPS_USB_STP
);

    // ------------------------------------------------------------------ clocks
    wire sys_clk;      // 100 MHz, pll_0 outclk0
    wire xclk;         // 25 MHz, pll_0 outclk1
    wire pll_locked;
    wire hps_running;  // h2f_reset_n: high while the HPS is out of reset

    assign D5M_XCLKIN = xclk;

    // ------------------------------------------------ lightweight bridge host (LW H2F)
    wire [20:0] lw_address;     // byte address in the 2 MiB window
    wire        lw_read;
    wire        lw_write;
    wire [31:0] lw_writedata;
    wire [3:0]  lw_byteenable;
    wire [31:0] lw_readdata;
    wire [0:0]  lw_burstcount;  // always 1 (MAX_BURST_SIZE 1)
    wire        lw_debugaccess;
    // The core's agent has a fixed read latency of 1 and never stalls (docs/registers.md):
    // waitrequest is 0 and readdatavalid is the read strobe delayed by one cycle.
    reg         lw_readdatavalid = 1'b0;
    always @(posedge sys_clk) lw_readdatavalid <= lw_read;

    // ---------------------------------------------------------- f2sdram hosts
    wire [28:0] dma_address;
    wire [7:0]  dma_burstcount;
    wire        dma_write;
    wire [63:0] dma_writedata;
    wire [7:0]  dma_byteenable;
    wire        dma_waitrequest;

    wire [28:0] rbx_address;
    wire [7:0]  rbx_burstcount;
    wire        rbx_read;
    wire        rbx_write;
    wire [63:0] rbx_writedata;
    wire [7:0]  rbx_byteenable;
    wire        rbx_waitrequest;
    wire [63:0] rbx_readdata;
    wire        rbx_readdatavalid;

    wire        core_irq;

    // ---------------------------------------------------------------- camera
    wire sdata_oe;  // 1: pull SDATA low; 0: release (the pull-up makes it high)
    assign D5M_SDATA = sdata_oe ? 1'b0 : 1'bz;

    // KEY[0] is active low and asynchronous: two flip-flops into sys_clk.
    reg [1:0] key_sync = 2'b11;
    always @(posedge sys_clk) key_sync <= {key_sync[0], KEY[0]};
    wire ext_trigger = ~key_sync[1];

    // ------------------------------------------------------------ status LEDs
    // LEDR[0] system-clock heartbeat (bit 26 of a 100 MHz counter: 0.67 s per half period)
    // LEDR[1] interrupt line to the HPS
    // LEDR[2] PLL locked
    // LEDR[3] PIXCLK heartbeat (bit 24 of a PIXCLK counter): the sensor clock is running
    // LEDR[4] FRAME_VALID from the sensor
    // LEDR[5] shield stepper driver enabled
    // LEDR[6] HPS out of reset (h2f_reset_n)
    // LEDR[7] external trigger key pressed
    // LEDR[9:8] off
    reg [26:0] sys_heartbeat = 27'd0;
    always @(posedge sys_clk) sys_heartbeat <= sys_heartbeat + 27'd1;
    reg [24:0] pix_heartbeat = 25'd0;
    reg        fval_led = 1'b0;
    always @(posedge D5M_PIXLCLK) begin
        pix_heartbeat <= pix_heartbeat + 25'd1;
        fval_led      <= D5M_FVAL;
    end

    assign LEDR = {2'b00, ext_trigger, hps_running, ~SHIELD_ENABLE_N, fval_led,
                   pix_heartbeat[24], pll_locked, core_irq, sys_heartbeat[26]};

    // Signals the top receives but has no use for (verilator's default unused pattern).
    wire unused_lw = &{1'b0, lw_address[1:0], lw_burstcount, lw_debugaccess};

    // ------------------------------------------------------------------- core
    skylux_core core (
        .clk              (sys_clk),
        .avs_address      (lw_address[20:2]),
        .avs_read         (lw_read),
        .avs_write        (lw_write),
        .avs_writedata    (lw_writedata),
        .avs_byteenable   (lw_byteenable),
        .avs_readdata     (lw_readdata),
        .irq              (core_irq),
        .dma_address      (dma_address),
        .dma_burstcount   (dma_burstcount),
        .dma_write        (dma_write),
        .dma_writedata    (dma_writedata),
        .dma_byteenable   (dma_byteenable),
        .dma_waitrequest  (dma_waitrequest),
        .rbx_address      (rbx_address),
        .rbx_burstcount   (rbx_burstcount),
        .rbx_read         (rbx_read),
        .rbx_write        (rbx_write),
        .rbx_writedata    (rbx_writedata),
        .rbx_byteenable   (rbx_byteenable),
        .rbx_waitrequest  (rbx_waitrequest),
        .rbx_readdata     (rbx_readdata),
        .rbx_readdatavalid(rbx_readdatavalid),
        .pixclk           (D5M_PIXLCLK),
        .d                (D5M_D),
        .fval             (D5M_FVAL),
        .lval             (D5M_LVAL),
        .strobe           (D5M_STROBE),
        .reset_n          (D5M_RESET_N),
        .trigger          (D5M_TRIGGER),
        .sclk             (D5M_SCLK),
        .sdata_oe         (sdata_oe),
        .sdata_in         (D5M_SDATA),
        .ext_trigger      (ext_trigger),
        .shield_step      (SHIELD_STEP),
        .shield_dir       (SHIELD_DIR),
        .shield_enable_n  (SHIELD_ENABLE_N)
    );

    // ------------------------------------------------------------- soc_system
    soc_system u0 (
        // clocks and resets
        .clk_clk                               (CLOCK_50),
        .reset_reset_n                         (1'b1),
        .pll_0_outclk0_clk                     (sys_clk),
        .pll_0_outclk1_clk                     (xclk),
        .pll_0_locked_export                   (pll_locked),
        .sys_clk_clk                           (sys_clk),
        .sys_reset_reset_n                     (pll_locked),
        .hps_0_h2f_reset_reset_n               (hps_running),
        // interrupts: f2h_irq0[0] = the core's line (GIC SPI 40, hardware-facts.md 3.5)
        .hps_0_f2h_irq0_irq                    ({31'd0, core_irq}),
        // lightweight HPS-to-FPGA bridge, through the pipeline bridge
        .lw_bridge_m0_waitrequest              (1'b0),
        .lw_bridge_m0_readdata                 (lw_readdata),
        .lw_bridge_m0_readdatavalid            (lw_readdatavalid),
        .lw_bridge_m0_burstcount               (lw_burstcount),
        .lw_bridge_m0_writedata                (lw_writedata),
        .lw_bridge_m0_address                  (lw_address),
        .lw_bridge_m0_write                    (lw_write),
        .lw_bridge_m0_read                     (lw_read),
        .lw_bridge_m0_byteenable               (lw_byteenable),
        .lw_bridge_m0_debugaccess              (lw_debugaccess),
        // f2sdram port 0: frame DMA (write-only)
        .hps_0_f2h_sdram0_data_address         (dma_address),
        .hps_0_f2h_sdram0_data_burstcount      (dma_burstcount),
        .hps_0_f2h_sdram0_data_waitrequest     (dma_waitrequest),
        .hps_0_f2h_sdram0_data_writedata       (dma_writedata),
        .hps_0_f2h_sdram0_data_byteenable      (dma_byteenable),
        .hps_0_f2h_sdram0_data_write           (dma_write),
        // f2sdram port 1: ray-box unit (read/write)
        .hps_0_f2h_sdram1_data_address         (rbx_address),
        .hps_0_f2h_sdram1_data_burstcount      (rbx_burstcount),
        .hps_0_f2h_sdram1_data_waitrequest     (rbx_waitrequest),
        .hps_0_f2h_sdram1_data_readdata        (rbx_readdata),
        .hps_0_f2h_sdram1_data_readdatavalid   (rbx_readdatavalid),
        .hps_0_f2h_sdram1_data_read            (rbx_read),
        .hps_0_f2h_sdram1_data_writedata       (rbx_writedata),
        .hps_0_f2h_sdram1_data_byteenable      (rbx_byteenable),
        .hps_0_f2h_sdram1_data_write           (rbx_write),
        // HPS DDR3
        .memory_mem_a                          (HPS_DDR3_ADDR),
        .memory_mem_ba                         (HPS_DDR3_BA),
        .memory_mem_ck                         (HPS_DDR3_CK_P),
        .memory_mem_ck_n                       (HPS_DDR3_CK_N),
        .memory_mem_cke                        (HPS_DDR3_CKE),
        .memory_mem_cs_n                       (HPS_DDR3_CS_N),
        .memory_mem_ras_n                      (HPS_DDR3_RAS_N),
        .memory_mem_cas_n                      (HPS_DDR3_CAS_N),
        .memory_mem_we_n                       (HPS_DDR3_WE_N),
        .memory_mem_reset_n                    (HPS_DDR3_RESET_N),
        .memory_mem_dq                         (HPS_DDR3_DQ),
        .memory_mem_dqs                        (HPS_DDR3_DQS_P),
        .memory_mem_dqs_n                      (HPS_DDR3_DQS_N),
        .memory_mem_odt                        (HPS_DDR3_ODT),
        .memory_mem_dm                         (HPS_DDR3_DM),
        .memory_oct_rzqin                      (HPS_DDR3_RZQ),
        // HPS Ethernet (EMAC1, RGMII)
        .hps_0_hps_io_hps_io_emac1_inst_TX_CLK (HPS_ENET_GTX_CLK),
        .hps_0_hps_io_hps_io_emac1_inst_TXD0   (HPS_ENET_TX_DATA[0]),
        .hps_0_hps_io_hps_io_emac1_inst_TXD1   (HPS_ENET_TX_DATA[1]),
        .hps_0_hps_io_hps_io_emac1_inst_TXD2   (HPS_ENET_TX_DATA[2]),
        .hps_0_hps_io_hps_io_emac1_inst_TXD3   (HPS_ENET_TX_DATA[3]),
        .hps_0_hps_io_hps_io_emac1_inst_RXD0   (HPS_ENET_RX_DATA[0]),
        .hps_0_hps_io_hps_io_emac1_inst_MDIO   (HPS_ENET_MDIO),
        .hps_0_hps_io_hps_io_emac1_inst_MDC    (HPS_ENET_MDC),
        .hps_0_hps_io_hps_io_emac1_inst_RX_CTL (HPS_ENET_RX_DV),
        .hps_0_hps_io_hps_io_emac1_inst_TX_CTL (HPS_ENET_TX_EN),
        .hps_0_hps_io_hps_io_emac1_inst_RX_CLK (HPS_ENET_RX_CLK),
        .hps_0_hps_io_hps_io_emac1_inst_RXD1   (HPS_ENET_RX_DATA[1]),
        .hps_0_hps_io_hps_io_emac1_inst_RXD2   (HPS_ENET_RX_DATA[2]),
        .hps_0_hps_io_hps_io_emac1_inst_RXD3   (HPS_ENET_RX_DATA[3]),
        // HPS QSPI flash
        .hps_0_hps_io_hps_io_qspi_inst_IO0     (HPS_FLASH_DATA[0]),
        .hps_0_hps_io_hps_io_qspi_inst_IO1     (HPS_FLASH_DATA[1]),
        .hps_0_hps_io_hps_io_qspi_inst_IO2     (HPS_FLASH_DATA[2]),
        .hps_0_hps_io_hps_io_qspi_inst_IO3     (HPS_FLASH_DATA[3]),
        .hps_0_hps_io_hps_io_qspi_inst_SS0     (HPS_FLASH_NCSO),
        .hps_0_hps_io_hps_io_qspi_inst_CLK     (HPS_FLASH_DCLK),
        // HPS SD card
        .hps_0_hps_io_hps_io_sdio_inst_CMD     (HPS_SD_CMD),
        .hps_0_hps_io_hps_io_sdio_inst_D0      (HPS_SD_DATA[0]),
        .hps_0_hps_io_hps_io_sdio_inst_D1      (HPS_SD_DATA[1]),
        .hps_0_hps_io_hps_io_sdio_inst_CLK     (HPS_SD_CLK),
        .hps_0_hps_io_hps_io_sdio_inst_D2      (HPS_SD_DATA[2]),
        .hps_0_hps_io_hps_io_sdio_inst_D3      (HPS_SD_DATA[3]),
        // HPS USB (USB1, ULPI)
        .hps_0_hps_io_hps_io_usb1_inst_D0      (HPS_USB_DATA[0]),
        .hps_0_hps_io_hps_io_usb1_inst_D1      (HPS_USB_DATA[1]),
        .hps_0_hps_io_hps_io_usb1_inst_D2      (HPS_USB_DATA[2]),
        .hps_0_hps_io_hps_io_usb1_inst_D3      (HPS_USB_DATA[3]),
        .hps_0_hps_io_hps_io_usb1_inst_D4      (HPS_USB_DATA[4]),
        .hps_0_hps_io_hps_io_usb1_inst_D5      (HPS_USB_DATA[5]),
        .hps_0_hps_io_hps_io_usb1_inst_D6      (HPS_USB_DATA[6]),
        .hps_0_hps_io_hps_io_usb1_inst_D7      (HPS_USB_DATA[7]),
        .hps_0_hps_io_hps_io_usb1_inst_CLK     (HPS_USB_CLKOUT),
        .hps_0_hps_io_hps_io_usb1_inst_STP     (HPS_USB_STP),
        .hps_0_hps_io_hps_io_usb1_inst_DIR     (HPS_USB_DIR),
        .hps_0_hps_io_hps_io_usb1_inst_NXT     (HPS_USB_NXT),
        // HPS SPI master 1 (LTC header)
        .hps_0_hps_io_hps_io_spim1_inst_CLK    (HPS_SPIM_CLK),
        .hps_0_hps_io_hps_io_spim1_inst_MOSI   (HPS_SPIM_MOSI),
        .hps_0_hps_io_hps_io_spim1_inst_MISO   (HPS_SPIM_MISO),
        .hps_0_hps_io_hps_io_spim1_inst_SS0    (HPS_SPIM_SS),
        // HPS UART0 (console)
        .hps_0_hps_io_hps_io_uart0_inst_RX     (HPS_UART_RX),
        .hps_0_hps_io_hps_io_uart0_inst_TX     (HPS_UART_TX),
        // HPS I2C0 -> board HPS_I2C1 (G-sensor), HPS I2C1 -> board HPS_I2C2 (LTC header)
        .hps_0_hps_io_hps_io_i2c0_inst_SDA     (HPS_I2C1_SDAT),
        .hps_0_hps_io_hps_io_i2c0_inst_SCL     (HPS_I2C1_SCLK),
        .hps_0_hps_io_hps_io_i2c1_inst_SDA     (HPS_I2C2_SDAT),
        .hps_0_hps_io_hps_io_i2c1_inst_SCL     (HPS_I2C2_SCLK),
        // HPS GPIO
        .hps_0_hps_io_hps_io_gpio_inst_GPIO09  (HPS_CONV_USB_N),
        .hps_0_hps_io_hps_io_gpio_inst_GPIO35  (HPS_ENET_INT_N),
        .hps_0_hps_io_hps_io_gpio_inst_GPIO40  (HPS_LTC_GPIO),
        .hps_0_hps_io_hps_io_gpio_inst_GPIO48  (HPS_I2C_CONTROL),
        .hps_0_hps_io_hps_io_gpio_inst_GPIO53  (HPS_LED),
        .hps_0_hps_io_hps_io_gpio_inst_GPIO54  (HPS_KEY),
        .hps_0_hps_io_hps_io_gpio_inst_GPIO61  (HPS_GSENSOR_INT)
    );

endmodule

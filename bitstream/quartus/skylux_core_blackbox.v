/* verilator lint_off DECLFILENAME */ // stub file name ends in _blackbox on purpose
// skylux_core: black-box stub of the whole-core module (capture path + ray-box unit +
// register file as ONE module with flat port names). It exists only so that verilator can
// lint skylux_top.v before the core is written; the real module will be exported from
// rust-hdl (bitstream/src/blocks.rs) under the name `skylux_core` with exactly these ports.
// The interface contract, with the reasons for every port, is core_ports.md in this folder.
//
// rust-hdl has no reset nets (rust-hdl-notes.md section 3): every register has a power-up
// value, so there is no reset port. Two clocks: `clk` (system clock, 100 MHz) and `pixclk`
// (from the sensor, up to 96 MHz, hardware-facts.md section 1.2).

/* verilator lint_off UNUSED */
// Stub only: inputs are not read and outputs are tied off, by design.
module skylux_core (
    input  wire        clk,
    // Avalon-MM agent: the register window behind the lightweight HPS-to-FPGA bridge.
    // Word address (19 bits = 2 MiB / 4), fixed read latency 1, no waitrequest.
    input  wire [18:0] avs_address,
    input  wire        avs_read,
    input  wire        avs_write,
    input  wire [31:0] avs_writedata,
    input  wire [3:0]  avs_byteenable,
    output wire [31:0] avs_readdata,
    output wire        irq,
    // Frame DMA: Avalon-MM burst write host on f2sdram port 0 (64-bit, write-only).
    // Word address: byte address / 8, 29 bits (hardware-facts.md section 3.2).
    output wire [28:0] dma_address,
    output wire [7:0]  dma_burstcount,
    output wire        dma_write,
    output wire [63:0] dma_writedata,
    output wire [7:0]  dma_byteenable,
    input  wire        dma_waitrequest,
    // Ray-box unit: Avalon-MM read/write host on f2sdram port 1 (64-bit, bidirectional).
    output wire [28:0] rbx_address,
    output wire [7:0]  rbx_burstcount,
    output wire        rbx_read,
    output wire        rbx_write,
    output wire [63:0] rbx_writedata,
    output wire [7:0]  rbx_byteenable,
    input  wire        rbx_waitrequest,
    input  wire [63:0] rbx_readdata,
    input  wire        rbx_readdatavalid,
    // TRDB-D5M camera (hardware-facts.md sections 1.2 and 1.8).
    input  wire        pixclk,
    input  wire [11:0] d,
    input  wire        fval,
    input  wire        lval,
    input  wire        strobe,
    output wire        reset_n,
    output wire        trigger,
    output wire        sclk,
    output wire        sdata_oe,
    input  wire        sdata_in,
    // External sequence trigger (seq.ctrl.EXT_TRIGGER), already synchronised to clk.
    input  wire        ext_trigger,
    // Lens-shield stepper driver.
    output wire        shield_step,
    output wire        shield_dir,
    output wire        shield_enable_n
);
    assign avs_readdata    = 32'd0;
    assign irq             = 1'b0;
    assign dma_address     = 29'd0;
    assign dma_burstcount  = 8'd0;
    assign dma_write       = 1'b0;
    assign dma_writedata   = 64'd0;
    assign dma_byteenable  = 8'd0;
    assign rbx_address     = 29'd0;
    assign rbx_burstcount  = 8'd0;
    assign rbx_read        = 1'b0;
    assign rbx_write       = 1'b0;
    assign rbx_writedata   = 64'd0;
    assign rbx_byteenable  = 8'd0;
    assign reset_n         = 1'b0;
    assign trigger         = 1'b0;
    assign sclk            = 1'b1;
    assign sdata_oe        = 1'b0;
    assign shield_step     = 1'b0;
    assign shield_dir      = 1'b0;
    assign shield_enable_n = 1'b1;
endmodule
/* verilator lint_on UNUSED */

# Skylux timing constraints (DE1-SoC, Cyclone V).

# Board oscillator: 50 MHz (hardware-facts.md section 2).
create_clock -name CLOCK_50 -period 20.000 [get_ports {CLOCK_50}]

# Sensor pixel clock: up to 96 MHz (hardware-facts.md section 1.2), so 10.417 ns.
create_clock -name PIXCLK -period 10.417 [get_ports {D5M_PIXLCLK}]

# PLL outputs (100 MHz system clock, 25 MHz XCLKIN) and the HPS-internal clocks.
derive_pll_clocks
derive_clock_uncertainty

# D[11:0], FVAL, LVAL are launched by the sensor on PIXCLK. With R0x0A[15] = 1
# (Invert_Pixel_Clock) the data is captured on the PIXCLK rising edge (hardware-facts.md
# section 1.2: Terasic, Linux and the EPFL code all do this). The MT9P031 output setup/hold
# times are NOT in hardware-facts.md, so these numbers are an ASSUMPTION: data valid from
# 2.0 ns after the edge that launches it until 8.0 ns after it, i.e. a window centred in a
# 96 MHz period with ~2 ns of board skew on each side. Replace them with the datasheet's
# t_PD (max, min) once retrieved, and check the capture timing report.
set_input_delay -clock PIXCLK -max 8.0 [get_ports {D5M_D[*] D5M_FVAL D5M_LVAL}]
set_input_delay -clock PIXCLK -min 2.0 [get_ports {D5M_D[*] D5M_FVAL D5M_LVAL}]

# PIXCLK and the system clock are unrelated: the capture FIFO (gray-coded pointers with
# synchronisers) and the status synchronisers are the only crossings (ARCHITECTURE.md,
# "Clock domains"). CLOCK_50 is the PLL reference; its derived clocks belong to its group.
set_clock_groups -asynchronous \
    -group [get_clocks {PIXCLK}] \
    -group [get_clocks {CLOCK_50 u0|pll_0|*}]

# Slow or asynchronous pins: stepper driver (kHz step rates), sensor I2C (100 kHz, timed by
# the core's own counters), sensor control, key and LEDs.
set_false_path -to   [get_ports {SHIELD_STEP SHIELD_DIR SHIELD_ENABLE_N}]
set_false_path -to   [get_ports {D5M_SCLK D5M_SDATA D5M_RESET_N D5M_TRIGGER}]
set_false_path -from [get_ports {D5M_SDATA D5M_STROBE KEY[*]}]
set_false_path -to   [get_ports {LEDR[*]}]
# The XCLKIN pin carries a clock; the sensor's PLL does not need a phase relation to it.
set_false_path -to   [get_ports {D5M_XCLKIN}]

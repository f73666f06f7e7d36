#!/usr/bin/env bash
# Builds the Skylux DE1-SoC bitstream: output_files/skylux.sof (JTAG) and
# output_files/skylux.rbf (compressed, for U-Boot `fpga load`, see ../linux/uboot.txt).
#
# Needs Intel Quartus Prime (Lite is enough) WITH Cyclone V device support, and its
# Platform Designer tools (qsys-script, qsys-generate) on PATH. Nothing here is simulated:
# without Quartus this script says so and fails.
set -euo pipefail
cd "$(dirname "$0")"

missing=()
for t in quartus_sh quartus_map quartus_sta quartus_cpf qsys-script qsys-generate; do
  command -v "$t" >/dev/null 2>&1 || missing+=("$t")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "build.sh: cannot build the bitstream here: ${missing[*]} not found." >&2
  echo "Install Intel Quartus Prime Lite with Cyclone V device support and put its" >&2
  echo "quartus/bin and qsys/bin (Platform Designer) folders on PATH." >&2
  exit 1
fi

# 1. The rust-hdl core, exported as core/skylux_core.v (module skylux_core, ports as in
#    core_ports.md).
if [ ! -f core/skylux_core.v ]; then
  echo "build.sh: core/skylux_core.v is missing. Export the core first:" >&2
  echo "  cargo run -p skylux-bitstream -- verilog" >&2
  echo "(it is checked in; cargo test fails when the copy is stale)." >&2
  exit 1
fi

# 2. The Platform Designer system.
qsys-script --script=soc_system.tcl
qsys-generate soc_system.qsys --synthesis=VERILOG --output-directory=soc_system

# 3. Analysis and synthesis, then the HPS DDR3 pin assignments Platform Designer generated
#    (the Terasic/Intel GHRD flow), then the full compile.
quartus_map skylux
quartus_sta -t soc_system/synthesis/submodules/hps_sdram_p0_pin_assignments.tcl skylux
quartus_sh --flow compile skylux

# 4. The compressed raw binary for U-Boot.
quartus_cpf -c -o bitstream_compression=on output_files/skylux.sof output_files/skylux.rbf
echo "built output_files/skylux.sof and output_files/skylux.rbf"

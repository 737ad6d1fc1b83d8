// soc_pkg: the SoC memory map's constants for soc_rtl/, and nothing else.
//
// contract/soc_map.vh, generated from contract/soc_map.toml (`make contract`), is included here and
// nowhere else; modules name its constants soc_pkg::SOC_* (region bases and windows, register
// offsets, field positions, the default clock and baud rate; the SDRAM's native width below).
// Qualified names everywhere: yosys 0.23 accepts no `import` (gpu_rtl/README.md, "Shared types").
// No logic here.
`default_nettype none

package soc_pkg;
`include "contract/soc_map.vh"  // relative to the repository root, where every tool runs
// LiteDRAM's native user ports (the CPU's and the GPU's frame memory port, soc_top gpu_mem_*,
// soc_rtl/soc_gpu_mem.vh): the half-rate PHY's two 16-bit beats a system clock
// (soc_rtl/litedram/ulx3s_sdram.yml, whose user ports must say the same), and the SDRAM window
// in those words.
localparam integer SOC_SDRAM_NATIVE_DW = 32;
localparam integer SOC_SDRAM_NATIVE_AW = $clog2(SOC_SDRAM_WINDOW_BYTES / (SOC_SDRAM_NATIVE_DW / 8));
endpackage

`default_nettype wire

// soc_pkg: the SoC memory map's constants for soc_rtl/, and nothing else.
//
// contract/soc_map.vh, generated from contract/soc_map.toml (`make contract`), is included here and
// nowhere else; modules name its constants soc_pkg::SOC_* (region bases and windows, register
// offsets, field positions, the default clock and baud rate). Qualified names everywhere: yosys 0.23
// accepts no `import` (gpu_rtl/README.md, "Shared types"). No logic here.
`default_nettype none

package soc_pkg;
`include "contract/soc_map.vh"  // relative to the repository root, where every tool runs
endpackage

`default_nettype wire

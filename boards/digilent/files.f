// The Digilent Artix-7 builds' own sources after gpu_rtl/files.f, the core and soc_rtl/files.f, in
// compilation order: the clocks (MMCME2_BASE, BUFG), then the common top around them and the SoC;
// each board adds its own top (boards/basys3/basys3_top.v, boards/nexys_a7/nexys_a7_top.v), which
// names the pins.
boards/common/board_status.v
boards/digilent/digilent_clocks.v
boards/digilent/digilent_top.v

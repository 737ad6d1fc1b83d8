// After boards/ulx3s/files.f, in place of files_top.f: the FPGA build with SDRAM (SOC_MEM=sdram) —
// the PLLs, the SDRAM's block (LiteDRAM's generated core, litedram_core.v, comes from the build tree:
// board.mk adds it) and the pin-level top, whose vendor primitives Verilator does not simulate.
boards/ulx3s/ulx3s_pll.v
boards/ulx3s/ulx3s_sdram_pll.v
soc_rtl/litedram/sdram_wb_burst.v
soc_rtl/litedram/soc_sdram.v
boards/ulx3s/ulx3s_sdram_top.v

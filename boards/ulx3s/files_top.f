// After boards/ulx3s/files.f: what only the FPGA build has — the PLL and the pin-level top, whose
// vendor primitives (EHXPLLL, ODDRX1F) Verilator does not simulate.
boards/ulx3s/ulx3s_pll.v
boards/ulx3s/ulx3s_top.v

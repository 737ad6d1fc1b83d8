// The ULX3S build's own sources after gpu_rtl/files.f, the core and soc_rtl/files.f, in
// compilation order (boards/ulx3s/board.mk, the board's socsim build and lint read it).
boards/common/tmds_encoder.v
boards/common/dvi_tx.v
boards/common/board_status.v
boards/ulx3s/ulx3s_system.v

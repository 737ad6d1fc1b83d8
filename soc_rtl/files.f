// The SoC's own RTL, in compilation order (the package first, soc_top last): the one list soc.mk
// (lint-soc, the simulators) and synth/synth_soc.sh read. The GPU's sources come from
// gpu_rtl/files.f and the CPU from the pythondata-cpu-vexriscv package (SOC_CPU_V in soc.mk).
soc_rtl/soc_pkg.sv
soc_rtl/soc_wb_arbiter.v
soc_rtl/soc_wb_decoder.v
soc_rtl/soc_ram.v
soc_rtl/soc_uart.v
soc_rtl/soc_sys.v
soc_rtl/soc_wb_stage.v
soc_rtl/soc_stream_slice.v
soc_rtl/soc_proj_unit.v
soc_rtl/soc_spiflash.v
soc_rtl/usb/usb_pkg.sv
soc_rtl/usb/usb_ls_tx.v
soc_rtl/usb/usb_ls_rx.v
soc_rtl/usb/usb_ls_packet_tx.v
soc_rtl/usb/usb_ls_packet_rx.v
soc_rtl/usb/usb_ls_xfer.v
soc_rtl/usb/usb_hid_keys.v
soc_rtl/usb/usb_ls_host.v
soc_rtl/usb/soc_usb.v
soc_rtl/soc_top.v

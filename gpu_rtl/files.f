// The GPU's RTL, in compilation order (the package first): the one list the Makefile (lint,
// simulators), synth/synth.sh and the tests read. Paths are relative to the repository root.
gpu_rtl/gpu_pkg.sv
gpu_rtl/gpu_ram.v
gpu_rtl/gpu_cdc_sync.v
gpu_rtl/gpu_cdc_pulse.v
gpu_rtl/gpu_div.v
gpu_rtl/gpu_plane_setup.v
gpu_rtl/gpu_regs.v
gpu_rtl/gpu_prim_setup.v
gpu_rtl/gpu_span_walker.v
gpu_rtl/gpu_raster.v
gpu_rtl/gpu_framebuffer.v
gpu_rtl/gpu_strip_buffer.v
gpu_rtl/gpu_frame_dram.v
gpu_rtl/gpu_vga.v
gpu_rtl/gpu_core.v
gpu_rtl/gpu_top.v
gpu_rtl/gpu_wb_slave.v
gpu_rtl/gpu_axil_slave.v

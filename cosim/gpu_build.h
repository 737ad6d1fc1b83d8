// gpu_build: the GPU's build parameters as this simulator was Verilated with them, for the golden
// model beside it. The Makefile's `verilate` and socsim.mk pass each GPU -G flag of a build once
// more as -DGPU_BUILD_<NAME>=<value> (make's gpu_build_defs, from the very same flags), so the
// model cannot be given other sizes than the RTL; a parameter no flag names has the contract's
// default, as the RTL's does. The co-simulation still compares CAPS, VTX_CAP and TRI_CAP with the
// RTL after every batch, so a disagreement between these and the Verilated model is reported.
//
// Only for translation units compiled per simulator (cosim/gpu_sim.cpp, cosim/soc/socsim.cpp): the
// harness library is compiled once for every simulator and must not see these macros.
#ifndef GPU_BUILD_H
#define GPU_BUILD_H

#ifndef GPU_BUILD_SPAN_W
#error "gpu_build.h: GPU_BUILD_SPAN_W undefined: included outside a Verilated build (see gpu_build_defs)"
#endif

extern "C" {
#include "gpu_model.h"
#include "gpu_regs.h"
}

#ifndef GPU_BUILD_ENABLE_LINES
#define GPU_BUILD_ENABLE_LINES GPU_DEFAULT_ENABLE_LINES
#endif
#ifndef GPU_BUILD_ENABLE_ZBUF
#define GPU_BUILD_ENABLE_ZBUF GPU_DEFAULT_ENABLE_ZBUF
#endif
#ifndef GPU_BUILD_ENABLE_WMASK
#define GPU_BUILD_ENABLE_WMASK GPU_DEFAULT_ENABLE_WMASK
#endif
#ifndef GPU_BUILD_ZBUF_BITS
#define GPU_BUILD_ZBUF_BITS GPU_DEFAULT_ZBUF_BITS
#endif
#ifndef GPU_BUILD_ENABLE_GOURAUD
#define GPU_BUILD_ENABLE_GOURAUD GPU_DEFAULT_ENABLE_GOURAUD
#endif
#ifndef GPU_BUILD_VTX_CAP
#define GPU_BUILD_VTX_CAP GPU_VTX_CAP
#endif
#ifndef GPU_BUILD_TRI_CAP
#define GPU_BUILD_TRI_CAP GPU_TRI_CAP
#endif
#ifndef GPU_BUILD_FB_WIDTH
#define GPU_BUILD_FB_WIDTH GPU_FB_WIDTH
#endif
#ifndef GPU_BUILD_FB_HEIGHT
#define GPU_BUILD_FB_HEIGHT GPU_FB_HEIGHT
#endif
#ifndef GPU_BUILD_STRIP_ROWS
#define GPU_BUILD_STRIP_ROWS GPU_DEFAULT_STRIP_ROWS
#endif
#ifndef GPU_BUILD_FRAME_DRAM
#define GPU_BUILD_FRAME_DRAM GPU_DEFAULT_FRAME_DRAM
#endif

// The model's configuration for this build.
inline gpu_model_config gpu_build_config()
{
    gpu_model_config cfg{};
    cfg.span_w = GPU_BUILD_SPAN_W;
    cfg.lines = GPU_BUILD_ENABLE_LINES != 0;
    cfg.zbuf = GPU_BUILD_ENABLE_ZBUF != 0;
    cfg.wmask = GPU_BUILD_ENABLE_WMASK != 0;
    cfg.gouraud = GPU_BUILD_ENABLE_GOURAUD != 0;
    cfg.vtx_cap = GPU_BUILD_VTX_CAP;
    cfg.tri_cap = GPU_BUILD_TRI_CAP;
    cfg.zbuf_bits = GPU_BUILD_ZBUF_BITS;
    cfg.fb_width = GPU_BUILD_FB_WIDTH;
    cfg.fb_height = GPU_BUILD_FB_HEIGHT;
    cfg.strip_rows = GPU_BUILD_STRIP_ROWS;
    return cfg;
}

#endif

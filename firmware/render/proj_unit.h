/*
 * proj_unit.h — the SoC's projection unit (soc_rtl/soc_proj_unit.v): xf_apply and
 * proj_point_impl of one vertex as five custom instructions (custom-0 on VexRiscv_FullCfu's
 * custom-function port) instead of about 82 instructions, the unit working on one vertex while the
 * core stores the last one's words and reads the next one's. Its answers are the fixed-point path's to
 * the bit (tests/rtl/proj_unit.sh checks the RTL against this firmware's C), so a frame is the
 * same with the unit or without it.
 *
 * A build option: FW_PROJ_UNIT = 1 on a platform whose core has the unit (bsp/soc/bsp.mk);
 * elsewhere (QEMU, the host) it is 0 and the C path runs. The unit implements the default
 * accuracy knobs' projection, fixed point with one Newton step (FW_RECIP_NEWTON_STEPS = 1, any
 * FW_SUBPIXEL_BITS); a build with other knobs keeps the C path (PROJ_UNIT_USED = 0), so
 * `make bench-error` measures its knobs on the SoC as before.
 *
 * proj_unit_regs is pure (host-testable; fixed point only, as the unit): what SET writes into the
 * unit's configuration registers (contract/soc_map.toml [[pu_reg]]) for a projection set-up and a
 * model-view transform.
 */
#ifndef PROJ_UNIT_H
#define PROJ_UNIT_H

#include <stdbool.h>
#include <stdint.h>

#include "config/build_options.h"
#include "math/fixed.h"
#include "math/vec.h"
#include "render/proj.h"
#include "soc_map.h"

#ifndef FW_PROJ_UNIT
#define FW_PROJ_UNIT 0
#endif
#define PROJ_UNIT_USED (FW_PROJ_UNIT && REAL_IS_FIXED && FW_RECIP_NEWTON_STEPS == 1)

#define PROJ_UNIT_REG_COUNT (SOC_PU_REG_LIMITS + 1u)

#if REAL_IS_FIXED
/* The unit's configuration for set-up ps and transform mv: regs[i] is what SET writes to register i. */
static inline void proj_unit_regs(const struct proj_setup *ps, const xf_affine *mv,
                                  uint32_t regs[PROJ_UNIT_REG_COUNT])
{
    for (uint32_t r = 0; r < 3u; r++) {
        for (uint32_t c = 0; c < 3u; c++) {
            regs[SOC_PU_REG_M00 + 3u * r + c] = (uint32_t)mv->r.m[r][c];
        }
    }
    regs[SOC_PU_REG_TX] = (uint32_t)mv->t.x;
    regs[SOC_PU_REG_TX + 1u] = (uint32_t)mv->t.y;
    regs[SOC_PU_REG_TX + 2u] = (uint32_t)mv->t.z;
    regs[SOC_PU_REG_FOCAL_HI] = ps->focal_hi;
    regs[SOC_PU_REG_OFF_SHIFT] = (uint32_t)ps->off_shift | ((uint32_t)PROJ_SUBPIXEL_DROP << 8);
    regs[SOC_PU_REG_CENTRE] = (uint32_t)ps->cx_q4 | ((uint32_t)ps->cy_q4 << 16);
    regs[SOC_PU_REG_LAST] = (uint32_t)ps->x_last | ((uint32_t)ps->y_last << 16);
    regs[SOC_PU_REG_NEAR] = (uint32_t)ps->near;
    regs[SOC_PU_REG_FAR] = (uint32_t)ps->far;
    regs[SOC_PU_REG_LIMITS] = (uint32_t)PROJ_GUARD_Q4 | (PROJ_DEPTH_MAX << 16) |
                              ((FW_WITH_DEPTH && ps->zbuf) ? 0x80000000u : 0u);
}
#endif
/* The fields above fit their registers: the frame's centre and last centres in 16 bits, the
 * depth cap in 15, the guard band in 16. */
_Static_assert(16 * GPU_FB_MAX_WIDTH < 65536 && 16 * GPU_FB_MAX_HEIGHT < 65536,
               "proj_unit: a Q12.4 pixel position of the largest frame needs more than 16 bits");
_Static_assert(PROJ_DEPTH_MAX < 32768u && PROJ_GUARD_Q4 < 65536,
               "proj_unit: the depth cap or the guard band outgrows its field of LIMITS");

#if PROJ_UNIT_USED
#if !defined(__riscv) || __BYTE_ORDER__ != __ORDER_LITTLE_ENDIAN__
#error "FW_PROJ_UNIT: the unit is a custom instruction of the SoC's RV32 core (little-endian)"
#endif

/* One custom-0 instruction: funct3 op, funct7 0, rd = the unit's answer. Volatile: SET and XY
 * change the unit's state, and the answers come in the order the instructions are issued. */
#define PROJ_UNIT_INSN(op, a, b)                                                          \
    __extension__({                                                                       \
        uint32_t answer_;                                                                 \
        __asm__ volatile(".insn r 0x0B, %3, 0, %0, %1, %2"                                \
                         : "=r"(answer_)                                                  \
                         : "r"((uint32_t)(a)), "r"((uint32_t)(b)), "i"(op));              \
        answer_;                                                                          \
    })

/* Whether the core has the unit: a SET of no register changes nothing and answers 0; a SoC built
 * without the unit (soc_top PROJ_UNIT = 0) answers all ones. */
static inline bool proj_unit_present(void)
{
    return PROJ_UNIT_INSN(SOC_PU_OP_SET, 0, PROJ_UNIT_REG_COUNT) == 0u;
}

/* Load the unit's configuration: the projection and the object's model-view transform. */
static inline void proj_unit_load(const struct proj_setup *ps, const xf_affine *mv)
{
    uint32_t regs[PROJ_UNIT_REG_COUNT];

    proj_unit_regs(ps, mv, regs);
    for (uint32_t i = 0; i < PROJ_UNIT_REG_COUNT; i++) {
        (void)PROJ_UNIT_INSN(SOC_PU_OP_SET, regs[i], i);
    }
}

/* n (>= 1) model-space vertices through the loaded transform into out: proj_point (or, inside,
 * proj_point_inside) of xf_apply of each, to the bit. The unit takes the next vertex's XY while it
 * projects one, so the loop gives it before asking for the answers, and stores a vertex's words
 * while the unit projects the next. */
static inline __attribute__((always_inline)) void proj_unit_points(const vec3 *verts, uint32_t n,
                                                                   struct proj_vertex *out,
                                                                   bool inside)
{
    (void)PROJ_UNIT_INSN(SOC_PU_OP_XY, verts[0].x, verts[0].y);
    (void)PROJ_UNIT_INSN(SOC_PU_OP_Z, verts[0].z, inside);
    for (uint32_t i = 0; i < n; i++) {
        const bool more = i + 1u < n;
        uint32_t sxy;
        uint32_t zd;
        uint32_t tail;

        if (more) {
            (void)PROJ_UNIT_INSN(SOC_PU_OP_XY, verts[i + 1u].x, verts[i + 1u].y);
        }
        sxy = PROJ_UNIT_INSN(SOC_PU_OP_SXY, 0, 0);
        zd = PROJ_UNIT_INSN(SOC_PU_OP_ZD, 0, 0);
        tail = inside ? 0u : PROJ_UNIT_INSN(SOC_PU_OP_CODE, 0, 0) << 8;
        if (more) {
            (void)PROJ_UNIT_INSN(SOC_PU_OP_Z, verts[i + 1u].z, inside);
        }
        out[i].sxy = sxy;
        out[i].zd = zd;
        out[i].tail = tail;
    }
}
#endif /* PROJ_UNIT_USED */

#endif /* PROJ_UNIT_H */

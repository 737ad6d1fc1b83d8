/* proj_unit_ref.h — the firmware's projection for the projection unit's testbench (C linkage). */
#ifndef PROJ_UNIT_REF_H
#define PROJ_UNIT_REF_H

#include <stdint.h>

#define PROJ_REF_REGS 19

#ifdef __cplusplus
extern "C" {
#endif

/* What SET writes into the unit's registers for this set-up and transform (proj_unit_regs). */
void proj_ref_regs(int32_t focal_px, int32_t far_q16, uint32_t width, uint32_t height, int zbuf,
                   const int32_t m[9], const int32_t t[3], uint32_t regs[PROJ_REF_REGS]);
/* xf_apply and proj_point (inside: proj_point_inside) of model-space v: the vertex's two words
 * and its outcode. */
void proj_ref_point(int32_t focal_px, int32_t far_q16, uint32_t width, uint32_t height, int zbuf,
                    const int32_t m[9], const int32_t t[3], const int32_t v[3], int inside,
                    uint32_t words[3]);
/* xf_apply's view z of v (q16_16). */
uint32_t proj_ref_view_z(const int32_t m[9], const int32_t t[3], const int32_t v[3]);

#ifdef __cplusplus
}
#endif

#endif /* PROJ_UNIT_REF_H */

/*
 * le.h — little-endian fields read byte by byte, as the mesh file and the upload's frames store
 * them: no alignment and no host byte order assumed (MicroBlaze may be big-endian). Pure code.
 */
#ifndef MODEL_LE_H
#define MODEL_LE_H

#include <stdint.h>

static inline uint32_t le16_at(const uint8_t *p) { return (uint32_t)p[0] | ((uint32_t)p[1] << 8); }
static inline int32_t le16s_at(const uint8_t *p) { return (int32_t)(int16_t)le16_at(p); }
static inline uint32_t le32_at(const uint8_t *p) { return le16_at(p) | (le16_at(p + 2) << 16); }

#endif /* MODEL_LE_H */

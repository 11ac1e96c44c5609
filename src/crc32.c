/* crc32.c - CRC-32 of table bytes (trk/table.h): IEEE 802.3 polynomial,
 * reflected (0xEDB88320), initial value and final xor 0xFFFFFFFF; the same
 * value as zlib's crc32(). Four bits at a time with a 64-byte constant table:
 * tables are checked once at start-up, so ROM size matters more than speed
 * here (a 1 KB byte-wise table would be ~2x faster). */
#include "trk/table.h"

/* crc_nibble[i] = CRC register after shifting the 4-bit value i through */
static const uint32_t crc_nibble[16] = {
    0x00000000u, 0x1db71064u, 0x3b6e20c8u, 0x26d930acu, 0x76dc4190u, 0x6b6b51f4u, 0x4db26158u, 0x5005713cu, 0xedb88320u, 0xf00f9344u, 0xd6d6a3e8u, 0xcb61b38cu, 0x9b64c2b0u, 0x86d3d2d4u, 0xa00ae278u, 0xbdbdf21cu};

uint32_t trk_crc32(uint32_t crc, const void *bytes, size_t len)
{
    const unsigned char *p = bytes;
    if (!p) return crc;
    crc = ~crc;
    for (size_t i = 0; i < len; i++) {
        crc = crc_nibble[(crc ^ p[i]) & 0xfu] ^ (crc >> 4);
        crc = crc_nibble[(crc ^ (uint32_t)(p[i] >> 4)) & 0xfu] ^ (crc >> 4);
    }
    return ~crc;
}

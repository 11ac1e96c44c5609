/* window_impl.h (private) - sliding detection window of up to 64 scans,
 * shared by M/N confirmation and K/N termination. */
#ifndef TRK_WINDOW_IMPL_H
#define TRK_WINDOW_IMPL_H

#include <stdint.h>

/* Push one outcome into a window of n scans (bit 0 = latest) whose count of
 * ones is *count; t is the number of scans before this one. */
static inline void trk_i_window_push(uint64_t *hist, int *count, uint32_t t, int n, int bit)
{
    if (t >= (uint32_t)n) *count -= (int)((*hist >> (n - 1)) & 1u);
    *hist = (*hist << 1) | (uint64_t)(bit != 0);
    if (n < 64) *hist &= (UINT64_C(1) << n) - 1;
    *count += bit != 0;
}

#endif

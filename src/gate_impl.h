/* gate_impl.h (private) - the gate-volume formula, inline for the PDA's hot
 * path; gate.c's public trk_gate_unit_volume, trk_gate_volume and
 * trk_gate_volume_inn wrap these (docs/conventions.md "Gating"). */
#ifndef TRK_GATE_IMPL_H
#define TRK_GATE_IMPL_H

#include "internal.h"
#include "trk/types.h"

/* c_nz: the unit ball's volume (2, pi, 4 pi / 3); 0 for nz outside 1..3. */
TRK_INLINE trk_real trk_i_gate_unit_volume(int nz)
{
    switch (nz) {
    case 1: return 2;
    case 2: return TRK_PI;
    case 3: return TRK_REAL_C(4.0) * TRK_PI / 3;
    default: return 0;
    }
}

/* V_G = c_nz gamma^(nz/2) sqrt(det S), with sqrt(det S) = sqrt_det_s when
 * that is finite, else exp(ln det S / 2) (it overflows first in float). The
 * one place of the formula; gamma^(nz/2) = gamma for nz = 2, without a call.
 * With gamma = d2 of a detection: the volume its ellipse encloses. */
TRK_INLINE trk_real trk_i_gate_volume(int nz, trk_real gamma, trk_real sqrt_det_s, trk_real log_det_s)
{
    const trk_real c = trk_i_gate_unit_volume(nz) * (nz == 2 ? gamma : trk_pow(gamma, (trk_real)nz / 2));
    return sqrt_det_s <= TRK_REAL_MAX ? c * sqrt_det_s : c * trk_exp(TRK_REAL_C(0.5) * log_det_s);
}

#endif

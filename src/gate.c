/* gate.c - gate threshold, volume and distance (docs/conventions.md "Gating"). */
#include "trk/gate.h"

#include "gate_impl.h"
#include "kalman_impl.h"
#include "trk/special.h"

trk_status trk_gate_gamma(int nz, trk_real gate_prob, trk_real *gamma)
{
    if (!gamma || nz < 1 || nz > 3) return TRK_E_ARG;
    if (!(gate_prob > 0 && gate_prob < 1)) return TRK_E_RANGE;
    return trk_chi2_inv(nz, gate_prob, gamma);
}

trk_real trk_gate_unit_volume(int nz) { return trk_i_gate_unit_volume(nz); }

trk_real trk_gate_volume_inn(const struct trk_innovation *inn, trk_real gamma)
{
    return trk_i_gate_volume(inn->nz, gamma, inn->sqrt_det_s, inn->log_det_s);
}

trk_real trk_gate_volume(int nz, trk_real gamma, trk_real log_det_s)
{
    return trk_i_gate_volume(nz, gamma, (trk_real)INFINITY, log_det_s);
}

trk_real trk_gate_d2(const struct trk_innovation *inn, const trk_real *nu)
{
    return trk_i_mahalanobis2(inn->nz, inn->s_chol_inv, nu);
}

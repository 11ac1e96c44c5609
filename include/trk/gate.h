/** @file
 * trk/gate.h - ellipsoidal gating (docs/conventions.md "Gating").
 *
 * A measurement is in the gate when d2 = nu' S^-1 nu <= gamma (less-or-equal),
 * gamma the chi-square inverse CDF of the gate probability P_G with nz degrees
 * of freedom; the gate volume is V_G = c_nz gamma^(nz/2) sqrt(det S),
 * c_1 = 2, c_2 = pi, c_3 = 4 pi / 3. */
#ifndef TRK_GATE_H
#define TRK_GATE_H

#include "trk/types.h"

/** gamma from gate_prob in (0,1), nz in 1..3 (nz = 2: gamma = -2 ln(1 - P_G)).
 * TRK_E_ARG bad nz/pointer, TRK_E_RANGE gate_prob outside (0,1). */
TRK_NODISCARD trk_status trk_gate_gamma(int nz, trk_real gate_prob, trk_real *gamma);

/** c_nz: unit-ball volume (2, pi, 4 pi / 3); 0 for nz outside 1..3. */
trk_real trk_gate_unit_volume(int nz);

struct trk_innovation;

/** V_G = c_nz gamma^(nz/2) sqrt(det S) of the innovation covariance S of *inn
 * (nz = inn->nz). The library evaluates the gate volume in one place
 * (src/gate_impl.h), which this function, trk_gate_volume, the PDA (V_G,
 * lambda = m_G / V_G) and the tracker's clutter tests use; tools call this.
 * With gamma = d2 of a detection it is the volume that detection's ellipse
 * encloses (Kennedy eqs 5-9: rho V_g). sqrt(det S) is taken from
 * inn->sqrt_det_s, or from inn->log_det_s where that overflows (float). */
trk_real trk_gate_volume_inn(const struct trk_innovation *inn, trk_real gamma);

/** The same with ln det S given instead of an innovation (e.g. from a
 * Cholesky factor). */
trk_real trk_gate_volume(int nz, trk_real gamma, trk_real log_det_s);

/** 1 when d2 <= gamma, else 0 (a NaN d2 is outside). */
static inline int trk_gate_inside(trk_real d2, trk_real gamma) { return d2 <= gamma; }

/** Squared Mahalanobis distance d2 = nu' S^-1 nu of the innovation nu
 * (inn->nz values) with the innovation covariance of *inn (kalman.h). */
trk_real trk_gate_d2(const struct trk_innovation *inn, const trk_real *nu);

#endif

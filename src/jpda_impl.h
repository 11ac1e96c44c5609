/* jpda_impl.h (private) - what the tracker's joint association shares with
 * jpda.c. */
#ifndef TRK_JPDA_IMPL_H
#define TRK_JPDA_IMPL_H

#include "trk/jpda.h"

/* JIPDA posterior existence and conditional weights of one track
 * (trk_jpda_existence, docs/conventions.md "Joint association (JPDA /
 * JIPDA)"), in place: p[0, n) holds the track's marginals P(t <- j) and gets beta_j; *beta0 and
 * *psi_post the rest. psi' is in [0, 1] whatever the rounding; when every
 * term underflows (psi tiny) psi' = 0 and beta0 = 1. Statuses as
 * trk_jpda_existence; p untouched on error. */
trk_status trk_i_jpda_condition(trk_real psi, trk_real pd_pg, size_t n, trk_real *p, trk_real p_miss,
                                trk_real *beta0, trk_real *psi_post);

#endif

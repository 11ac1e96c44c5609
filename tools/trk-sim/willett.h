/* willett.h - Willett 2010 ("Issues in Target Tracking", sec. I.C) Table I:
 * q2 of the PDAF for nz = 2, R = I and a gate of area V = 400, and the CRLB
 * of its setting; shared by the experiments willett-table1 and willett-crlb. */
#ifndef TRK_SIM_WILLETT_H
#define TRK_SIM_WILLETT_H

#define WILLETT_NL 10     /* clutter densities (rows) */
#define WILLETT_AREA 400.0 /* V: gamma = V / pi, lambda_vg = V lambda (docs/conventions.md) */

/* Table I, typed from seed 000: q2 at the clutter densities willett_lambda
 * (per unit area) and the detection probabilities willett_pd. */
extern const double willett_lambda[WILLETT_NL];
extern const double willett_pd[3];
extern const double willett_q2[WILLETT_NL][3];

/* The table's q2 at (pd, lambda); NAN when they are not on the table. */
double willett_paper_q2(double pd, double lambda);

/* The steady-state CRLB with the information-reduction factor q2 (Willett
 * eq 37, the library's trk_crlb) in Table I's setting: nz = 2, T = 1 s,
 * q~ = 1 m^2/s^3, R = I: the (1,1) element of J^-1 (j11; NULL: not wanted)
 * and the position RMSE bound. 0, or -1 with "EXP: CRLB at q2 = ..." on
 * stderr. */
int willett_crlb(const char *exp, double q2, double *j11, double *pos_rmse);

#endif

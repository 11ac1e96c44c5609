/* willett.c - Willett 2010 Table I and the CRLB of its setting (willett.h). */
#include "errmsg.h"
#include "willett.h"

#include <math.h>
#include <stdio.h>

#include "trk/crlb.h"

const double willett_lambda[WILLETT_NL] = {0.0001, 0.0020, 0.0040, 0.0060, 0.0080,
                                           0.0100, 0.0120, 0.0140, 0.0160, 0.0180};
const double willett_pd[3] = {0.7, 0.8, 0.9};
const double willett_q2[WILLETT_NL][3] = {
    {0.6814, 0.7700, 0.8890}, {0.6341, 0.7472, 0.8491}, {0.5722, 0.6860, 0.8144},
    {0.5460, 0.6498, 0.7727}, {0.5257, 0.6290, 0.7457}, {0.5037, 0.6096, 0.7367},
    {0.4679, 0.5729, 0.6938}, {0.4479, 0.5343, 0.6801}, {0.4356, 0.5330, 0.6590},
    {0.4180, 0.5133, 0.6312},
};

double willett_paper_q2(double pd, double lambda)
{
    int j = -1;
    for (int k = 0; k < 3; k++)
        if (fabs(pd - willett_pd[k]) < 1e-9) j = k;
    if (j < 0) return NAN;
    for (int i = 0; i < WILLETT_NL; i++)
        if (fabs(lambda - willett_lambda[i]) < 1e-12) return willett_q2[i][j];
    return NAN;
}

int willett_crlb(const char *exp, double q2, double *j11, double *pos_rmse)
{
    const struct trk_crlb_params p = {2, 1, 1, 1, (trk_real)q2, 0, 0};
    struct trk_crlb c;
    struct trk_crlb_result r;
    trk_status st = trk_crlb_init(&c, &p);
    if (st == TRK_OK) st = trk_crlb_steady_state(&c, NULL, &r);
    if (st != TRK_OK) {
        fprintf(stderr, "trk-sim %s: CRLB at q2 = %g: %s\n", exp, q2, ERRMSG_STATUS(st));
        return -1;
    }
    if (j11) *j11 = (double)r.j_inv[0];
    *pos_rmse = (double)r.pos_rmse_m;
    return 0;
}

/* baseline_pda.c - BENCHMARK BASELINE, NOT LIBRARY CODE.
 *
 * A plain fixed-size C99 loop of the arithmetic that trk_cv2_predict +
 * trk_pda_update do for one 2-D CV track (state [x, vx, y, vy], H picks x
 * and y): the prediction, S = H P H' + R with its explicit 2x2 inverse, the
 * gate, the parametric PDAF weights, and the PDA covariance with the
 * Joseph form of P_c,
 *   P = beta0 P- + (1 - beta0) P_c + K (sum beta_i nu_i nu_i' - nubar nubar') K'.
 * No status, no argument or finite check, no log domain, no SPD check of
 * the result: the floor a hand-written loop reaches, for the ratio lines of
 * trk-bench. It uses the benchmark's trk_real, so the double and float
 * builds each compare like with like. */
#include "baseline.h"

#include <math.h>

#ifdef TRK_REAL_FLOAT
#define B_EXP expf
#define B_SQRT sqrtf
#else
#define B_EXP exp
#define B_SQRT sqrt
#endif

void baseline_pda_cv2(const struct baseline_pda *b, trk_real x[4], trk_real p[16], size_t m,
                      const trk_real *z, trk_real *beta)
{
    const trk_real t = b->dt_s, t2 = t * t, q = b->q;
    /* predict: x = F x, P = F P F' + Q (white-noise acceleration) */
    x[0] += t * x[1];
    x[2] += t * x[3];
    trk_real fp[16];
    for (int c = 0; c < 4; c++) {
        fp[0 * 4 + c] = p[0 * 4 + c] + t * p[1 * 4 + c];
        fp[1 * 4 + c] = p[1 * 4 + c];
        fp[2 * 4 + c] = p[2 * 4 + c] + t * p[3 * 4 + c];
        fp[3 * 4 + c] = p[3 * 4 + c];
    }
    for (int r = 0; r < 4; r++) {
        p[r * 4 + 0] = fp[r * 4 + 0] + t * fp[r * 4 + 1];
        p[r * 4 + 1] = fp[r * 4 + 1];
        p[r * 4 + 2] = fp[r * 4 + 2] + t * fp[r * 4 + 3];
        p[r * 4 + 3] = fp[r * 4 + 3];
    }
    p[0] += q * t2 * t / 3;
    p[1] += q * t2 / 2;
    p[4] += q * t2 / 2;
    p[5] += q * t;
    p[10] += q * t2 * t / 3;
    p[11] += q * t2 / 2;
    p[14] += q * t2 / 2;
    p[15] += q * t;
    /* S = H P H' + R and its inverse */
    const trk_real s00 = p[0] + b->r[0], s01 = p[2] + b->r[1], s11 = p[10] + b->r[3];
    const trk_real det = s00 * s11 - s01 * s01;
    const trk_real i00 = s11 / det, i01 = -s01 / det, i11 = s00 / det;
    /* gate and weights: e_i = P_D / (2 pi sqrt|S|) exp(-d2/2), e_0 = lambda (1 - P_D P_G) */
    const trk_real zx = x[0], zy = x[2];
    const trk_real norm = b->pd / (TRK_REAL_C(6.283185307179586) * B_SQRT(det));
    trk_real sum = b->lambda * (1 - b->pd * b->pg);
    const trk_real e0 = sum;
    for (size_t i = 0; i < m; i++) {
        const trk_real nx = z[2 * i] - zx, ny = z[2 * i + 1] - zy;
        const trk_real d2 = nx * (i00 * nx + i01 * ny) + ny * (i01 * nx + i11 * ny);
        beta[i] = d2 <= b->gamma ? norm * B_EXP(TRK_REAL_C(-0.5) * d2) : 0;
        sum += beta[i];
    }
    const trk_real beta0 = e0 / sum;
    /* moments: nubar = sum beta_i nu_i, M = sum beta_i nu_i nu_i' */
    trk_real nbx = 0, nby = 0, mxx = 0, mxy = 0, myy = 0;
    for (size_t i = 0; i < m; i++) {
        beta[i] /= sum;
        const trk_real nx = z[2 * i] - zx, ny = z[2 * i + 1] - zy, w = beta[i];
        nbx += w * nx;
        nby += w * ny;
        mxx += w * nx * nx;
        mxy += w * nx * ny;
        myy += w * ny * ny;
    }
    /* K = P H' S^-1 (4 x 2) */
    trk_real k[8];
    for (int r = 0; r < 4; r++) {
        k[r * 2 + 0] = p[r * 4 + 0] * i00 + p[r * 4 + 2] * i01;
        k[r * 2 + 1] = p[r * 4 + 0] * i01 + p[r * 4 + 2] * i11;
    }
    /* P_c = (I - K H) P (I - K H)' + K R K' (Joseph) */
    trk_real a[16], ap[16], pc[16];
    for (int r = 0; r < 4; r++)
        for (int c = 0; c < 4; c++) a[r * 4 + c] = (r == c) - (c == 0 ? k[r * 2] : c == 2 ? k[r * 2 + 1] : 0);
    for (int r = 0; r < 4; r++)
        for (int c = 0; c < 4; c++)
            ap[r * 4 + c] = a[r * 4 + 0] * p[0 * 4 + c] + a[r * 4 + 1] * p[1 * 4 + c] +
                            a[r * 4 + 2] * p[2 * 4 + c] + a[r * 4 + 3] * p[3 * 4 + c];
    for (int r = 0; r < 4; r++)
        for (int c = 0; c < 4; c++) {
            const trk_real kr0 = k[r * 2], kr1 = k[r * 2 + 1], kc0 = k[c * 2], kc1 = k[c * 2 + 1];
            pc[r * 4 + c] = ap[r * 4 + 0] * a[c * 4 + 0] + ap[r * 4 + 1] * a[c * 4 + 1] +
                            ap[r * 4 + 2] * a[c * 4 + 2] + ap[r * 4 + 3] * a[c * 4 + 3] +
                            kr0 * (b->r[0] * kc0 + b->r[1] * kc1) + kr1 * (b->r[2] * kc0 + b->r[3] * kc1);
        }
    /* spread W = M - nubar nubar', and the combination */
    const trk_real wxx = mxx - nbx * nbx, wxy = mxy - nbx * nby, wyy = myy - nby * nby;
    for (int r = 0; r < 4; r++)
        for (int c = 0; c < 4; c++) {
            const trk_real kr0 = k[r * 2], kr1 = k[r * 2 + 1], kc0 = k[c * 2], kc1 = k[c * 2 + 1];
            const trk_real spread = kr0 * (wxx * kc0 + wxy * kc1) + kr1 * (wxy * kc0 + wyy * kc1);
            p[r * 4 + c] = beta0 * p[r * 4 + c] + (1 - beta0) * pc[r * 4 + c] + spread;
        }
    for (int r = 0; r < 4; r++) x[r] += k[r * 2] * nbx + k[r * 2 + 1] * nby;
}

/* alpha_beta.c - the steady state of the one-axis CV Kalman filter, the
 * gains of the constant-gain (alpha-beta) filter (trk/kalman.h
 * trk_cv_steady_state; docs/conventions.md "Constant-gain filter").
 *
 * Derivation (per axis, F = [1 T; 0 1], Q = q [T^3/3 T^2/2; T^2/2 T], H =
 * [1 0]): in the steady state the updated covariance is P = (I - K H) M with
 * K = [alpha, beta / T]', so P_pp = alpha r, P_pv = beta r / T, M_pp =
 * alpha r / (1 - alpha), M_pv = beta r / (T (1 - alpha)), and M = F P F' + Q
 * gives three equations. The vv one is beta^2 / (1 - alpha) = q T^3 / r =
 * lambda^2; the pv one gives P_vv = alpha beta r / (T^2 (1 - alpha)) - q T /
 * 2; the pp one then alpha^2 + alpha beta - 2 beta + beta^2 / 6 = 0. With s
 * = sqrt(1 - alpha) and beta = lambda s, dividing the last by s^2 leaves
 * (1/s - s)^2 - lambda (1/s + s) + lambda^2 / 6 = 0, a quadratic in u =
 * 1/s + s: u = (lambda + sqrt(16 + lambda^2 / 3)) / 2 (the root >= 2), and s
 * = 2 / (u + sqrt(u^2 - 4)) (the root below 1, without cancellation). The
 * same steps with Q of piecewise-constant acceleration give Kalata's
 * (survey eq 3.5). */
#include "internal.h"
#include "trk/kalman.h"

trk_status trk_cv_steady_state(trk_real dt_s, trk_real q_m2_per_s3, trk_real r_m2, struct trk_cv_steady *ss)
{
    if (!ss || !(dt_s > 0 && dt_s <= TRK_REAL_MAX) || !(q_m2_per_s3 > 0 && q_m2_per_s3 <= TRK_REAL_MAX) ||
        !(r_m2 > 0 && r_m2 <= TRK_REAL_MAX))
        return TRK_E_ARG;
    const trk_real t = dt_s, q = q_m2_per_s3, r = r_m2;
    const trk_real lambda = trk_sqrt(q / r * t) * t; /* sqrt(q T^3 / r), in steps that overflow late */
    if (!(lambda <= TRK_REAL_C(1e15))) return TRK_E_RANGE; /* u^2 below would overflow in float */
    /* u - 2 and 1 - s without cancellation: alpha = (1 - s)(1 + s) keeps its
     * digits when it is small (a float 1 - s^2 kept 3 of them at alpha 0.006) */
    const trk_real w = trk_sqrt(16 + lambda * lambda / 3);
    const trk_real u_m2 = (lambda + lambda * lambda / (3 * (w + 4))) / 2; /* u - 2 */
    const trk_real u = u_m2 + 2, root = trk_sqrt(u_m2 * (u + 2)), den = u + root;
    const trk_real s = 2 / den, s2 = s * s;
    const trk_real alpha = (u_m2 + root) / den * (1 + s), beta = lambda * s, k_vel = beta / t;
    const trk_real post_vv = alpha * k_vel * r / (t * s2) - q * t / 2;
    const trk_real out[10] = {alpha, beta, k_vel, alpha * r / s2, k_vel * r / s2, post_vv + q * t,
                              alpha * r, k_vel * r, post_vv, 0};
    for (int i = 0; i < 9; i++) /* lambda underflowed to 0 (alpha = 0), or a term beyond the real type */
        if (!(out[i] > 0 && out[i] <= TRK_REAL_MAX)) return TRK_E_RANGE;
    ss->alpha = alpha;
    ss->beta = beta;
    ss->k_vel_per_s = k_vel;
    for (int i = 0; i < 3; i++) {
        ss->pred[i] = out[3 + i];
        ss->post[i] = out[6 + i];
    }
    return TRK_OK;
}

/* hmm_brute.h - test helper: the likelihood of a detection sequence under
 * the two-state Markov detection model by brute-force enumeration of every
 * hidden state sequence (Willett eqs 51-53), independent of the library's
 * recursive predictive likelihood, for either event model. Double
 * precision. */
#ifndef TRK_TEST_HMM_BRUTE_H
#define TRK_TEST_HMM_BRUTE_H

#include <math.h>

/* ln P(d_1..m | H1) for one sensor: sum over u_1..u_m of
 * P(u_1) prod P(u_j | u_j-1) prod P(d_j | u_j); m <= 20. pfa NULL: the
 * paper's event model, P(d | u) = pd or 1 - pd; else the complete one with
 * the gate's P_FA pfa[j]: P(miss | u) = (1 - pd)(1 - pfa_j), P(hit | u) =
 * 1 - P(miss | u) (docs/conventions.md "Complete detection-event model"). */
static inline double brute_log_lik_events(int m, const int *d, const double *pfa, double p,
                                          double q, double pd_low, double pd_high,
                                          double pi0_high)
{
    double total = 0;
    for (unsigned long seq = 0; seq < (1ul << m); seq++) {
        double pr = 1;
        for (int j = 0; j < m; j++) {
            int u = (int)((seq >> j) & 1u);
            if (j == 0) pr *= u ? pi0_high : 1 - pi0_high;
            else {
                int up = (int)((seq >> (j - 1)) & 1u);
                pr *= up ? (u ? 1 - q : q) : (u ? p : 1 - p);
            }
            double pd = u ? pd_high : pd_low;
            const double miss = pfa ? (1 - pd) * (1 - pfa[j]) : 1 - pd;
            pr *= d[j] ? (pfa ? 1 - miss : pd) : miss;
        }
        total += pr;
    }
    return log(total);
}

/* The paper's event model (f1 of Blanding eq 8 as printed). */
static inline double brute_log_lik(int m, const int *d, double p, double q, double pd_low,
                                   double pd_high, double pi0_high)
{
    return brute_log_lik_events(m, d, NULL, p, q, pd_low, pd_high, pi0_high);
}

#endif

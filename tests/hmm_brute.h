/* hmm_brute.h - test helper: the likelihood of a detection sequence under
 * the two-state Markov detection model by brute-force enumeration of every
 * hidden state sequence (Willett eqs 51-53), independent of the library's
 * recursive predictive likelihood. Double precision. */
#ifndef TRK_TEST_HMM_BRUTE_H
#define TRK_TEST_HMM_BRUTE_H

#include <math.h>

/* ln P(d_1..m | H1) for one sensor: sum over u_1..u_m of
 * P(u_1) prod P(u_j | u_j-1) prod P(d_j | u_j); m <= 20. */
static double brute_log_lik(int m, const int *d, double p, double q, double pd_low,
                            double pd_high, double pi0_high)
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
            pr *= d[j] ? pd : 1 - pd;
        }
        total += pr;
    }
    return log(total);
}

#endif

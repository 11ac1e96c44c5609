/* track_tests.c - dispatch from the tracker to the confirmation and
 * termination tests (see track_tests.h). */
#include "track_tests.h"

#include "internal.h"

trk_status trk_i_tests_check(const struct trk_tracker_params *p)
{
    trk_status st;
    switch (p->confirm.method) {
    case TRK_CONFIRM_MN: {
        struct trk_mn s;
        st = trk_mn_init(&s, &p->confirm.u.mn);
        break;
    }
    default: return TRK_E_ARG;
    }
    if (st != TRK_OK) return st;
    switch (p->term.method) {
    case TRK_TERM_KN: {
        struct trk_kn s;
        st = trk_kn_init(&s, &p->term.u.kn);
        break;
    }
    default: return TRK_E_ARG;
    }
    return st;
}

void trk_i_confirm_start(const struct trk_tracker_params *p, struct trk_track *tr)
{
    switch (p->confirm.method) {
    case TRK_CONFIRM_MN: TRK_CHECKED(trk_mn_init(&tr->confirm.mn, &p->confirm.u.mn)); break;
    }
    tr->confirm_stat = 0;
}

int trk_i_confirm_step(const struct trk_tracker_params *p, struct trk_track *tr,
                       const struct trk_look *look)
{
    int d = 0;
    switch (p->confirm.method) {
    case TRK_CONFIRM_MN:
        d = trk_mn_step(&tr->confirm.mn, look->detected);
        tr->confirm_stat = (trk_real)tr->confirm.mn.count;
        break;
    }
    return d;
}

void trk_i_term_start(const struct trk_tracker_params *p, struct trk_track *tr)
{
    switch (p->term.method) {
    case TRK_TERM_KN: TRK_CHECKED(trk_kn_init(&tr->term.kn, &p->term.u.kn)); break;
    }
    tr->term_stat = 0;
}

int trk_i_term_step(const struct trk_tracker_params *p, struct trk_track *tr,
                    const struct trk_look *look)
{
    int d = 0;
    switch (p->term.method) {
    case TRK_TERM_KN:
        d = trk_kn_step(&tr->term.kn, look->detected);
        tr->term_stat = (trk_real)tr->term.kn.count;
        break;
    }
    return d;
}

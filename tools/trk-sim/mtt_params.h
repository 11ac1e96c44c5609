/* mtt_params.h - the tracker configurations of trk-sim's multi-target
 * experiments (trk-sim mtt, trk-sim demo): each configuration's parameters
 * for a scenario of tools/sim/mtt_scenario.h at a clutter density, with the
 * user's --set settings on top. */
#ifndef TRK_SIM_MTT_PARAMS_H
#define TRK_SIM_MTT_PARAMS_H

#include <stddef.h>

#include "mtt_scenario.h"
#include "tracker_config.h"
#include "trk/tracker.h"

#define MTT_MAX_SETTINGS 64

/* The configurations: new (trk_tracker_default_params), pda (the same with
 * per-track PDA), old (the defaults before two-point initiation), imm (new
 * with IMM tracks), oracle (no tracker: its R and q), cart (the sonar
 * family's new the old way: the caller converts), cfar (new given each
 * detection's true clutter density), known (new given only the targets'
 * detections: no persistent-return description, the scans having none).
 * cfg_name[kind]. */
enum { CFG_NEW, CFG_PDA, CFG_OLD, CFG_IMM, CFG_ORACLE, CFG_CART, CFG_CFAR, CFG_KNOWN, N_CFG_KINDS };
extern const char *const cfg_name[N_CFG_KINDS];

struct mtt_settings {
    const char *kv[MTT_MAX_SETTINGS];
    int n;
};

/* The imm configuration's models (--imm-rate, --imm-stay, --imm-turn-q). */
struct imm_opts {
    double rate_dps, p_stay, turn_q;
};

/* The tracker parameters of configuration kind at clutter density lambda
 * (per m^2: the scenario's sensor, then the --set settings; rt holds what
 * the settings loaded, tcfg_unload it). 0, or -1 with a message in err. */
int mtt_build_params(int kind, const struct mtt_scenario *sc, double lambda, double q, const struct imm_opts *im,
                     const struct mtt_settings *set, struct trk_tracker_params *out, struct tcfg_runtime *rt,
                     char *err, size_t n);

#endif

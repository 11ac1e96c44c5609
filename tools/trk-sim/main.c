/* trk-sim - seeded Monte Carlo experiments reproducing the papers' results.
 *
 *   trk-sim <experiment> [options]     run one experiment
 *   trk-sim --help                     list the experiments
 *   trk-sim <experiment> --help        the experiment's options
 *
 * Experiments register themselves (sim.h); each writes CSV files (and a
 * gnuplot script + PNG when gnuplot is available) under its --out prefix and
 * prints a summary on stdout. Runs are keyed by (--seed, run index), so the
 * results do not depend on --threads. */
#include <stdio.h>
#include <string.h>

#include "sim.h"
#include "trk/types.h"

#define SIM_ENTRY(id, name, desc) SIM_EXPERIMENT(id, name, desc);
#include "sim_experiments.inc"
#undef SIM_ENTRY

static const struct {
    const char *name, *desc;
    int (*fn)(int, char **);
} experiments[] = {
#define SIM_ENTRY(id, name, desc) {name, desc, sim_exp_##id},
#include "sim_experiments.inc"
#undef SIM_ENTRY
    {NULL, NULL, NULL}};

static void usage(FILE *f)
{
    fprintf(f, "usage: trk-sim <experiment> [options]   (trk-sim <experiment> --help for its options)\n"
               "experiments:\n");
    for (int i = 0; experiments[i].name; i++)
        fprintf(f, "  %-20s %s\n", experiments[i].name, experiments[i].desc);
    fprintf(f, "common options (where an experiment uses them):\n");
    sim_common_usage(f);
}

int main(int argc, char **argv)
{
    if (trk_config_check() != TRK_OK) {
        fprintf(stderr, "trk-sim: libtrk was built with other capacities or real type\n");
        return 2;
    }
    if (argc < 2 || strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0) {
        usage(argc < 2 ? stderr : stdout);
        return argc < 2 ? 2 : 0;
    }
    for (int i = 0; experiments[i].name; i++)
        if (strcmp(argv[1], experiments[i].name) == 0) return experiments[i].fn(argc - 1, argv + 1);
    fprintf(stderr, "trk-sim: unknown experiment '%s'\n", argv[1]);
    usage(stderr);
    return 2;
}

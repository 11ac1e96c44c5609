/* trk-sim - seeded Monte Carlo experiments reproducing the papers' results.
 *
 *   trk-sim <experiment> [options]     run one experiment
 *   trk-sim --help                     list the experiments
 *   trk-sim <experiment> --help        the experiment's options
 *
 * Experiments register themselves (sim.h); each writes CSV files (and a
 * gnuplot script + PNG when gnuplot is available) under its --out prefix and
 * prints a summary on stdout. Runs are keyed by (--seed, run index), so the
 * results do not depend on --threads. Compiled with -DTRK_TOOL_MPI
 * (mk/mpi.mk) this is trk-sim-mpi: the same program on every rank of an MPI
 * job, the runs spread over the ranks (tools/par/par.h), the files written
 * by rank 0. */
#include <stdio.h>

#include "cli.h"

#include "par.h"
#include "sim.h"
#include "trk/types.h"

#ifdef TRK_TOOL_MPI
#include "par_mpi.h" /* its PAR_TOOL_MAIN */
#define SIM_PROG "trk-sim-mpi"
#else
#define SIM_PROG "trk-sim"
#endif

#define SIM_ENTRY(id, name, desc) SIM_EXPERIMENT(id, name, desc);
#include "sim_experiments.inc"
#undef SIM_ENTRY

static const struct cli_cmd experiments[] = {
#define SIM_ENTRY(id, name, desc) {name, desc, sim_exp_##id},
#include "sim_experiments.inc"
#undef SIM_ENTRY
    {NULL, NULL, NULL}};

static void common_usage(FILE *f)
{
    fprintf(f, "common options (where an experiment uses them):\n");
    sim_common_usage(f);
}

static int run(int argc, char **argv)
{
    if (trk_config_check() != TRK_OK) {
        fprintf(stderr, SIM_PROG ": libtrk was built with other capacities or real type\n");
        return 2;
    }
    return cli_dispatch(SIM_PROG, "experiment",
                        "usage: trk-sim <experiment> [options]   (trk-sim <experiment> --help for its options)\n"
                        "experiments:\n",
                        experiments, common_usage, argc, argv);
}

PAR_TOOL_MAIN(sim_par, run, SIM_PROG) /* main; every rank runs it, rank 0 writes */

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
#include "par_mpi.h"
#define SIM_PROG "trk-sim-mpi"
static struct par g_par; /* this rank of the job */
struct par *sim_par(void) { return &g_par; }
#else
#define SIM_PROG "trk-sim"
struct par *sim_par(void) { return NULL; }
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

int main(int argc, char **argv)
{
#ifdef TRK_TOOL_MPI
    if (par_mpi_start(&g_par, &argc, &argv, SIM_PROG) != 0) return 1;
    const int rc = run(argc, argv);
    /* the files are written: the checkpoint (if any) goes */
    if (par_finish(&g_par, rc == 0) != 0 && rc == 0) return par_mpi_end(&g_par, 1);
    return par_mpi_end(&g_par, rc);
#else
    return run(argc, argv);
#endif
}

/* par_mpi.h - par's message layer over MPI: the one piece of trk
 * that includes mpi.h, linked only into the tools' MPI builds
 * (build/bin/trk-tablegen-mpi, trk-sim-mpi: mk/mpi.mk). libtrk never sees
 * MPI.
 *
 * MPI_Init_thread with MPI_THREAD_FUNNELED (only the thread that called
 * par_run talks to MPI; OpenMP threads compute). Errors on MPI_COMM_WORLD
 * are returned and checked: a failed call prints "PROG: rank R: MPI_X:
 * message" and ends the job (MPI_Abort), as does a rank that dies (the MPI
 * runtime's doing). Waiting (broadcasts, the last sends) polls with short
 * sleeps, so a rank that waits leaves its core to the others. Ranks > 0
 * write nothing on stdout (it goes to /dev/null) and are quiet; their
 * error messages stay on stderr. */
#ifndef TRK_TOOLS_PAR_MPI_H
#define TRK_TOOLS_PAR_MPI_H

#include "par.h"

/* The main of a tool's MPI build: par_mpi_start, run(argc, argv) (the
 * tool), par_finish (the output is written when run returned 0: the
 * checkpoint goes), par_mpi_end with run's exit status. */
int par_mpi_main(struct par *p, int argc, char **argv, const char *prog, int (*run)(int argc, char **argv));

/* PAR_TOOL_MAIN (par.h) of the MPI build: this rank's par, main through
 * par_mpi_main. */
#define PAR_TOOL_MAIN(accessor, run, prog)                                                   \
    static struct par accessor##_rank;                                                       \
    struct par *accessor(void) { return &accessor##_rank; }                                  \
    int main(int argc, char **argv) { return par_mpi_main(&accessor##_rank, argc, argv, prog, run); }

/* Start MPI and make *p this rank (par_init, then rank, size, comm). Run
 * without mpirun it is a job of one rank. 0, or -1 with a message. */
int par_mpi_start(struct par *p, int *argc, char ***argv, const char *prog);

/* The end of the program with exit status `status`: 0 MPI_Finalize (and
 * 0); else MPI_Abort(status), which ends every rank (a rank that fails
 * alone must not leave the others waiting; ranks > 0 first give rank 0 3 s
 * to do it, so that an error of every rank is reported once). */
int par_mpi_end(struct par *p, int status);

#endif

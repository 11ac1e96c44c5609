/* par.h - work distribution of the host tools: a batch of N
 * independent work units, each writing a result of known size into its own
 * slot of one buffer, run on the OpenMP threads of this process or over the
 * ranks of an MPI job, with every result on every rank in index order when
 * the batch returns; a checkpoint of the finished units that a restarted run
 * resumes from; progress of all ranks on rank 0.
 *
 * The callers merge the slots in index order after par_run, as they did
 * before (trk-tablegen: the q2 sampler's items, the amplitude table's nodes;
 * trk-sim: every Monte Carlo run). A unit's result is a pure function of its
 * index and the run's arguments (counter-based random numbers keyed by
 * (seed, unit)), so the bytes of the output are the same for any number of
 * threads and ranks, and for a resumed run.
 *
 * PROCESSES. A struct par describes this process: one process (par_init;
 * NULL stands for it everywhere), or one rank of an MPI job (par_mpi.h fills
 * comm; only trk-*-mpi link it, libtrk never sees MPI). Every rank runs the
 * same program on the same arguments (SPMD): it makes the same batches in
 * the same order and calls par_run for each; a unit never calls par_run with
 * the process's par (nested work runs locally: par NULL).
 *
 * ASSIGNMENT. Units are grouped into chunks of consecutive units
 * (par_batch.chunk). Chunks are assigned statically: with costs, greedily to
 * the least loaded rank in decreasing cost (longest processing time first);
 * without, cyclically (chunk k to rank k mod size). Within a rank the
 * threads take the rank's chunks dynamically, costliest first. Rank 0 (the
 * root) computes its share too; between its chunks its first thread takes in
 * the other ranks' finished chunks (sent every 0.1 s), counts them into the
 * progress (par_batch.done) and writes the checkpoint. At the end rank 0
 * broadcasts all results, so every rank continues with the same data.
 *
 * CHECKPOINT (par_checkpoint; rank 0 only). A file of finished units per
 * batch, keyed by the job key (the tool's arguments that determine the
 * results, and the library's configuration): another run's file is refused.
 * It is rewritten as units finish, at most every interval_s seconds and
 * only once the results finished since the last write are at least 1/8 of
 * those in the file (so the writes cost in proportion to the results, about
 * 8 + 17 ln(chunks / 8) of them with interval 0), always whole: written to
 * a temporary file, fsync'd and
 * renamed onto the path (fileio.h), so it is never cut. A run with the same
 * arguments takes the units it holds instead of computing them (their bytes
 * are those of the first run), and par_finish removes it after the output
 * is written.
 *
 * FAILURE. A unit returning non-zero fails the batch after the others ran:
 * par_run returns PAR_E_UNIT with the lowest failed unit and its code, the
 * same on every rank (the checkpoint keeps the units that finished). A rank
 * that dies ends the job (the MPI runtime's default error handling: mpirun
 * kills the others and exits non-zero); the tools write their output only on
 * rank 0 after every batch returned, atomically, so no cut file appears.
 * Fault injection for the tests: TRK_PAR_FAIL_AFTER=N makes rank
 * TRK_PAR_FAIL_RANK (default 0) print a line and _exit(3) once it has
 * finished N units (counted over the batches of the process).
 * TRK_PAR_STATS=1: every rank says at the end how long it worked, how
 * long it waited for the others (the balance of the assignment) and how
 * many checkpoint files it wrote.
 *
 * Host code: heap, stdio, OpenMP. */
#ifndef TRK_TOOLS_PAR_H
#define TRK_TOOLS_PAR_H

#include <stddef.h>
#include <stdint.h>

/* The message layer between the ranks (par_mpi.c implements it over MPI).
 * Every function returns 0 or -1 (the backend reports the error itself);
 * par calls abort when the ranks cannot go on together (a failed call, no
 * memory on one rank, ranks that disagree). Only the thread that called
 * par_run calls them. */
struct par_comm {
    void *ctx;
    /* every rank: rank 0's buf[len] into everyone's buf */
    int (*bcast)(void *ctx, void *buf, size_t len);
    /* rank > 0: send buf[len] (malloc'd; the backend frees it once sent) to rank 0 */
    int (*send)(void *ctx, void *buf, size_t len);
    /* rank > 0: sends still in flight? *pending = their count (wait: until none) */
    int (*sends)(void *ctx, int wait, size_t *pending);
    /* rank 0: the next message from any rank into *buf (malloc'd, caller frees),
     * *len; *buf = NULL when none is waiting */
    int (*recv)(void *ctx, void **buf, size_t *len);
    /* end the whole job with a message on stderr (does not return) */
    void (*abort)(void *ctx, const char *msg);
};

struct par_ckpt; /* par.c */

struct par {
    const char *prog;             /* message prefix ("trk-sim-mpi") */
    int rank, size;               /* 0, 1 for one process */
    const struct par_comm *comm;  /* NULL: one process */
    int quiet;                    /* no checkpoint notes on stderr */
    struct par_ckpt *ckpt;        /* rank 0, par_checkpoint; else NULL */
    int ckpt_on;                  /* every rank: a checkpoint is in use */
    uint64_t seq;                 /* batches run so far */
    long fail_after;              /* TRK_PAR_FAIL_AFTER (-1: off) */
    int fail_rank;                /* TRK_PAR_FAIL_RANK */
    uint64_t units_here;          /* units finished by this process */
    uint64_t units_resumed, units_computed; /* over all ranks (rank 0) */
    uint64_t ckpt_writes;         /* checkpoint files written (rank 0) */
    /* TRK_PAR_STATS=1: par_finish prints, per rank, the batches, the time
     * this rank worked on its units and the time it waited for the others */
    int stats;
    uint64_t batches, result_bytes;
    double work_s, wait_s;
};

enum {
    PAR_OK = 0,
    PAR_E_UNIT = -1,   /* a unit failed: failed_unit, failed_code */
    PAR_E_NOMEM = -2,
    PAR_E_CKPT = -3,   /* the checkpoint does not fit this batch */
    PAR_E_ARG = -4     /* a batch without run or sizes */
};

struct par_batch {
    size_t n;                  /* work units */
    size_t size;               /* result bytes of every unit (offsets NULL) */
    const size_t *offsets;     /* else unit i's result is out[offsets[i] .. offsets[i+1]) */
    size_t chunk;              /* consecutive units per chunk (0: 1) */
    const double *cost;        /* per unit, for the assignment and order (NULL: uniform) */
    int threads;               /* OpenMP threads of this rank (<= 0: the default) */
    /* unit i: write its result into res (its slot); *ws is this thread's
     * workspace (NULL at first; run may allocate it, ws_free frees it).
     * 0, or a failure code (> 0 or < 0, the caller's) */
    int (*run)(void *ctx, size_t i, void *res, void **ws);
    void (*ws_free)(void *ctx, void *ws); /* may be NULL */
    /* rank 0, one thread at a time: units [first, first + count) are done
     * (computed anywhere, or resumed); for progress. May be NULL */
    void (*done)(void *ctx, size_t first, size_t count);
    void *ctx;                 /* run's and ws_free's */
    void *done_ctx;            /* done's (NULL: ctx) */
    /* out, with PAR_E_UNIT: the lowest failed unit and its code */
    size_t failed_unit;
    int failed_code;
};

/* The main of a tool with an MPI build (trk-tablegen, trk-sim):
 *     PAR_TOOL_MAIN(accessor, run, prog)
 * defines `struct par *accessor(void)` (this process's par: NULL in the
 * single-process build) and main, which runs `int run(int argc, char
 * **argv)`. With -DTRK_TOOL_MPI the tool includes tools/par/mpi/par_mpi.h
 * too, whose PAR_TOOL_MAIN runs it through par_mpi_main (on every rank, the
 * checkpoint removed after success): par knows nothing of its MPI layer. */
#ifndef TRK_TOOL_MPI
#define PAR_TOOL_MAIN(accessor, run, prog)       \
    struct par *accessor(void) { return NULL; } \
    int main(int argc, char **argv) { return run(argc, argv); }
#endif

/* *b = n units of `size` bytes (0 with offsets), `chunk` units per chunk,
 * run(ctx, ...); every other field 0 (set them after). */
void par_batch_init(struct par_batch *b, size_t n, size_t size, size_t chunk,
                    int (*run)(void *ctx, size_t i, void *res, void **ws), void *ctx);

/* One process: rank 0 of 1, no checkpoint; the fault injection from the
 * environment. */
void par_init(struct par *p, const char *prog);

/* 1 on the rank that writes the output (rank 0; also for p == NULL). */
int par_is_root(const struct par *p);

/* Run every unit of b (see above); the results are in out (every slot) on
 * every rank when it returns PAR_OK. p may be NULL (one process). Else a
 * PAR_E_* code, the same on every rank, with a message in err (PAR_E_UNIT:
 * "unit I failed (code C)"). */
int par_run(struct par *p, struct par_batch *b, void *out, char *err, size_t errlen);

/* Units [0, n) of one fixed size through par_run: the shape of an executor
 * hook (amp_table.h's struct amp_table_exec): fn(ctx, i, out + i * size) for
 * every i, on p's threads and ranks (p: a struct par *, or NULL). 0, or -1
 * when a unit or the distribution failed. */
int par_for_each(void *p, size_t n, size_t size, int (*fn)(void *ctx, size_t i, void *res), void *ctx,
                 void *out);

/* Use a checkpoint at path (collective: every rank calls it). Rank 0 reads
 * the file when it exists: refused (-1, message in err) when it is not a
 * checkpoint, is damaged or was written for another job key; else its units
 * are resumed by the batches that follow. interval_s: the least time between
 * two writes (0: none; the 1/8 rule above holds at any interval). 0, or -1
 * on every rank. */
int par_checkpoint(struct par *p, const char *path, double interval_s, const char *job_key, char *err,
                   size_t errlen);

/* The tools' --help text of --checkpoint-interval. */
#define PAR_CHECKPOINT_INTERVAL_HELP                                        \
    "least seconds between two writes of FILE; a write also waits for\n"   \
    "new results of at least 1/8 of those in FILE, so that the writes\n"   \
    "cost in proportion to the results (0: no least time)"

/* par_checkpoint for a tool's command line (argv[0] its subcommand): the
 * job key from tool ("trk-sim kennedy-null") and the arguments but
 * --threads, --quiet, --no-plot, --checkpoint and --checkpoint-interval;
 * a refusal printed by rank 0 as "TOOL: message". 0, or 2 (the exit status
 * of bad usage) on every rank. */
int par_checkpoint_cli(struct par *p, const char *tool, const char *path, double interval_s, int argc,
                       char **argv);

/* End of the run: with ok, rank 0 removes the checkpoint (the output is
 * written) and says how many units it resumed; without, it writes what is
 * done. Frees the checkpoint state. 0, or -1 with a message on stderr. */
int par_finish(struct par *p, int ok);

/* The job key of a checkpoint: "tool arg arg ..." (the arguments after the
 * subcommand) without the options named in skip_value (each with its value,
 * as "--opt V" or "--opt=V") and skip_flag, then the library's configuration
 * (trk_config_check's knobs). 0, or -1 when it does not fit in buf. */
int par_job_key(char *buf, size_t len, const char *tool, int argc, char **argv, const char *const *skip_value,
                const char *const *skip_flag);

#endif

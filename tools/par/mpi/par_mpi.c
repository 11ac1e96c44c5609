/* par_mpi.c - par's message layer over MPI (par_mpi.h). Compiled with
 * mpicc into libtrk_par_mpi.a (mk/mpi.mk). */
#define _POSIX_C_SOURCE 199309L
#include "par_mpi.h"

#include <limits.h>
#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define TAG 20                      /* par's messages to rank 0 */
#define PIECE ((size_t)1 << 30)     /* broadcasts in pieces of at most 1 GiB (int counts) */

struct pend {
    MPI_Request req;
    void *buf;
};

struct mpi_ctx {
    const char *prog;
    int rank;
    struct pend *pend;
    size_t n_pend, cap_pend;
};

static struct mpi_ctx g_ctx;   /* one MPI per process: the tool's one context */
static struct par_comm g_comm;

static void nap(void)
{
    const struct timespec ts = {0, 200000}; /* 0.2 ms */
    nanosleep(&ts, NULL);
}

static void die(const struct mpi_ctx *c, const char *msg)
{
    fprintf(stderr, "%s: rank %d: %s; the job ends\n", c->prog, c->rank, msg);
    fflush(stderr);
    fflush(stdout);
    MPI_Abort(MPI_COMM_WORLD, 3);
    exit(3);
}

/* a failed MPI call: its message, then the end of the job */
static void check(const struct mpi_ctx *c, int rc, const char *call)
{
    if (rc == MPI_SUCCESS) return;
    char s[MPI_MAX_ERROR_STRING], m[MPI_MAX_ERROR_STRING + 64];
    int n = 0;
    if (MPI_Error_string(rc, s, &n) != MPI_SUCCESS) snprintf(s, sizeof s, "error %d", rc);
    snprintf(m, sizeof m, "%s: %s", call, s);
    die(c, m);
}

/* wait for req, polling: a waiting rank sleeps instead of spinning */
static void wait_req(struct mpi_ctx *c, MPI_Request *req, const char *call)
{
    for (;;) {
        int flag = 0;
        check(c, MPI_Test(req, &flag, MPI_STATUS_IGNORE), call);
        if (flag) return;
        nap();
    }
}

static int c_bcast(void *ctx, void *buf, size_t len)
{
    struct mpi_ctx *c = ctx;
    for (size_t at = 0; at < len; at += PIECE) {
        const size_t n = len - at < PIECE ? len - at : PIECE;
        MPI_Request req;
        check(c, MPI_Ibcast((char *)buf + at, (int)n, MPI_BYTE, 0, MPI_COMM_WORLD, &req), "MPI_Ibcast");
        wait_req(c, &req, "MPI_Ibcast");
    }
    return 0;
}

static int c_send(void *ctx, void *buf, size_t len)
{
    struct mpi_ctx *c = ctx;
    if (len > INT_MAX) die(c, "a message of more than 2 GiB");
    if (c->n_pend == c->cap_pend) {
        const size_t cap = c->cap_pend ? 2 * c->cap_pend : 16;
        struct pend *np = realloc(c->pend, cap * sizeof *np);
        if (!np) die(c, "out of memory");
        c->pend = np;
        c->cap_pend = cap;
    }
    struct pend *e = &c->pend[c->n_pend];
    check(c, MPI_Isend(buf, (int)len, MPI_BYTE, 0, TAG, MPI_COMM_WORLD, &e->req), "MPI_Isend");
    e->buf = buf;
    c->n_pend++;
    return 0;
}

static int c_sends(void *ctx, int wait, size_t *pending)
{
    struct mpi_ctx *c = ctx;
    for (;;) {
        size_t keep = 0;
        for (size_t i = 0; i < c->n_pend; i++) {
            int flag = 0;
            check(c, MPI_Test(&c->pend[i].req, &flag, MPI_STATUS_IGNORE), "MPI_Test");
            if (flag) {
                free(c->pend[i].buf);
                continue;
            }
            c->pend[keep++] = c->pend[i];
        }
        c->n_pend = keep;
        if (!wait || keep == 0) break;
        nap();
    }
    *pending = c->n_pend;
    return 0;
}

static int c_recv(void *ctx, void **buf, size_t *len)
{
    struct mpi_ctx *c = ctx;
    int flag = 0, n = 0;
    MPI_Status st;
    *buf = NULL;
    *len = 0;
    check(c, MPI_Iprobe(MPI_ANY_SOURCE, TAG, MPI_COMM_WORLD, &flag, &st), "MPI_Iprobe");
    if (!flag) return 0;
    check(c, MPI_Get_count(&st, MPI_BYTE, &n), "MPI_Get_count");
    void *b = malloc(n > 0 ? (size_t)n : 1);
    if (!b) die(c, "out of memory");
    check(c, MPI_Recv(b, n, MPI_BYTE, st.MPI_SOURCE, TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE), "MPI_Recv");
    *buf = b;
    *len = (size_t)n;
    return 0;
}

static void c_abort(void *ctx, const char *msg) { die(ctx, msg); }

int par_mpi_start(struct par *p, int *argc, char ***argv, const char *prog)
{
    par_init(p, prog);
    int provided = 0, rank = 0, size = 1;
    if (MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS) {
        fprintf(stderr, "%s: MPI_Init_thread failed\n", prog);
        return -1;
    }
    MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
    memset(&g_ctx, 0, sizeof g_ctx);
    g_ctx.prog = prog;
    check(&g_ctx, MPI_Comm_rank(MPI_COMM_WORLD, &rank), "MPI_Comm_rank");
    g_ctx.rank = rank;
    check(&g_ctx, MPI_Comm_size(MPI_COMM_WORLD, &size), "MPI_Comm_size");
    if (provided < MPI_THREAD_FUNNELED && rank == 0)
        fprintf(stderr, "%s: note: this MPI gives thread level %d only (FUNNELED wanted); only one thread calls it\n",
                prog, provided);
    g_comm = (struct par_comm){&g_ctx, c_bcast, c_send, c_sends, c_recv, c_abort};
    p->rank = rank;
    p->size = size;
    p->comm = &g_comm;
    if (rank > 0) {
        p->quiet = 1;
        if (!freopen("/dev/null", "w", stdout)) die(&g_ctx, "cannot send stdout to /dev/null");
    }
    return 0;
}

int par_mpi_main(struct par *p, int argc, char **argv, const char *prog, int (*run)(int argc, char **argv))
{
    if (par_mpi_start(p, &argc, &argv, prog) != 0) return 1;
    const int rc = run(argc, argv);
    if (par_finish(p, rc == 0) != 0 && rc == 0) return par_mpi_end(p, 1);
    return par_mpi_end(p, rc);
}

int par_mpi_end(struct par *p, int status)
{
    (void)p;
    fflush(stdout);
    fflush(stderr);
    if (status == 0) {
        size_t pending = 0;
        c_sends(&g_ctx, 1, &pending);
        MPI_Finalize();
        return 0;
    }
    /* An error every rank meets (a usage error, a refused checkpoint) is
     * reported by rank 0 and its abort ends the others: they wait for it
     * (one banner of the runtime instead of one per rank), and abort
     * themselves after 3 s (an error of their own). */
    if (g_ctx.rank > 0) {
        const struct timespec ts = {0, 100000000};
        for (int i = 0; i < 30; i++) nanosleep(&ts, NULL);
    }
    MPI_Abort(MPI_COMM_WORLD, status);
    return status;
}

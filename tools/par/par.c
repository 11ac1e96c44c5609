/* par.c - work distribution of the host tools (par.h): the batch runner on
 * this process's threads and, through struct par_comm, over MPI ranks; the
 * checkpoint file; the job key.
 *
 * OpenMP pragmas go through PAR_OMP() (as q2_is.c's): compiled without
 * -fopenmp the same source runs serially. */
#define _POSIX_C_SOURCE 199309L
#include "par.h"

#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "errmsg.h"
#include "fileio.h"
#include "progress.h"
#include "trk/types.h"

#ifdef _OPENMP
#include <omp.h>
#define PAR_OMP(x) _Pragma(#x)
#else
#define PAR_OMP(x)
#endif

#define SEND_EVERY_S 0.1            /* a worker rank sends its finished chunks this often */
#define SEND_BYTES ((size_t)1 << 20) /* or once this much is waiting */
#define MSG_MAGIC 0x3130474d52415054ull /* "TPARMG01" */
#define MSG_DATA 1u
#define MSG_END 2u
#define CKPT_MAGIC "TRKPARCK"
#define CKPT_VERSION 1u
#define CKPT_ENDIAN 0x01020304u
#define CKPT_MAX_BYTES ((size_t)1 << 40)
#define CKPT_GROWTH 8 /* a write waits for 1/8 of the file's results in new ones (ckpt_maybe_write) */

/* ---------------------------------------------------------------- basics */

static double now_s(void) { return progress_now_s(); }

static void nap(void)
{
    const struct timespec ts = {0, 500000}; /* 0.5 ms */
    nanosleep(&ts, NULL);
}

static size_t unit_off(const struct par_batch *b, size_t i) { return b->offsets ? b->offsets[i] : i * b->size; }

void par_init(struct par *p, const char *prog)
{
    memset(p, 0, sizeof *p);
    p->prog = prog ? prog : "trk";
    p->size = 1;
    p->fail_after = -1;
    const char *fa = getenv("TRK_PAR_FAIL_AFTER"), *fr = getenv("TRK_PAR_FAIL_RANK");
    if (fa && *fa) {
        char *end;
        const long v = strtol(fa, &end, 10);
        if (!*end && v >= 0) p->fail_after = v;
    }
    if (fr && *fr) p->fail_rank = atoi(fr);
    const char *st = getenv("TRK_PAR_STATS");
    p->stats = st && *st && strcmp(st, "0") != 0;
}

int par_is_root(const struct par *p) { return !p || p->rank == 0; }

void par_batch_init(struct par_batch *b, size_t n, size_t size, size_t chunk,
                    int (*run)(void *ctx, size_t i, void *res, void **ws), void *ctx)
{
    memset(b, 0, sizeof *b);
    b->n = n;
    b->size = size;
    b->chunk = chunk;
    b->run = run;
    b->ctx = ctx;
}

/* FNV-1a, 64 bits */
static uint64_t fnv(uint64_t h, const void *data, size_t n)
{
    const unsigned char *s = data;
    for (size_t i = 0; i < n; i++) h = (h ^ s[i]) * 0x100000001b3ull;
    return h;
}
#define FNV0 0xcbf29ce484222325ull

/* ---------------------------------------------------------------- job key */

static int in_list(const char *a, const char *const *list, int with_value, int *eq)
{
    *eq = 0;
    for (; list && *list; list++) {
        const size_t n = strlen(*list);
        if (strcmp(a, *list) == 0) return 1;
        if (with_value && strncmp(a, *list, n) == 0 && a[n] == '=') {
            *eq = 1;
            return 1;
        }
    }
    return 0;
}

int par_job_key(char *buf, size_t len, const char *tool, int argc, char **argv, const char *const *skip_value,
                const char *const *skip_flag)
{
    size_t at = 0;
    int n = snprintf(buf, len, "%s", tool);
    if (n < 0 || (size_t)n >= len) return -1;
    at = (size_t)n;
    for (int i = 1; i < argc; i++) {
        int eq;
        if (in_list(argv[i], skip_value, 1, &eq)) {
            if (!eq) i++; /* and its value */
            continue;
        }
        if (in_list(argv[i], skip_flag, 0, &eq)) continue;
        n = snprintf(buf + at, len - at, " %s", argv[i]);
        if (n < 0 || (size_t)n >= len - at) return -1;
        at += (size_t)n;
    }
    n = snprintf(buf + at, len - at,
                 " | trk: real %zu, tracks %zu, detections %zu, sensors %zu, state %zu, meas %zu, kmax %zu, "
                 "clutter tests %d, joint %d, imm %d, models %zu, jpda bits %zu, pairs %zu",
                 trk_real_size(), trk_max_tracks(), trk_max_detections(), trk_max_sensors(), trk_max_state(),
                 trk_max_meas(), trk_clutter_kmax(), (int)trk_with_clutter_tests(), (int)trk_with_joint(),
                 (int)trk_with_imm(), trk_max_models(), trk_jpda_exact_bits(), trk_max_gated_pairs());
    return n < 0 || (size_t)n >= len - at ? -1 : 0;
}

/* ---------------------------------------------------------------- checkpoint */

struct par_rec {
    uint64_t seq, n_units, batch_bytes, first, count, bytes;
    unsigned char *data; /* owned */
};

struct par_ckpt {
    char path[1024];
    char *key;
    size_t key_len;
    double interval_s, last_write;
    /* result bytes in the file last written (or read), and finished since */
    uint64_t file_bytes, new_bytes;
    int dirty, write_failed, write_errno;
    struct par_rec *rec;
    size_t n_rec, cap_rec;
    /* the batch running (rank 0): its done units are written from out */
    int in_batch;
    uint64_t seq;
    const struct par_batch *b;
    const unsigned char *out, *done;
};

static void rec_free(struct par_rec *r)
{
    free(r->data);
    r->data = NULL;
}

static int rec_add(struct par_ckpt *c, const struct par_rec *r)
{
    if (c->n_rec == c->cap_rec) {
        const size_t cap = c->cap_rec ? 2 * c->cap_rec : 64;
        struct par_rec *nr = realloc(c->rec, cap * sizeof *nr);
        if (!nr) return -1;
        c->rec = nr;
        c->cap_rec = cap;
    }
    c->rec[c->n_rec++] = *r;
    return 0;
}

static void ckpt_free(struct par_ckpt *c)
{
    if (!c) return;
    for (size_t i = 0; i < c->n_rec; i++) rec_free(&c->rec[i]);
    free(c->rec);
    free(c->key);
    free(c);
}

/* little helpers of the file format: native u64s (a failed write is kept
 * by fileio_put, with its errno, for fileio_commit) */
struct wr {
    struct fileio_out *o;
    uint64_t h;
};

static void wr_bytes(struct wr *w, const void *p, size_t n)
{
    if (n == 0) return;
    (void)fileio_put(w->o, p, n);
    w->h = fnv(w->h, p, n);
}

static void wr_u64(struct wr *w, uint64_t v) { wr_bytes(w, &v, sizeof v); }

static void wr_rec(struct wr *w, uint64_t seq, uint64_t n_units, uint64_t batch_bytes, uint64_t first,
                   uint64_t count, uint64_t bytes, const void *data)
{
    const uint64_t h[6] = {seq, n_units, batch_bytes, first, count, bytes};
    wr_bytes(w, h, sizeof h);
    wr_bytes(w, data, (size_t)bytes);
}

/* The runs of done units of the batch running. */
static size_t done_runs(const struct par_ckpt *c, int write, struct wr *w)
{
    if (!c->in_batch) return 0;
    const struct par_batch *b = c->b;
    const uint64_t total = unit_off(b, b->n);
    size_t runs = 0;
    for (size_t i = 0; i < b->n;) {
        if (!c->done[i]) {
            i++;
            continue;
        }
        size_t j = i;
        while (j < b->n && c->done[j]) j++;
        if (write) {
            const size_t a = unit_off(b, i), z = unit_off(b, j);
            wr_rec(w, c->seq, b->n, total, i, j - i, z - a, c->out + a);
        }
        runs++;
        i = j;
    }
    return runs;
}

/* Rewrite the whole file: temporary file, fsync, rename (fileio_commit). */
static int ckpt_write(struct par_ckpt *c)
{
    struct fileio_out o;
    if (!fileio_create(&o, c->path, 1)) return -1;
    struct wr w = {&o, FNV0};
    const uint32_t ver[2] = {CKPT_VERSION, CKPT_ENDIAN};
    wr_bytes(&w, CKPT_MAGIC, 8);
    wr_bytes(&w, ver, sizeof ver);
    wr_u64(&w, c->key_len);
    wr_bytes(&w, c->key, c->key_len);
    size_t n = 0;
    for (size_t i = 0; i < c->n_rec; i++)
        if (!(c->in_batch && c->rec[i].seq == c->seq)) n++; /* this batch's: from done[] */
    n += done_runs(c, 0, NULL);
    wr_u64(&w, n);
    for (size_t i = 0; i < c->n_rec; i++) {
        const struct par_rec *r = &c->rec[i];
        if (c->in_batch && r->seq == c->seq) continue;
        wr_rec(&w, r->seq, r->n_units, r->batch_bytes, r->first, r->count, r->bytes, r->data);
    }
    done_runs(c, 1, &w);
    const uint64_t h = w.h;
    (void)fileio_put(&o, &h, sizeof h);
    if (fileio_commit(&o) != 0) return -1;
    c->file_bytes += c->new_bytes;
    c->new_bytes = 0;
    c->dirty = 0;
    c->last_write = now_s();
    return 0;
}

/* Write when due (force: now): interval_s after the last write, and once
 * the results finished since are at least CKPT_GROWTH of those in the file.
 * Every write rewrites the whole file, so a write per chunk would cost the
 * square of the results (a 4.7 s job unfinished after 240 s); growing the
 * file by a factor of at least 1 + 1/CKPT_GROWTH per write bounds the bytes
 * written to (CKPT_GROWTH + 1) x the results plus the first few chunks, and
 * the writes to about CKPT_GROWTH + ln(chunks / CKPT_GROWTH) / ln(1 +
 * 1/CKPT_GROWTH), at most 1/(CKPT_GROWTH + 1) of the finished work being
 * unwritten when a rank dies. A failed write is reported once; the run goes
 * on (the checkpoint is an aid, the output is what matters) and the next
 * write tries again. */
static void ckpt_failed(struct par *p, int e);

static void ckpt_maybe_write(struct par *p, int force)
{
    struct par_ckpt *c = p->ckpt;
    if (!c || !c->dirty) return;
    if (!force && (now_s() - c->last_write < c->interval_s || c->new_bytes * CKPT_GROWTH < c->file_bytes)) return;
    if (ckpt_write(c) != 0) {
        ckpt_failed(p, errno);
    } else {
        c->write_failed = 0;
        p->ckpt_writes++;
    }
}

/* A write of the checkpoint failed with errno e: said once (until a write
 * succeeds again); the run goes on (the checkpoint is an aid, the output
 * is what matters). */
static void ckpt_failed(struct par *p, int e)
{
    struct par_ckpt *c = p->ckpt;
    if (!c->write_failed)
        fprintf(stderr, "%s: checkpoint %s: cannot write: %s (the run goes on)\n", p->prog, c->path, strerror(e));
    c->write_failed = 1;
    c->write_errno = e;
}

/* At the start: can the checkpoint be written at all (its directory exists
 * and takes a file)? A temporary file created and removed; a failure said
 * now, not only at the first write (which may never come in a short run). */
static void ckpt_probe(struct par *p)
{
    struct fileio_out o;
    if (!fileio_create(&o, p->ckpt->path, 1)) {
        ckpt_failed(p, errno);
        return;
    }
    fileio_discard(&o);
}

struct rd {
    const unsigned char *p;
    size_t n, at;
};

static int rd_u64(struct rd *r, uint64_t *v)
{
    if (r->n - r->at < sizeof *v) return -1;
    memcpy(v, r->p + r->at, sizeof *v);
    r->at += sizeof *v;
    return 0;
}

static int ckpt_load(struct par_ckpt *c, const unsigned char *buf, size_t len, char *err, size_t errlen)
{
    struct rd r = {buf, len, 0};
    uint32_t ver[2];
    if (len < 8 + sizeof ver + 2 * sizeof(uint64_t) || memcmp(buf, CKPT_MAGIC, 8) != 0)
        return errmsg_fail(err, errlen, "checkpoint %s: not a checkpoint file", c->path);
    uint64_t h;
    memcpy(&h, buf + len - sizeof h, sizeof h);
    if (fnv(FNV0, buf, len - sizeof h) != h)
        return errmsg_fail(err, errlen, "checkpoint %s: damaged (checksum)", c->path);
    r.n = len - sizeof h;
    memcpy(ver, buf + 8, sizeof ver);
    r.at = 8 + sizeof ver;
    if (ver[0] != CKPT_VERSION || ver[1] != CKPT_ENDIAN)
        return errmsg_fail(err, errlen, "checkpoint %s: version %u (this program writes %u) or another byte order",
                           c->path, ver[0], CKPT_VERSION);
    uint64_t klen, n;
    if (rd_u64(&r, &klen) || klen > r.n - r.at) return errmsg_fail(err, errlen, "checkpoint %s: damaged", c->path);
    if (klen != c->key_len || memcmp(buf + r.at, c->key, c->key_len) != 0)
        return errmsg_fail(err, errlen,
                           "checkpoint %s belongs to another run (%.*s); remove it or give another --checkpoint",
                           c->path, (int)(klen < 300 ? klen : 300), (const char *)(buf + r.at));
    r.at += (size_t)klen;
    if (rd_u64(&r, &n)) return errmsg_fail(err, errlen, "checkpoint %s: damaged", c->path);
    for (uint64_t i = 0; i < n; i++) {
        struct par_rec x;
        memset(&x, 0, sizeof x);
        if (rd_u64(&r, &x.seq) || rd_u64(&r, &x.n_units) || rd_u64(&r, &x.batch_bytes) || rd_u64(&r, &x.first) ||
            rd_u64(&r, &x.count) || rd_u64(&r, &x.bytes) || x.bytes > r.n - r.at || x.count == 0 ||
            x.first > x.n_units || x.count > x.n_units - x.first || x.bytes > x.batch_bytes)
            return errmsg_fail(err, errlen, "checkpoint %s: damaged (record %llu)", c->path, (unsigned long long)i);
        x.data = malloc(x.bytes ? (size_t)x.bytes : 1);
        if (!x.data) return errmsg_fail(err, errlen, "checkpoint %s: out of memory", c->path);
        memcpy(x.data, buf + r.at, (size_t)x.bytes);
        r.at += (size_t)x.bytes;
        c->file_bytes += x.bytes;
        if (rec_add(c, &x) != 0) {
            free(x.data);
            return errmsg_fail(err, errlen, "checkpoint %s: out of memory", c->path);
        }
    }
    if (r.at != r.n) return errmsg_fail(err, errlen, "checkpoint %s: damaged (trailing bytes)", c->path);
    return 0;
}

int par_checkpoint(struct par *p, const char *path, double interval_s, const char *job_key, char *err,
                   size_t errlen)
{
    if (err && errlen) err[0] = 0;
    int32_t st = 0;
    if (par_is_root(p)) {
        struct par_ckpt *c = calloc(1, sizeof *c);
        if (!c || strlen(path) >= sizeof c->path || !(c->key = malloc(strlen(job_key) + 1))) {
            ckpt_free(c);
            st = errmsg_fail(err, errlen, "checkpoint %s: out of memory or path too long", path);
        } else {
            strcpy(c->path, path);
            strcpy(c->key, job_key);
            c->key_len = strlen(job_key);
            c->interval_s = interval_s > 0 ? interval_s : 0;
            c->last_write = now_s();
            /* a rank killed in a write left its temporary file */
            const size_t n_stale = fileio_remove_stale(path);
            if (n_stale && !p->quiet)
                fprintf(stderr, "%s: checkpoint %s: removed %zu temporary file%s of a write that never finished\n",
                        p->prog, path, n_stale, n_stale > 1 ? "s" : "");
            size_t len = 0;
            unsigned char *buf = fileio_read_max(path, CKPT_MAX_BYTES, &len);
            if (buf) {
                st = ckpt_load(c, buf, len, err, errlen);
                free(buf);
            } else if (errno != ENOENT) {
                st = errmsg_fail(err, errlen, "checkpoint %s: %s", path, strerror(errno));
            }
            if (st == 0 && c->n_rec > 0 && !p->quiet)
                fprintf(stderr, "%s: checkpoint %s: %zu records of finished work units to resume from\n", p->prog,
                        path, c->n_rec);
            if (st == 0) {
                p->ckpt = c;
                ckpt_probe(p);
            } else {
                ckpt_free(c);
            }
        }
    }
    if (p->comm && p->comm->bcast(p->comm->ctx, &st, sizeof st) != 0) st = -1;
    p->ckpt_on = st == 0;
    return st == 0 ? 0 : -1;
}

int par_checkpoint_cli(struct par *p, const char *tool, const char *path, double interval_s, int argc,
                       char **argv)
{
    static const char *const skip_value[] = {"--threads", "--checkpoint", "--checkpoint-interval", NULL};
    static const char *const skip_flag[] = {"--quiet", "--no-plot", NULL};
    char key[8192], err[1600];
    if (par_job_key(key, sizeof key, tool, argc, argv, skip_value, skip_flag) != 0) {
        if (par_is_root(p)) fprintf(stderr, "%s: the arguments are too long for a checkpoint key\n", tool);
        return 2;
    }
    if (par_checkpoint(p, path, interval_s, key, err, sizeof err) != 0) {
        if (par_is_root(p)) fprintf(stderr, "%s: %s\n", tool, err);
        return 2;
    }
    return 0;
}

int par_finish(struct par *p, int ok)
{
    if (!p) return 0;
    if (p->stats)
        fprintf(stderr, "%s: rank %d of %d: %llu batches (%.3g MB of results), %llu work units here, %.3f s on them, "
                        "%.3f s waiting for the other ranks; %llu checkpoint writes\n",
                p->prog, p->rank, p->size, (unsigned long long)p->batches, 1e-6 * (double)p->result_bytes,
                (unsigned long long)p->units_here, p->work_s, p->wait_s, (unsigned long long)p->ckpt_writes);
    struct par_ckpt *c = p->ckpt;
    int rc = 0;
    if (c) {
        if (ok) {
            if (remove(c->path) != 0 && errno != ENOENT) {
                fprintf(stderr, "%s: checkpoint %s: cannot remove: %s\n", p->prog, c->path, strerror(errno));
                rc = -1;
            }
            if (c->write_failed) /* the last write failed: nothing of this run is in it */
                fprintf(stderr, "%s: checkpoint %s: %llu work units resumed, %llu computed; not written (%s)\n",
                        p->prog, c->path, (unsigned long long)p->units_resumed,
                        (unsigned long long)p->units_computed, strerror(c->write_errno));
            else if (!p->quiet)
                fprintf(stderr, "%s: checkpoint %s: %llu work units resumed, %llu computed; removed\n", p->prog,
                        c->path, (unsigned long long)p->units_resumed, (unsigned long long)p->units_computed);
        } else {
            ckpt_maybe_write(p, 1);
        }
        ckpt_free(c);
        p->ckpt = NULL;
    }
    p->ckpt_on = 0;
    return rc;
}

/* This batch's records into out (rank 0): done[i] = 1 for the units they
 * hold; *n_done their count. 0, or PAR_E_CKPT (message). */
static int ckpt_take(struct par *p, uint64_t seq, const struct par_batch *b, unsigned char *out,
                     unsigned char *done, size_t *n_done, char *err, size_t errlen)
{
    struct par_ckpt *c = p->ckpt;
    *n_done = 0;
    if (!c) return 0;
    const uint64_t total = unit_off(b, b->n);
    for (size_t k = 0; k < c->n_rec; k++) {
        const struct par_rec *r = &c->rec[k];
        if (r->seq != seq) continue;
        if (r->n_units != b->n || r->batch_bytes != total || r->first + r->count > b->n ||
            r->bytes != unit_off(b, (size_t)(r->first + r->count)) - unit_off(b, (size_t)r->first)) {
            errmsg_fail(err, errlen,
                        "checkpoint %s does not fit this run: batch %llu has %zu units of %llu bytes here, %llu of "
                        "%llu in the file (remove it to start again)",
                        c->path, (unsigned long long)seq, b->n, (unsigned long long)total,
                        (unsigned long long)r->n_units, (unsigned long long)r->batch_bytes);
            return PAR_E_CKPT;
        }
        memcpy(out + unit_off(b, (size_t)r->first), r->data, (size_t)r->bytes);
        for (uint64_t i = r->first; i < r->first + r->count; i++) {
            *n_done += !done[i];
            done[i] = 1;
        }
    }
    return 0;
}

/* The batch's done units become records of their own (copies): the batch
 * is over, out may go. */
static int ckpt_seal(struct par_ckpt *c)
{
    size_t keep = 0;
    for (size_t k = 0; k < c->n_rec; k++) {
        if (c->rec[k].seq == c->seq) {
            rec_free(&c->rec[k]);
            continue;
        }
        c->rec[keep++] = c->rec[k];
    }
    c->n_rec = keep;
    const struct par_batch *b = c->b;
    const uint64_t total = unit_off(b, b->n);
    int rc = 0;
    for (size_t i = 0; i < b->n && rc == 0;) {
        if (!c->done[i]) {
            i++;
            continue;
        }
        size_t j = i;
        while (j < b->n && c->done[j]) j++;
        const size_t a = unit_off(b, i), z = unit_off(b, j);
        struct par_rec r = {c->seq, b->n, total, i, j - i, z - a, malloc(z - a ? z - a : 1)};
        if (!r.data || rec_add(c, &r) != 0) {
            free(r.data);
            rc = -1;
        } else {
            memcpy(r.data, c->out + a, z - a);
        }
        i = j;
    }
    c->in_batch = 0;
    c->dirty = 1;
    return rc;
}

/* ---------------------------------------------------------------- the batch */

struct chunk {
    size_t first, count;
    double cost;
};

struct run {
    struct par *p;
    struct par_batch *b;
    unsigned char *out;
    int multi;                /* several ranks */
    struct chunk *ch;
    size_t n_ch;
    size_t *mine, n_mine;
    unsigned char *done;      /* per unit: resumed; rank 0: finished */
    /* completion queue (critical par_q): chunk, and whether a unit of it failed */
    size_t *q, q_in, q_out;
    unsigned char *qfail;
    size_t n_local_done;
    /* lowest failed unit (critical par_fail) */
    size_t fail_unit;
    int fail_code, failed;
    /* worker ranks: records waiting to be sent */
    unsigned char *sbuf;
    size_t slen, scap;
    double last_send;
    int end_sent;
    /* rank 0: the other ranks that have finished */
    int ends;
    double t0, t_local;       /* start; this rank's units done (0: not yet) */
};

/* The ranks cannot go on together: end the job (several ranks). */
static void fatal(const struct par *p, const char *fmt, ...)
{
    char msg[300];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    p->comm->abort(p->comm->ctx, msg);
    abort(); /* not reached */
}

static int cmp_chunk_cost(size_t x, size_t y, const struct chunk *ch)
{
    if (ch[x].cost != ch[y].cost) return ch[x].cost > ch[y].cost ? -1 : 1;
    return x < y ? -1 : x > y;
}

/* chunk indices by decreasing cost, ties in index order (qsort has no
 * context, and is not stable): a merge sort */
static void sort_by_cost(size_t *v, size_t n, const struct chunk *ch, size_t *tmp)
{
    if (n < 2) return;
    const size_t h = n / 2;
    sort_by_cost(v, h, ch, tmp);
    sort_by_cost(v + h, n - h, ch, tmp);
    size_t i = 0, j = h, k = 0;
    while (i < h && j < n) tmp[k++] = cmp_chunk_cost(v[i], v[j], ch) <= 0 ? v[i++] : v[j++];
    while (i < h) tmp[k++] = v[i++];
    while (j < n) tmp[k++] = v[j++];
    memcpy(v, tmp, n * sizeof *v);
}

static void fail_unit(struct run *r, size_t u, int code)
{
    PAR_OMP(omp critical(par_fail))
    {
        if (!r->failed || u < r->fail_unit) {
            r->fail_unit = u;
            r->fail_code = code;
        }
        r->failed = 1;
    }
}

static void buf_put(struct run *r, const void *p, size_t n)
{
    if (r->slen + n > r->scap) {
        size_t cap = r->scap ? r->scap : 4096;
        while (cap < r->slen + n) cap *= 2;
        unsigned char *nb = realloc(r->sbuf, cap);
        if (!nb) fatal(r->p, "rank %d: out of memory for a message of %zu bytes", r->p->rank, cap);
        r->sbuf = nb;
        r->scap = cap;
    }
    memcpy(r->sbuf + r->slen, p, n);
    r->slen += n;
}

static void msg_head(struct run *r, uint64_t kind, uint64_t x, uint64_t y, uint64_t z)
{
    const uint64_t h[6] = {MSG_MAGIC, kind, r->p->seq - 1, x, y, z};
    buf_put(r, h, sizeof h);
}

/* Worker ranks: send what is waiting (data records, and the end). */
static void flush_sends(struct run *r)
{
    if (r->slen == 0) return;
    const struct par_comm *c = r->p->comm;
    if (c->send(c->ctx, r->sbuf, r->slen) != 0) fatal(r->p, "rank %d: a send to rank 0 failed", r->p->rank);
    r->sbuf = NULL;
    r->slen = r->scap = 0;
    r->last_send = now_s();
}

/* Rank 0: units [first, first + count) finished (its own or a message's);
 * the hook hears of the ones not done before (a chunk partly resumed is
 * computed again, with the same bytes) */
static void root_done(struct run *r, size_t first, size_t count)
{
    const struct par_batch *b = r->b;
    for (size_t i = first; i < first + count;) {
        if (r->done[i]) {
            i++;
            continue;
        }
        size_t j = i;
        while (j < first + count && !r->done[j]) r->done[j++] = 1;
        if (b->done) b->done(b->done_ctx ? b->done_ctx : b->ctx, i, j - i);
        if (r->p->ckpt) r->p->ckpt->new_bytes += unit_off(b, j) - unit_off(b, i);
        i = j;
    }
    if (r->p->ckpt) r->p->ckpt->dirty = 1;
}

/* Rank 0: one message of another rank. */
static void root_message(struct run *r, const unsigned char *m, size_t len)
{
    const struct par_batch *b = r->b;
    uint64_t h[6];
    size_t at = 0;
    int bad = 0;
    while (at < len && !bad) {
        if (len - at < sizeof h) {
            bad = 1;
            break;
        }
        memcpy(h, m + at, sizeof h);
        at += sizeof h;
        if (h[0] != MSG_MAGIC || h[2] != r->p->seq - 1 || (h[1] != MSG_END && h[1] != MSG_DATA)) {
            bad = 1;
        } else if (h[1] == MSG_END) {
            r->ends++;
            if (h[3]) fail_unit(r, (size_t)h[4], (int)(int64_t)h[5]);
        } else {
            const size_t first = (size_t)h[3], count = (size_t)h[4], bytes = (size_t)h[5];
            if (first > b->n || count > b->n - first || bytes > len - at ||
                bytes != unit_off(b, first + count) - unit_off(b, first)) {
                bad = 1;
            } else {
                memcpy(r->out + unit_off(b, first), m + at, bytes);
                at += bytes;
                root_done(r, first, count);
            }
        }
    }
    if (bad) fatal(r->p, "rank 0: a malformed message from another rank (batch %llu)",
                         (unsigned long long)(r->p->seq - 1));
}

/* The first thread, between its chunks and after them: take in finished
 * chunks, talk to the other ranks, write the checkpoint, the fault
 * injection. Returns 1 when this rank's part of the batch is complete. */
static int service(struct run *r)
{
    struct par *p = r->p;
    const struct par_batch *b = r->b;
    const int root = p->rank == 0;
    for (;;) {
        size_t k = 0;
        int have = 0, bad = 0;
        PAR_OMP(omp critical(par_q))
        if (r->q_out < r->q_in) {
            bad = r->qfail[r->q_out];
            k = r->q[r->q_out++];
            have = 1;
        }
        if (!have) break;
        const struct chunk *c = &r->ch[k];
        r->n_local_done++;
        p->units_here += c->count;
        if (bad) continue; /* not done: neither counted nor checkpointed (the end says why) */
        if (root) {
            root_done(r, c->first, c->count);
        } else {
            const size_t a = unit_off(b, c->first), z = unit_off(b, c->first + c->count);
            msg_head(r, MSG_DATA, c->first, c->count, z - a);
            buf_put(r, r->out + a, z - a);
        }
    }
    const int local_done = r->n_local_done == r->n_mine;
    if (local_done && r->t_local == 0) r->t_local = now_s();
    int complete = local_done;
    if (r->multi && root) {
        const struct par_comm *cm = p->comm;
        for (;;) {
            void *m = NULL;
            size_t len = 0;
            if (cm->recv(cm->ctx, &m, &len) != 0) fatal(p, "rank 0: a receive failed");
            if (!m) break;
            root_message(r, m, len);
            free(m);
        }
        complete = local_done && r->ends == p->size - 1;
    } else if (r->multi) {
        const struct par_comm *cm = p->comm;
        if (r->slen && (local_done || r->slen >= SEND_BYTES || now_s() - r->last_send >= SEND_EVERY_S))
            flush_sends(r);
        if (local_done && !r->end_sent) {
            int failed;
            size_t unit;
            int code;
            PAR_OMP(omp critical(par_fail))
            {
                failed = r->failed;
                unit = r->fail_unit;
                code = r->fail_code;
            }
            msg_head(r, MSG_END, (uint64_t)failed, unit, (uint64_t)(int64_t)code);
            flush_sends(r);
            r->end_sent = 1;
        }
        size_t pending = 0;
        if (cm->sends(cm->ctx, 0, &pending) != 0) fatal(p, "rank %d: a send to rank 0 failed", p->rank);
        complete = r->end_sent && pending == 0;
    }
    if (root) ckpt_maybe_write(p, 0);
    if (p->fail_after >= 0 && p->rank == p->fail_rank && p->units_here >= (uint64_t)p->fail_after) {
        fprintf(stderr, "%s: rank %d: TRK_PAR_FAIL_AFTER=%ld: exits after %llu work units (fault injection)\n",
                p->prog, p->rank, p->fail_after, (unsigned long long)p->units_here);
        fflush(stderr);
        _exit(3);
    }
    return complete;
}

static void run_chunks(struct run *r)
{
    const struct par_batch *b = r->b;
    int th = b->threads;
#ifdef _OPENMP
    if (th <= 0) th = omp_get_max_threads();
#endif
    if (th < 1) th = 1;
    (void)th;
    PAR_OMP(omp parallel num_threads(th))
    {
        void *ws = NULL;
        int first_thread = 1;
#ifdef _OPENMP
        first_thread = omp_get_thread_num() == 0;
#endif
        PAR_OMP(omp for schedule(dynamic, 1) nowait)
        for (size_t k = 0; k < r->n_mine; k++) {
            const struct chunk *c = &r->ch[r->mine[k]];
            int bad = 0;
            for (size_t u = c->first; u < c->first + c->count; u++) {
                const int code = b->run(b->ctx, u, r->out + unit_off(b, u), &ws);
                if (code) {
                    fail_unit(r, u, code);
                    bad = 1;
                }
            }
            PAR_OMP(omp critical(par_q))
            {
                r->qfail[r->q_in] = (unsigned char)bad;
                r->q[r->q_in++] = r->mine[k];
            }
            if (first_thread) service(r);
        }
        if (ws && b->ws_free) b->ws_free(b->ctx, ws);
        if (first_thread)
            while (!service(r)) nap();
    }
}

/* rank 0's buf[len] to every rank */
static void bcast(struct run *r, void *buf, size_t len)
{
    const struct par *p = r->p;
    if (r->multi && p->comm->bcast(p->comm->ctx, buf, len) != 0)
        fatal(p, "rank %d: a broadcast from rank 0 failed", p->rank);
}

/* The chunks to run (every unit not resumed), in the order of their costs
 * when given; this rank's share into r->mine. */
static int plan(struct run *r, size_t cs)
{
    const struct par_batch *b = r->b;
    const struct par *p = r->p;
    size_t *todo = malloc(r->n_ch * sizeof *todo), *tmp = malloc(r->n_ch * sizeof *tmp);
    double *load = calloc((size_t)p->size, sizeof *load);
    if (!todo || !tmp || !load) {
        free(todo), free(tmp), free(load);
        return -1;
    }
    size_t n_todo = 0;
    for (size_t k = 0; k < r->n_ch; k++) {
        struct chunk *c = &r->ch[k];
        c->first = k * cs;
        c->count = b->n - c->first < cs ? b->n - c->first : cs;
        c->cost = 0;
        int all = 1;
        for (size_t u = c->first; u < c->first + c->count; u++) {
            c->cost += b->cost ? b->cost[u] : 1;
            all &= r->done[u];
        }
        if (!all) todo[n_todo++] = k;
    }
    /* longest processing time first over the ranks (costs), or cyclic */
    if (b->cost) sort_by_cost(todo, n_todo, r->ch, tmp);
    for (size_t t = 0; t < n_todo; t++) {
        int to = (int)(t % (size_t)p->size);
        if (b->cost) {
            to = 0;
            for (int q = 1; q < p->size; q++)
                if (load[q] < load[to]) to = q;
            load[to] += r->ch[todo[t]].cost;
        }
        if (to == p->rank) r->mine[r->n_mine++] = todo[t];
    }
    free(todo), free(tmp), free(load);
    return 0;
}

int par_run(struct par *p, struct par_batch *b, void *out_v, char *err, size_t errlen)
{
    struct par local;
    if (!p) {
        par_init(&local, NULL);
        local.fail_after = -1; /* the fault injection is the tools' (their struct par) */
        p = &local;
    }
    if (err && errlen) err[0] = 0;
    b->failed_unit = 0;
    b->failed_code = 0;
    if (!b->run || (!b->offsets && b->n && !b->size)) {
        errmsg_fail(err, errlen, "a batch without run function or result size");
        return PAR_E_ARG;
    }
    const uint64_t seq = p->seq++;
    if (b->n == 0) return PAR_OK;
    unsigned char *out = out_v;
    const int root = p->rank == 0;
    struct run r;
    memset(&r, 0, sizeof r);
    r.p = p;
    r.b = b;
    r.out = out;
    r.multi = p->comm && p->size > 1;
    const size_t cs = b->chunk ? b->chunk : 1, total = unit_off(b, b->n);
    r.n_ch = (b->n + cs - 1) / cs;
    r.ch = malloc(r.n_ch * sizeof *r.ch);
    r.mine = malloc(r.n_ch * sizeof *r.mine);
    r.q = malloc(r.n_ch * sizeof *r.q);
    r.qfail = malloc(r.n_ch);
    r.done = calloc(b->n, 1);
    int rc = PAR_OK;
    char msg[1400] = "";
    if (!r.ch || !r.mine || !r.q || !r.qfail || !r.done) {
        if (r.multi) fatal(p, "rank %d: out of memory for a batch of %zu units", p->rank, b->n);
        rc = PAR_E_NOMEM;
        snprintf(msg, sizeof msg, "out of memory");
        goto out;
    }
    /* rank 0: the units the checkpoint holds; every rank learns rank 0's
     * shape of the batch and what it resumed */
    uint64_t head[4] = {seq, b->n, total, 0};
    if (root && p->ckpt) {
        size_t n_done = 0;
        if (ckpt_take(p, seq, b, out, r.done, &n_done, msg, sizeof msg) != 0) head[3] = UINT64_MAX;
        else head[3] = n_done;
    }
    if (r.multi) {
        const uint64_t mine[3] = {seq, b->n, total};
        bcast(&r, head, sizeof head);
        if (head[0] != mine[0] || head[1] != mine[1] || head[2] != mine[2])
            fatal(p, "rank %d: batch %llu has %zu units of %zu bytes here, %llu of %llu on rank 0 (not the same "
                     "arguments?)",
                  p->rank, (unsigned long long)seq, b->n, total, (unsigned long long)head[1],
                  (unsigned long long)head[2]);
    }
    if (head[3] == UINT64_MAX) {
        rc = PAR_E_CKPT;
        if (!msg[0]) snprintf(msg, sizeof msg, "the checkpoint does not fit this run (see rank 0)");
        goto out;
    }
    const size_t n_resumed = (size_t)head[3];
    if (n_resumed && r.multi) { /* the resumed units and their results, for everyone */
        bcast(&r, r.done, b->n);
        bcast(&r, out, total);
    }
    if (root && n_resumed) {
        p->units_resumed += n_resumed;
        for (size_t i = 0; i < b->n && b->done;) { /* the resumed ones count as done */
            if (!r.done[i]) {
                i++;
                continue;
            }
            size_t j = i;
            while (j < b->n && r.done[j]) j++;
            b->done(b->done_ctx ? b->done_ctx : b->ctx, i, j - i);
            i = j;
        }
    }
    if (plan(&r, cs) != 0) {
        if (r.multi) fatal(p, "rank %d: out of memory for the plan of %zu chunks", p->rank, r.n_ch);
        rc = PAR_E_NOMEM;
        snprintf(msg, sizeof msg, "out of memory");
        goto out;
    }
    if (root && p->ckpt) {
        struct par_ckpt *c = p->ckpt;
        c->in_batch = 1;
        c->seq = seq;
        c->b = b;
        c->out = out;
        c->done = r.done;
    }
    r.last_send = r.t0 = now_s();
    run_chunks(&r);
    /* the outcome, the same on every rank: the lowest failed unit */
    int64_t res[3] = {r.failed ? PAR_E_UNIT : PAR_OK, (int64_t)r.fail_unit, r.fail_code};
    bcast(&r, res, sizeof res);
    rc = (int)res[0];
    p->batches++;
    p->result_bytes += total;
    p->work_s += r.t_local - r.t0;
    if (rc == PAR_E_UNIT) {
        b->failed_unit = (size_t)res[1];
        b->failed_code = (int)res[2];
        snprintf(msg, sizeof msg, "work unit %zu of %zu failed (code %d)", b->failed_unit, b->n, b->failed_code);
    } else {
        bcast(&r, out, total);
    }
    p->wait_s += now_s() - r.t_local;
    if (root) {
        if (rc == PAR_OK) p->units_computed += b->n - n_resumed;
        if (p->ckpt) {
            if (ckpt_seal(p->ckpt) != 0 && rc == PAR_OK) {
                if (r.multi) fatal(p, "rank 0: out of memory for the checkpoint");
                rc = PAR_E_NOMEM;
                snprintf(msg, sizeof msg, "out of memory for the checkpoint");
            }
            ckpt_maybe_write(p, rc != PAR_OK); /* a failed batch: what finished, now */
        }
    }
out:
    if (rc && err && errlen) snprintf(err, errlen, "%s", msg);
    free(r.ch), free(r.mine), free(r.q), free(r.qfail), free(r.done), free(r.sbuf);
    return rc;
}

/* ---------------------------------------------------------------- a hook */

struct each {
    int (*fn)(void *ctx, size_t i, void *res);
    void *ctx;
};

static int each_run(void *ctx, size_t i, void *res, void **ws)
{
    const struct each *e = ctx;
    (void)ws;
    return e->fn(e->ctx, i, res) ? 1 : 0;
}

int par_for_each(void *p, size_t n, size_t size, int (*fn)(void *ctx, size_t i, void *res), void *ctx, void *out)
{
    struct each e = {fn, ctx};
    struct par_batch b;
    par_batch_init(&b, n, size, 8, each_run, &e);
    char err[256];
    const int rc = par_run(p, &b, out, err, sizeof err);
    if (rc != PAR_OK && rc != PAR_E_UNIT) fprintf(stderr, "%s: %s\n", p ? ((struct par *)p)->prog : "trk", err);
    return rc == PAR_OK ? 0 : -1;
}

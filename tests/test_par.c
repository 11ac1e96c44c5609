/* test_par.c - the work distribution layer (tools/par/par.h) in one process:
 * every unit's result in its slot for 1, 2 and 4 threads and any chunk size,
 * fixed and variable result sizes, the progress hook (every unit once), the
 * lowest failed unit reported; the checkpoint: a failed batch's finished
 * units resumed by the next run (not computed again, the same bytes), the
 * file removed at the end, refused for another job key, damaged (every
 * truncation, a flipped byte) or not fitting the batch; the job key; the
 * amplitude table through par_for_each (the executor hook) byte-identical to
 * its own loops. The ranks of an MPI job: tests/mpi_steps.sh. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <unistd.h>

#include "amp_table.h"
#include "fileio.h"
#include "par.h"
#include "trk_test.h"

#define N_UNITS 1000

/* a unit's value: a function of its index only */
static uint64_t value(size_t i)
{
    uint64_t h = 0x9e3779b97f4a7c15ull * (i + 1);
    h ^= h >> 29;
    return h * 0xbf58476d1ce4e5b9ull;
}

struct job {
    unsigned char calls[N_UNITS]; /* units computed (each by one thread) */
    unsigned char seen[N_UNITS];  /* the done hook's (rank 0's one thread) */
    size_t fail_from;             /* units >= fail_from with an odd index fail */
    int var;                      /* variable sizes: unit i has i % 5 + 1 values */
};

/* the job of a test, zeroed: units >= fail_from with an odd index fail */
static struct job *fresh(size_t fail_from)
{
    static struct job j;
    memset(&j, 0, sizeof j);
    j.fail_from = fail_from;
    return &j;
}

static int unit(void *ctx, size_t i, void *res, void **ws)
{
    struct job *j = ctx;
    if (!*ws && !(*ws = malloc(64))) return 99; /* a thread's workspace */
    j->calls[i]++;
    if (i >= j->fail_from && i % 2 == 1) return 5 + (int)(i % 3);
    const size_t nv = j->var ? i % 5 + 1 : 1;
    for (size_t k = 0; k < nv; k++) {
        const uint64_t v = value(i) + k;
        memcpy((unsigned char *)res + 8 * k, &v, 8);
    }
    return 0;
}

static void ws_free(void *ctx, void *ws)
{
    (void)ctx;
    free(ws);
}

static void done(void *ctx, size_t first, size_t count)
{
    struct job *j = ctx;
    for (size_t i = first; i < first + count; i++) j->seen[i]++;
}

static void batch(struct par_batch *b, struct job *j, size_t chunk, int threads, const size_t *off)
{
    par_batch_init(b, N_UNITS, 8, chunk, unit, j);
    b->offsets = off;
    b->threads = threads;
    b->ws_free = ws_free;
    b->done = done;
}

static void check_values(const unsigned char *out, const size_t *off, int var)
{
    for (size_t i = 0; i < N_UNITS; i++) {
        const size_t nv = var ? i % 5 + 1 : 1, at = off ? off[i] : 8 * i;
        for (size_t k = 0; k < nv; k++) {
            uint64_t v;
            memcpy(&v, out + at + 8 * k, 8);
            if (v != value(i) + k) fail_msg("unit %zu value %zu wrong", i, k);
        }
    }
}

static void test_slots(void **state)
{
    (void)state;
    static const size_t chunks[] = {1, 7, 64, 2000};
    static const int threads[] = {1, 2, 4};
    size_t off[N_UNITS + 1];
    off[0] = 0;
    for (size_t i = 0; i < N_UNITS; i++) off[i + 1] = off[i] + 8 * (i % 5 + 1);
    unsigned char *out = malloc(off[N_UNITS]);
    assert_non_null(out);
    for (int var = 0; var < 2; var++)
        for (size_t c = 0; c < 4; c++)
            for (size_t t = 0; t < 3; t++) {
                struct job *j = fresh(N_UNITS);
                j->var = var;
                struct par_batch b;
                batch(&b, j, chunks[c], threads[t], var ? off : NULL);
                memset(out, 0, off[N_UNITS]);
                char err[256];
                assert_int_equal(par_run(NULL, &b, out, err, sizeof err), PAR_OK);
                check_values(out, var ? off : NULL, var);
                for (size_t i = 0; i < N_UNITS; i++) {
                    assert_int_equal(j->calls[i], 1);
                    assert_int_equal(j->seen[i], 1);
                }
            }
    free(out);
}

static void test_costs(void **state)
{
    (void)state;
    struct job *j = fresh(N_UNITS);
    double cost[N_UNITS];
    for (size_t i = 0; i < N_UNITS; i++) cost[i] = (double)((i * 37) % 101);
    struct par_batch b;
    batch(&b, j, 1, 2, NULL);
    b.cost = cost;
    uint64_t out[N_UNITS];
    char err[256];
    assert_int_equal(par_run(NULL, &b, out, err, sizeof err), PAR_OK);
    check_values((const unsigned char *)out, NULL, 0);
}

static void test_failure(void **state)
{
    (void)state;
    for (int t = 1; t <= 4; t *= 2) {
        struct job *j = fresh(500);
        struct par_batch b;
        batch(&b, j, 3, t, NULL);
        uint64_t out[N_UNITS];
        char err[256];
        assert_int_equal(par_run(NULL, &b, out, err, sizeof err), PAR_E_UNIT);
        assert_int_equal(b.failed_unit, 501); /* the lowest, whatever the threads did first */
        assert_int_equal(b.failed_code, 5 + 501 % 3);
        assert_non_null(strstr(err, "work unit 501 of 1000 failed"));
        for (size_t i = 0; i < N_UNITS; i++) assert_int_equal(j->calls[i], 1); /* the others ran */
    }
    /* a batch without a run function or sizes */
    struct par_batch b;
    memset(&b, 0, sizeof b);
    b.n = 3;
    char err[256];
    assert_int_equal(par_run(NULL, &b, NULL, err, sizeof err), PAR_E_ARG);
}

/* *p a quiet process using the checkpoint at path with job key `key`;
 * par_checkpoint's value */
static int start(struct par *p, const char *path, const char *key, char *err, size_t errlen)
{
    par_init(p, "test_par");
    p->quiet = 1;
    return par_checkpoint(p, path, 0, key, err, errlen);
}

static void tmp_path(char *path, size_t n, const char *name)
{
    const char *dir = getenv("TMPDIR");
    snprintf(path, n, "%.60s/trk_test_par_%ld_%s", dir ? dir : "/tmp", (long)getpid(), name);
    remove(path);
}

static void test_checkpoint_resume(void **state)
{
    (void)state;
    char path[128], err[1600];
    tmp_path(path, sizeof path, "ck");
    uint64_t ref[N_UNITS], out[N_UNITS];
    for (size_t i = 0; i < N_UNITS; i++) ref[i] = value(i);
    /* run 1: batch 0 whole, batch 1 fails from unit 600 on (odd units) */
    struct par p;
    assert_int_equal(start(&p, path, "job A", err, sizeof err), 0);
    struct job *j = fresh(N_UNITS);
    struct par_batch b;
    batch(&b, j, 7, 2, NULL);
    assert_int_equal(par_run(&p, &b, out, err, sizeof err), PAR_OK);
    j = fresh(600);
    batch(&b, j, 7, 2, NULL);
    assert_int_equal(par_run(&p, &b, out, err, sizeof err), PAR_E_UNIT);
    assert_int_equal(par_finish(&p, 0), 0); /* failed: the file stays */
    assert_int_equal(access(path, F_OK), 0);

    /* run 2, same key: batch 0 entirely from the file, batch 1 from unit 600 on */
    assert_int_equal(start(&p, path, "job A", err, sizeof err), 0);
    j = fresh(N_UNITS);
    batch(&b, j, 7, 2, NULL);
    memset(out, 0, sizeof out);
    assert_int_equal(par_run(&p, &b, out, err, sizeof err), PAR_OK);
    assert_memory_equal(out, ref, sizeof out);
    size_t calls = 0, seen = 0;
    for (size_t i = 0; i < N_UNITS; i++) calls += j->calls[i], seen += j->seen[i];
    assert_int_equal(calls, 0);     /* nothing computed again */
    assert_int_equal(seen, N_UNITS); /* but all counted as done */
    j = fresh(N_UNITS);
    batch(&b, j, 7, 2, NULL);
    memset(out, 0, sizeof out);
    assert_int_equal(par_run(&p, &b, out, err, sizeof err), PAR_OK);
    assert_memory_equal(out, ref, sizeof out);
    calls = 0;
    for (size_t i = 0; i < N_UNITS; i++) {
        calls += j->calls[i];
        if (i < 595) assert_int_equal(j->calls[i], 0); /* chunks of 7 wholly done */
    }
    assert_int_equal(calls, N_UNITS - 595); /* the failed chunks: unit 601's and those after it */
    assert_int_equal(p.units_resumed, N_UNITS + 595);
    assert_int_equal(par_finish(&p, 1), 0);
    assert_int_equal(access(path, F_OK), -1); /* removed */
}

/* A checkpoint file of one batch (key "job A") at path; its bytes. */
static unsigned char *write_checkpoint(const char *path, size_t *len)
{
    struct par p;
    char err[1600];
    assert_int_equal(start(&p, path, "job A", err, sizeof err), 0);
    struct job *j = fresh(990);
    struct par_batch b;
    batch(&b, j, 10, 1, NULL);
    uint64_t out[N_UNITS];
    assert_int_equal(par_run(&p, &b, out, err, sizeof err), PAR_E_UNIT);
    assert_int_equal(par_finish(&p, 0), 0);
    unsigned char *bytes = fileio_read(path, len);
    assert_non_null(bytes);
    return bytes;
}

static void test_checkpoint_refused(void **state)
{
    (void)state;
    char path[128], err[1600];
    tmp_path(path, sizeof path, "ck2");
    size_t len;
    unsigned char *bytes = write_checkpoint(path, &len);
    assert_true(len > 990 * 8);
    struct par p;
    /* another job key */
    assert_int_equal(start(&p, path, "job B", err, sizeof err), -1);
    assert_non_null(strstr(err, "belongs to another run (job A)"));
    /* every truncation and a flipped byte: damaged (no crash, no resume) */
    for (size_t n = 0; n < len; n += n < 200 ? 1 : 97) {
        assert_int_equal(fileio_write(path, bytes, n), 0);
        if (start(&p, path, "job A", err, sizeof err) != -1) fail_msg("cut at %zu accepted", n);
        assert_true(strstr(err, "damaged") || strstr(err, "not a checkpoint"));
    }
    bytes[len / 2] ^= 0x10;
    assert_int_equal(fileio_write(path, bytes, len), 0);
    assert_int_equal(start(&p, path, "job A", err, sizeof err), -1);
    assert_non_null(strstr(err, "damaged"));
    bytes[len / 2] ^= 0x10;
    /* the right file, but a batch of another shape */
    assert_int_equal(fileio_write(path, bytes, len), 0);
    assert_int_equal(start(&p, path, "job A", err, sizeof err), 0);
    struct job *j = fresh(N_UNITS);
    struct par_batch b;
    batch(&b, j, 10, 1, NULL);
    b.n = N_UNITS - 1;
    uint64_t out[N_UNITS];
    assert_int_equal(par_run(&p, &b, out, err, sizeof err), PAR_E_CKPT);
    assert_non_null(strstr(err, "does not fit this run"));
    assert_int_equal(par_finish(&p, 0), 0);
    free(bytes);
    remove(path);
}

/* The checkpoint's cost is proportional to the results: with interval 0, a
 * batch of 1000 one-unit chunks on one thread (each chunk a chance to
 * write) writes the file about 8 + ln(1000 / 8) / ln(9 / 8) ~ 49 times, not
 * once per chunk (every write rewrites the whole file: 1000 writes were
 * quadratic); a failed batch's file still holds every finished unit. */
static void test_checkpoint_writes_bounded(void **state)
{
    (void)state;
    char path[128], err[1600];
    tmp_path(path, sizeof path, "ck3");
    struct par p;
    assert_int_equal(start(&p, path, "job C", err, sizeof err), 0);
    struct job *j = fresh(990);
    struct par_batch b;
    batch(&b, j, 1, 1, NULL);
    uint64_t out[N_UNITS];
    assert_int_equal(par_run(&p, &b, out, err, sizeof err), PAR_E_UNIT);
    print_message("checkpoint: %llu writes for %d chunks\n", (unsigned long long)p.ckpt_writes, N_UNITS);
    assert_true(p.ckpt_writes >= 8 && p.ckpt_writes <= 64);
    assert_int_equal(par_finish(&p, 0), 0);
    /* resumed: every unit that finished (all but the failed odd ones >= 990) */
    assert_int_equal(start(&p, path, "job C", err, sizeof err), 0);
    j = fresh(N_UNITS);
    batch(&b, j, 1, 1, NULL);
    memset(out, 0, sizeof out);
    assert_int_equal(par_run(&p, &b, out, err, sizeof err), PAR_OK);
    assert_int_equal(p.units_resumed, 995);
    for (size_t i = 0; i < N_UNITS; i++) assert_true(out[i] == value(i));
    assert_int_equal(par_finish(&p, 1), 0);
    assert_int_equal(access(path, F_OK), -1);
}

/* A rank killed while writing the checkpoint leaves PATH.tmp-XXXXXX (the
 * atomic write's temporary file, fileio.h): the next run with the
 * checkpoint removes it, and nothing else. A checkpoint path that cannot be
 * written is said at once; the run goes on. */
static void test_checkpoint_leftovers(void **state)
{
    (void)state;
    char path[128], tmp[160], other[3][160], err[1600];
    tmp_path(path, sizeof path, "ck4");
    snprintf(tmp, sizeof tmp, "%s.tmp-Ab3xYz", path);
    snprintf(other[0], sizeof other[0], "%s.tmp-keep", path);    /* not mkstemp's 6 characters */
    snprintf(other[1], sizeof other[1], "%s.tmp-ABCDEFG", path); /* 7 */
    snprintf(other[2], sizeof other[2], "%sx.tmp-Ab3xYz", path); /* another file's */
    assert_int_equal(fileio_write(tmp, "cut", 3), 0);
    for (int i = 0; i < 3; i++) assert_int_equal(fileio_write(other[i], "keep", 4), 0);
    struct par p;
    assert_int_equal(start(&p, path, "job D", err, sizeof err), 0);
    assert_int_equal(access(tmp, F_OK), -1);
    for (int i = 0; i < 3; i++) {
        assert_int_equal(access(other[i], F_OK), 0);
        remove(other[i]);
    }
    assert_int_equal(par_finish(&p, 1), 0);
}

static void test_job_key(void **state)
{
    (void)state;
    char *argv[] = {"q2", "--detector", "pdaf", "--threads", "4", "--quiet", "--seed=3", "--threads=2",
                    "--checkpoint", "f", "--out", "t.tbl", NULL};
    static const char *const skip_value[] = {"--threads", "--checkpoint", NULL};
    static const char *const skip_flag[] = {"--quiet", NULL};
    char key[1024];
    assert_int_equal(par_job_key(key, sizeof key, "trk-tablegen q2", 12, argv, skip_value, skip_flag), 0);
    const char *want = "trk-tablegen q2 --detector pdaf --seed=3 --out t.tbl | trk: real ";
    assert_memory_equal(key, want, strlen(want));
    char small[20];
    assert_int_equal(par_job_key(small, sizeof small, "trk-tablegen q2", 12, argv, skip_value, skip_flag), -1);
}

static void test_amp_exec(void **state)
{
    (void)state;
    for (int geo = 0; geo < 2; geo++) {
        struct amp_table_opts o;
        amp_table_opts_init(&o, TRK_AMP_K, 2, 12, 1e-2);
        o.grid = geo ? TRK_AMP_GRID_GEOMETRIC : TRK_AMP_GRID_UNIFORM;
        o.size = o.llr_size = 48;
        struct amp_table_result a, b;
        char err[256];
        assert_int_equal(amp_table_build(&o, &a, err, sizeof err), 0);
        const struct amp_table_exec ex = {par_for_each, NULL};
        o.exec = &ex;
        assert_int_equal(amp_table_build(&o, &b, err, sizeof err), 0);
        assert_int_equal(a.len, b.len);
        assert_memory_equal(a.bytes, b.bytes, a.len);
        free(a.bytes);
        free(b.bytes);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_slots),
        cmocka_unit_test(test_costs),
        cmocka_unit_test(test_failure),
        cmocka_unit_test(test_checkpoint_resume),
        cmocka_unit_test(test_checkpoint_refused),
        cmocka_unit_test(test_checkpoint_writes_bounded),
        cmocka_unit_test(test_checkpoint_leftovers),
        cmocka_unit_test(test_job_key),
        cmocka_unit_test(test_amp_exec),
    };
    return trk_run_tests("par", tests, NULL, NULL);
}

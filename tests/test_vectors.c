/* test_vectors.c - the parser, checker and kind registry that trk-vectors
 * runs the reference vectors with, and proof that the checks can fail: a
 * wrong value, a missing input, an unknown kind and malformed files. The
 * shared vector files themselves run once per configuration, through the
 * trk-vectors program (`make check`, step "vectors"). */
#include "trk_test.h"
#include "trk/types.h"
#include "vec.h"

static struct vec_case cs;
static struct vec_out out;

struct tally {
    long passed, failed, unimpl, not_applicable;
};

/* Run every case of a text; returns -1 on a malformed text. */
static int run_text(const char *text, size_t len, struct tally *t, int verbose)
{
    struct vec_file f;
    vec_file_init(&f, text, len);
    int r;
    while ((r = vec_next(&f, &cs)) == 1) {
        const struct vec_kind *k = vec_kind_find(cs.kind);
        if (!k) {
            t->unimpl++;
            continue;
        }
        vec_out_reset(&out);
        int rc = k->fn(&cs, &out);
        if (rc == VEC_NOT_APPLICABLE) {
            t->not_applicable++;
            continue;
        }
        if (rc != 0) {
            if (verbose) print_message("FAIL %s: %s\n", cs.id, out.err);
            t->failed++;
            continue;
        }
        struct vec_check chk;
        vec_compare(&f, &cs, &out, TRK_REAL_IS_FLOAT, k->float_abs, k->float_rel, &chk);
        if (chk.ok) t->passed++;
        else {
            if (verbose) print_message("FAIL %s %s\n", cs.id, chk.first_fail);
            t->failed++;
        }
    }
    return r < 0 ? -1 : 0;
}

/* Read every case of text into *f: vec_next's last value (0 end, -1 malformed). */
static int read_all(const char *text, struct vec_file *f)
{
    vec_file_init(f, text, strlen(text));
    int r;
    while ((r = vec_next(f, &cs)) == 1) {
    }
    return r;
}

/* The kind registry: every kind has a name, a function and a speed; the Monte
 * Carlo q2 kinds are the slow ones (`trk-vectors --skip-slow`, `make check`),
 * the fast ones include the library's kernels. */
static void test_registry_speed(void **state)
{
    (void)state;
    size_t n;
    const struct vec_kind *k = vec_kinds(&n);
    assert_true(n >= 10);
    size_t slow = 0;
    for (size_t i = 0; i < n; i++) {
        assert_non_null(k[i].name);
        assert_non_null(k[i].fn);
        assert_true(k[i].speed == VEC_FAST || k[i].speed == VEC_SLOW);
        slow += k[i].speed == VEC_SLOW;
    }
    assert_int_equal(slow, 2);
    assert_int_equal(vec_kind_find("q2_pdaf")->speed, VEC_SLOW);
    assert_int_equal(vec_kind_find("q2_pdafai")->speed, VEC_SLOW);
    assert_int_equal(vec_kind_find("pda_update")->speed, VEC_FAST);
    assert_int_equal(vec_kind_find("mre_steady")->speed, VEC_FAST);
}

static const char good_case[] =
    "# a kn case\n"
    "tol * 0 0\n"
    "case kn k1\n"
    "in k 0\n"
    "in n 2\n"
    "in delta 1 0 0 1\n"
    "out count 1 1 0 1\n"
    "out decision 0 0 1 1\n"
    "end\n";

static void test_checks_can_fail(void **state)
{
    (void)state;
    struct tally t = {0, 0, 0, 0};
    assert_int_equal(run_text(good_case, strlen(good_case), &t, 0), 0);
    assert_int_equal(t.passed, 1);
    assert_int_equal(t.failed, 0);
    /* a wrong expected value fails */
    char bad[sizeof good_case];
    memcpy(bad, good_case, sizeof good_case);
    char *p = strstr(bad, "out count 1 1 0 1");
    p[16] = '2';
    memset(&t, 0, sizeof t);
    assert_int_equal(run_text(bad, strlen(bad), &t, 0), 0);
    assert_int_equal(t.failed, 1);
    assert_int_equal(t.passed, 0);
    /* a missing input fails (not skipped) */
    memcpy(bad, good_case, sizeof good_case);
    p = strstr(bad, "in k 0");
    memcpy(p, "in q 0", 6);
    memset(&t, 0, sizeof t);
    assert_int_equal(run_text(bad, strlen(bad), &t, 0), 0);
    assert_int_equal(t.failed, 1);
    /* an output the kind does not compute fails */
    static const char extra[] = "case kn k2\nin k 0\nin n 1\nin delta 1\nout nonsense 1\nend\n";
    memset(&t, 0, sizeof t);
    assert_int_equal(run_text(extra, strlen(extra), &t, 0), 0);
    assert_int_equal(t.failed, 1);
    /* an unknown kind is counted as unimplemented */
    static const char unk[] = "case no_such_kind x\nin a 1\nout b 2\nend\n";
    memset(&t, 0, sizeof t);
    assert_int_equal(run_text(unk, strlen(unk), &t, 0), 0);
    assert_int_equal(t.unimpl, 1);
}

static void test_tolerance_rules(void **state)
{
    (void)state;
    /* file-level defaults, case overrides, per-name before '*' */
    static const char text[] = "tol * 1 2\ntol x 3 4\ncase kn a\ntol * 5 6\nin k 0\nin n 1\nin delta 1\nend\n"
                               "case kn b\nin k 0\nin n 1\nin delta 1\nend\n";
    struct vec_file f;
    vec_file_init(&f, text, strlen(text));
    double a, r;
    assert_int_equal(vec_next(&f, &cs), 1);
    vec_tolerance(&f, &cs, "x", &a, &r);
    assert_true(a == 5 && r == 6); /* case '*' beats file's named entry */
    assert_int_equal(vec_next(&f, &cs), 1);
    vec_tolerance(&f, &cs, "x", &a, &r);
    assert_true(a == 3 && r == 4);
    vec_tolerance(&f, &cs, "y", &a, &r);
    assert_true(a == 1 && r == 2);
    assert_int_equal(vec_next(&f, &cs), 0);
}

static void test_malformed(void **state)
{
    (void)state;
    static const char *bad[] = {
        "case kn\nend\n",                   /* no id */
        "case kn a\nin k 0\n",              /* no end */
        "in k 0\n",                         /* outside a case */
        "case kn a\nin k 1 x\nend\n",       /* word after numbers */
        "case kn a\nin k inf\nend\n",       /* non-finite */
        "case kn a\nbogus 1\nend\n",        /* unknown record */
        "case kn a\ntol x 1\nend\n",        /* short tol */
        "case kn a\ntol x -1 0\nend\n",     /* negative tol */
        "end\n",
        "case kn a\ncase kn b\nend\n",
        "case kn aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa\nend\n",
        "case kn a\nin nnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnn 1\nend\n",
        "case kn a\nin k 0x0\nin n 2\nin delta 1 0\nend\n", /* hex numbers */
        "case kn a\nin k 0\nin n 2\nin delta 1 0x1p0\nend\n",
        "case kn a\nin k 0\nin n 2\nin delta -0X1\nend\n",
        "case kn a\ntol count 0x0 0\nend\n",
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        struct vec_file f;
        if (read_all(bad[i], &f) != -1) fail_msg("malformed text %zu accepted", i);
        assert_true(f.err[0] != '\0');
    }
    /* an array longer than 1024 values */
    static char big[1100 * 2 + 64];
    strcpy(big, "case kn a\nin delta");
    for (int i = 0; i < 1025; i++) strcat(big, " 1");
    strcat(big, "\nend\n");
    struct vec_file f;
    vec_file_init(&f, big, strlen(big));
    assert_int_equal(vec_next(&f, &cs), -1);
    /* an embedded NUL */
    static const char nul[] = "case kn a\nin k 0\0\nend\n";
    vec_file_init(&f, nul, sizeof nul - 1);
    assert_int_equal(vec_next(&f, &cs), -1);
}

/* Hostile input: a name given twice, hex numbers refused (a
 * subnormal accepted); the K-distribution direct evaluation outside its range
 * (clutter power 1e-300, a/sqrt(P) = 1e50 or 1e100, x = 1e300) fails with a
 * message instead of returning 0 or NaN or hanging. */
static void test_hostile_input(void **state)
{
    (void)state;
    struct vec_file f;
    assert_int_equal(read_all("case kn a\nin k 0\nin k 1\nin n 2\nin delta 1 0\nend\n", &f), -1);
    assert_non_null(strstr(f.err, "duplicate in name"));
    assert_int_equal(read_all("case kn a\nin k 0\nin n 2\nin delta 1 0\nout count 1 1\nout count 1 1\nend\n", &f),
                     -1);
    assert_non_null(strstr(f.err, "duplicate out name"));
    /* hex numbers: in test_malformed */
    static const char sub[] = "case kn a\nin k 4.9e-324\nend\n";
    vec_file_init(&f, sub, strlen(sub));
    assert_int_equal(vec_next(&f, &cs), 1);
    assert_true(cs.pool[0] > 0 && cs.pool[0] < 1e-323);

    static const char *const far[] = {
        "case amp_loglr a\nin model k\nin nu 1\nin clutter_power 1e-300\nin snr_db 15\nin pfa 1e-3\n"
        "in a 1\nout log_lr 0\nend\n",
        "case amp_loglr b\nin model k\nin nu 1\nin clutter_power 1\nin snr_db 15\nin pfa 1e-3\n"
        "in a 1e50\nout log_lr 0\nend\n",
        "case amp_loglr c\nin model k\nin nu 1\nin clutter_power 1\nin snr_db 15\nin pfa 1e-3\n"
        "in a 1e100\nout log_lr 0\nend\n",
        "case amp_inv_sf d\nin model k\nin nu 1\nin clutter_power 1\nin snr_db 15\nin pfa 1e-3\n"
        "in which 0\nin x 1e300\nout a 0\nend\n",
    };
    for (size_t i = 0; i < sizeof far / sizeof far[0]; i++) {
        struct tally t = {0, 0, 0, 0};
        assert_int_equal(run_text(far[i], strlen(far[i]), &t, 0), 0);
        if (t.failed != 1) fail_msg("far case %zu: %ld failed, %ld passed", i, t.failed, t.passed);
        if (!strstr(out.err, "failed")) fail_msg("far case %zu: '%s'", i, out.err);
    }
    /* inside the range the direct value stands: at a/sqrt(P) = 1e4 and 1e8 ln l^a is at its
     * limit (1/a convergence; the quadrature's rounding grows with a) */
    static const char near_limit[] = "case amp_loglr e\nin model k\nin nu 1\nin clutter_power 1\nin snr_db 15\n"
                                     "in pfa 1e-3\nin a 1e4 1e8\nend\n";
    vec_file_init(&f, near_limit, strlen(near_limit));
    assert_int_equal(vec_next(&f, &cs), 1);
    vec_out_reset(&out);
    assert_int_equal(vec_kind_find("amp_loglr")->fn(&cs, &out), 0);
    const struct vec_entry *lr = vec_out_find(&out, "log_lr");
    assert_non_null(lr);
    assert_int_equal(lr->n, 2);
    TRK_ASSERT_NEAR(out.pool[lr->off + 1], out.pool[lr->off], 1e-7, 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_registry_speed),
        cmocka_unit_test(test_checks_can_fail),
        cmocka_unit_test(test_tolerance_rules),
        cmocka_unit_test(test_malformed),
        cmocka_unit_test(test_hostile_input),
    };
    return trk_run_tests("vectors", tests, NULL, NULL);
}

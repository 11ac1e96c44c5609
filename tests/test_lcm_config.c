/* test_lcm_config.c - the tools' tracker configuration (tools/cli/
 * tracker_config.c) and "key = value" files (kvfile.c): defaults are the
 * library's, every key sets its field, bad values and unknown keys are
 * refused with the key (and file:line) in the message, a misspelled key with
 * the nearest known one, the printed
 * configuration reads back to the same, and tcfg_check refuses bad
 * combinations, bad tables and methods the tracker does not run yet. */
#define _POSIX_C_SOURCE 200809L /* getpid */
#include <unistd.h>

#include "trk_test.h"

#include "kvfile.h"
#include "tracker_config.h"

static struct tcfg c, c2;
static char err[1024];

static int set(const char *k, const char *v) { return tcfg_set(&c, k, v, err, sizeof err); }

/* A setter that fails unless the key is one of tcfg_keys() or a sensor's. */
static int listed_key(void *ctx, const char *key, const char *value, char *e, size_t n)
{
    (void)ctx, (void)value, (void)n, (void)e;
    for (const char *const *k = tcfg_keys(); *k; k++)
        if (strcmp(key, *k) == 0) return 0;
    for (const char *const *k = tcfg_sensor_keys(); *k; k++) {
        char full[64];
        for (int s = 0; s < TRK_MAX_SENSORS; s++) {
            snprintf(full, sizeof full, "sensor.%d.%s", s, *k);
            if (strcmp(key, full) == 0) return 0;
        }
    }
    fail_msg("tcfg_write wrote the key '%s', not in tcfg_keys()", key);
    return 1;
}

/* The key list of the suggestions is the keys tcfg_set takes: each listed
 * key is known to it (a value may be refused), and every key tcfg_write
 * writes is listed. */
static void test_key_list(void **state)
{
    (void)state;
    for (const char *const *k = tcfg_keys(); *k; k++) {
        tcfg_defaults(&c);
        assert_int_not_equal(set(*k, "1"), 1);
    }
    for (const char *const *k = tcfg_sensor_keys(); *k; k++) {
        char full[64];
        snprintf(full, sizeof full, "sensor.0.%s", *k);
        tcfg_defaults(&c);
        assert_int_not_equal(set(full, "1"), 1);
    }
    tcfg_defaults(&c);
    c.params.n_sensors = TRK_MAX_SENSORS;
    snprintf(c.q2_table, sizeof c.q2_table, "q2.tbl");
    snprintf(c.amp[0].table, sizeof c.amp[0].table, "amp.tbl");
    char buf[16384];
    FILE *f = fmemopen(buf, sizeof buf, "w+");
    assert_non_null(f);
    tcfg_write(f, &c);
    rewind(f);
    int none = 0;
    assert_int_equal(kv_parse_stream(f, "written", listed_key, &none, err, sizeof err), 0);
    fclose(f);
    /* an unknown key: the nearest listed one in err, or "" */
    tcfg_defaults(&c);
    assert_int_equal(set("confirm.mn.mm", "3"), 1);
    assert_string_equal(err, "confirm.mn.m");
    assert_int_equal(set("zzz", "3"), 1);
    assert_string_equal(err, "");
}

/* A temporary file with the given contents; returns its path (static). */
static const char *tmp_file(const char *name, const char *text, size_t len)
{
    static char path[256];
    const char *dir = getenv("TMPDIR");
    snprintf(path, sizeof path, "%s/trk_test_lcm_config_%ld_%s", dir ? dir : "/tmp", (long)getpid(),
             name);
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    assert_int_equal(fwrite(text, 1, len, f), len);
    fclose(f);
    return path;
}

/* A config file of text that kv_parse_file refuses, with want in the message (err). */
static void file_refused(const char *name, const char *text, const char *want)
{
    const char *path = tmp_file(name, text, strlen(text));
    assert_int_equal(kv_parse_file(path, tcfg_set, &c, err, sizeof err), -1);
    if (!strstr(err, want)) fail_msg("%s: '%s', want '%s'", name, err, want);
    remove(path);
}

static void test_defaults(void **state)
{
    (void)state;
    struct trk_tracker_params d;
    trk_tracker_default_params(&d);
    tcfg_defaults(&c);
    static struct trk_tracker_params pp;
    tcfg_params(&c, &pp);
    const struct trk_tracker_params *p = &pp;
    assert_int_equal(p->n_sensors, d.n_sensors);
    assert_true(p->process_noise_q == d.process_noise_q && p->gate_prob == d.gate_prob);
    assert_true(p->max_dt_s == d.max_dt_s && p->init_speed_sigma_mps == d.init_speed_sigma_mps);
    assert_int_equal(p->confirm.method, TRK_CONFIRM_EXISTENCE);
    assert_true(p->confirm.u.existence.p_confirm == d.confirm.u.existence.p_confirm);
    assert_true(p->confirm.u.existence.reject_odds_ratio == d.confirm.u.existence.reject_odds_ratio);
    assert_true(p->confirm.u.existence.count_alpha == d.confirm.u.existence.count_alpha);
    assert_true(p->clutter_map.edge_alpha == d.clutter_map.edge_alpha);
    assert_int_equal(p->term.method, TRK_TERM_EXISTENCE);
    assert_true(p->term.u.existence.p_terminate == d.term.u.existence.p_terminate);
    assert_int_equal(p->init.method, d.init.method);
    assert_true(p->init.birth_density_per_m2 == d.init.birth_density_per_m2);
    assert_true(p->max_pos_sigma_ratio == d.max_pos_sigma_ratio);
    for (unsigned s = 0; s < TRK_MAX_SENSORS; s++) { /* every sensor like sensor 0 */
        assert_true(p->sensor[s].pd == d.sensor[0].pd);
        assert_true(p->sensor[s].meas_cov_m2[0] == d.sensor[0].meas_cov_m2[0]);
    }
    assert_int_equal(tcfg_check(&c, err, sizeof err), 0);
}

static void test_set_keys(void **state)
{
    (void)state;
    tcfg_defaults(&c);
    assert_int_equal(set("process_noise_q", "0.25"), 0);
    assert_int_equal(set("gate_prob", " 0.995 "), 0);
    assert_int_equal(set("clutter", "nonparametric"), 0);
    assert_int_equal(set("init_speed_sigma_mps", "7"), 0);
    assert_int_equal(set("max_dt_s", "60"), 0);
    assert_int_equal(set("max_tentative_scans", "12"), 0);
    assert_int_equal(set("confirm", "mn"), 0);
    assert_int_equal(set("term", "kn"), 0);
    assert_int_equal(set("init.method", "single_point"), 0);
    assert_int_equal(set("init.max_speed_mps", "12.5"), 0);
    assert_int_equal(set("init.max_gap_scans", "3"), 0);
    assert_int_equal(set("init.birth_density_per_m2", "2e-9"), 0);
    assert_int_equal(set("max_pos_sigma_ratio", "8"), 0);
    assert_int_equal(set("confirm.mn.m", "4"), 0);
    assert_int_equal(set("confirm.mn.n", "6"), 0);
    assert_int_equal(set("confirm.mn.mode", "sliding"), 0);
    assert_int_equal(set("term.kn.k", "1"), 0);
    assert_int_equal(set("term.kn.n", "8"), 0);
    assert_int_equal(set("sensor.0.pd", "0.8"), 0);
    assert_int_equal(set("sensor.0.meas_cov_m2", "4, 1, 9"), 0);
    assert_int_equal(set("sensor.0.clutter_density_per_m2", "2e-6"), 0);
    static struct trk_tracker_params pp;
    tcfg_params(&c, &pp);
    const struct trk_tracker_params *p = &pp;
    assert_true(p->process_noise_q == TRK_REAL_C(0.25));
    assert_true(p->gate_prob == TRK_REAL_C(0.995));
    assert_int_equal(p->clutter, TRK_CLUTTER_NONPARAMETRIC);
    assert_true(p->init_speed_sigma_mps == 7 && p->max_dt_s == 60);
    assert_int_equal(p->max_tentative_scans, 12);
    assert_int_equal(p->init.method, TRK_INIT_SINGLE_POINT);
    assert_true(p->init.max_speed_mps == TRK_REAL_C(12.5) && p->init.max_gap_scans == 3);
    assert_true(p->init.birth_density_per_m2 == TRK_REAL_C(2e-9) && p->max_pos_sigma_ratio == 8);
    assert_int_equal(p->confirm.u.mn.m, 4);
    assert_int_equal(p->confirm.u.mn.n, 6);
    assert_int_equal(p->confirm.u.mn.mode, TRK_MN_SLIDING);
    assert_int_equal(p->term.u.kn.k, 1);
    assert_int_equal(p->term.u.kn.n, 8);
    assert_true(p->sensor[0].pd == TRK_REAL_C(0.8));
    assert_true(p->sensor[0].meas_cov_m2[0] == 4 && p->sensor[0].meas_cov_m2[1] == 1 &&
                p->sensor[0].meas_cov_m2[2] == 9);
    assert_true(p->sensor[0].clutter_density_per_m2 == TRK_REAL_C(2e-6));
    assert_int_equal(set("sensor.0.meas_sigma_m", "3"), 0);
    tcfg_params(&c, &pp);
    assert_true(p->sensor[0].meas_cov_m2[0] == 9 && p->sensor[0].meas_cov_m2[1] == 0 &&
                p->sensor[0].meas_cov_m2[2] == 9);
    /* the default joint association needs parametric clutter: refused,
     * naming the field, until the per-track PDA is chosen */
    assert_int_equal(tcfg_check(&c, err, sizeof err), -1);
    assert_non_null(strstr(err, "association"));
    assert_int_equal(set("association", "pda"), 0);
    tcfg_params(&c, &pp);
    assert_int_equal(p->association, TRK_ASSOC_PDA);
    assert_int_equal(tcfg_check(&c, err, sizeof err), 0);
    /* pending methods' parameters are parsed into their module structs */
    assert_int_equal(set("confirm.sprt.alpha", "0.05"), 0);
    assert_int_equal(set("confirm.sprt.model", "hmm"), 0);
    assert_int_equal(set("term.page.h", "6.5"), 0);
    assert_int_equal(set("term.shiryaev.rho", "0"), 0);
    assert_int_equal(set("hmm.pi0_high", "stationary"), 0);
    assert_int_equal(set("hmm.pd_high", "0.95"), 0);
    assert_int_equal(c.hmm_events, TRK_EVENTS_COMPLETE); /* the default */
    assert_int_equal(set("hmm.events", "paper"), 0);
    assert_int_equal(set("confirm.clutter_density.kmax", "10"), 0);
    assert_true(c.sprt.alpha == TRK_REAL_C(0.05) && c.sprt.model == TRK_SPRT_HMM);
    assert_true(c.page.h == TRK_REAL_C(6.5) && c.shiryaev.rho == 0);
    assert_true(c.hmm.pi0_high == TRK_HMM_PI0_STATIONARY && c.hmm.pd_high == TRK_REAL_C(0.95));
    assert_int_equal(c.clutter_density.kmax, 10);
    /* hmm.events reaches every test that uses it (fixed-P_D SPRT included) */
    assert_int_equal(c.hmm_events, TRK_EVENTS_PAPER);
    const enum trk_term_method terms[2] = {TRK_TERM_PAGE, TRK_TERM_SHIRYAEV};
    for (int k = 0; k < 2; k++) {
        c.confirm = TRK_CONFIRM_SPRT;
        c.term = terms[k];
        tcfg_params(&c, &pp);
        assert_int_equal(pp.confirm.u.sprt.hmm.events, TRK_EVENTS_PAPER);
        assert_int_equal(k ? pp.term.u.shiryaev.hmm.events : pp.term.u.page.hmm.events,
                         TRK_EVENTS_PAPER);
    }
    assert_int_equal(set("hmm.events", "complete"), 0);
    tcfg_params(&c, &pp);
    assert_int_equal(pp.confirm.u.sprt.hmm.events, TRK_EVENTS_COMPLETE);
    assert_int_equal(pp.term.u.shiryaev.hmm.events, TRK_EVENTS_COMPLETE);
}

static void test_bad_values(void **state)
{
    (void)state;
    tcfg_defaults(&c);
    static const char *const bad[][2] = {
        {"gate_prob", "1"},          {"gate_prob", "0"},         {"gate_prob", "nan"},
        {"gate_prob", "0.9x"},       {"gate_prob", ""},          {"process_noise_q", "-1"},
        {"process_noise_q", "inf"},  {"sensors", "0"},           {"sensors", "99"},
        {"clutter", "maybe"},        {"max_dt_s", "0"},          {"max_dt_s", "2e9"},
        {"confirm", "voting"},       {"confirm.mn.m", "0"},      {"confirm.mn.n", "65"},
        {"confirm.mn.m", "2.5"},     {"term.kn.k", "-1"},        {"sensor.0.pd", "0"},
        {"sensor.0.pd", "1.01"},     {"sensor.0.meas_cov_m2", "1, 2, 1"},
        {"sensor.0.meas_cov_m2", "1, 0"},                        {"sensor.0.meas_cov_m2", "1,0,1,5"},
        {"sensor.0.meas_sigma_m", "0"},                          {"sensor.0.amplitude", "weibull"},
        {"sensor.0.pfa", "1"},       {"sensor.0.snr_db", "200"}, {"sensor.99.pd", "0.5"},
        {"hmm.pi0_high", "2"},       {"term.shiryaev.rho", "1"}, {"confirm.sprt.alpha", "0"},
        {"hmm.events", "blanding"},  {"hmm.events", ""},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        err[0] = 0;
        if (set(bad[i][0], bad[i][1]) != -1)
            fail_msg("%s = '%s' accepted", bad[i][0], bad[i][1]);
        assert_true(strlen(err) > 0);
    }
    /* nothing changed */
    tcfg_defaults(&c2);
    assert_true(c.params.gate_prob == c2.params.gate_prob && c.params.sensor[0].pd == c2.params.sensor[0].pd);
    /* unknown keys */
    assert_int_equal(set("gate_probability", "0.9"), 1);
    assert_int_equal(set("sensor.0.colour", "red"), 1);
    assert_int_equal(set("sensor.x.pd", "0.5"), 1);
    assert_int_equal(set("sensorX", "1"), 1);
}

static void test_file(void **state)
{
    (void)state;
    const char text[] = "# a tracker\n"
                        "\n"
                        "   gate_prob = 0.97   # P_G\n"
                        "sensor.0.pd=0.7\n"
                        "confirm.mn.m = 2\r\n"
                        "confirm.mn.m = 3\n";
    const char *path = tmp_file("ok.conf", text, sizeof text - 1);
    tcfg_defaults(&c);
    assert_int_equal(kv_parse_file(path, tcfg_set, &c, err, sizeof err), 0);
    assert_true(c.params.gate_prob == TRK_REAL_C(0.97));
    assert_true(c.params.sensor[0].pd == TRK_REAL_C(0.7));
    assert_int_equal(c.mn.m, 3); /* the last one wins */
    remove(path);

    file_refused("bad1.conf", "gate_prob = 0.9\n\nnot a setting\n", ":3: expected 'key = value'");
    file_refused("bad2.conf", "gate_prob = 0.9\ngate_prob = 2\n", ":2: gate_prob = 2: must be in (0, 1)");
    file_refused("bad3.conf", "colour = red\n", ":1: unknown setting 'colour'");
    assert_null(strstr(err, "did you mean"));
    file_refused("bad4.conf", "# tracker\nsensors = 1\nprocess_noise_qq = 0.1\n",
                 ":3: unknown setting 'process_noise_qq'; did you mean 'process_noise_q'?");

    static char longline[KV_MAX_LINE + 10];
    memset(longline, 'a', sizeof longline - 2);
    longline[sizeof longline - 2] = '\n';
    path = tmp_file("long.conf", longline, sizeof longline - 1);
    assert_int_equal(kv_parse_file(path, tcfg_set, &c, err, sizeof err), -1);
    assert_non_null(strstr(err, "longer than"));
    remove(path);

    assert_int_equal(kv_parse_file("/nonexistent/trk.conf", tcfg_set, &c, err, sizeof err), -1);
    assert_non_null(strstr(err, "cannot open"));

    /* a NUL byte hid the rest of its line (and
     * /dev/zero, all NULs, never returned); a comment of 1 020 bytes with a
     * setting after it, NUL-padded so that the old line test missed it */
    const char nul[] = "gate_prob = 0.9\0 trailing text\nsensor.0.pd = 0.8\n";
    path = tmp_file("nul.conf", nul, sizeof nul - 1);
    assert_int_equal(kv_parse_file(path, tcfg_set, &c, err, sizeof err), -1);
    assert_non_null(strstr(err, ":1: a NUL byte"));
    remove(path);
    static char crafted[2 * KV_MAX_LINE];
    memset(crafted, 0, sizeof crafted);
    crafted[0] = '#';
    memset(crafted + 1, 'x', 1018);
    memcpy(crafted + 1020, "gate_prob = 0.5\n", 16); /* after a NUL at 1019: the hidden setting */
    path = tmp_file("crafted.conf", crafted, 1036);
    tcfg_defaults(&c);
    assert_int_equal(kv_parse_file(path, tcfg_set, &c, err, sizeof err), -1);
    assert_true(c.params.gate_prob != TRK_REAL_C(0.5));
    remove(path);
    FILE *zero = fopen("/dev/zero", "r");
    if (zero) {
        fclose(zero);
        assert_int_equal(kv_parse_file("/dev/zero", tcfg_set, &c, err, sizeof err), -1);
        assert_non_null(strstr(err, "NUL"));
    }

    /* command-line form */
    assert_int_equal(kv_parse_assignment("term.kn.n = 9", tcfg_set, &c, err, sizeof err), 0);
    assert_int_equal(c.kn.n, 9);
    assert_int_equal(kv_parse_assignment("term.kn.n", tcfg_set, &c, err, sizeof err), -1);
    assert_int_equal(kv_parse_assignment("=3", tcfg_set, &c, err, sizeof err), -1);
}

static void test_number_parsers(void **state)
{
    (void)state;
    double v[3];
    long l;
    assert_int_equal(kv_parse_doubles("1, 2 ,3", v, 3), 0);
    assert_true(v[0] == 1 && v[1] == 2 && v[2] == 3);
    assert_int_equal(kv_parse_doubles("1 2 3", v, 3), 0);
    assert_int_equal(kv_parse_doubles("1,2", v, 3), -1);
    assert_int_equal(kv_parse_doubles("1,2,3,4", v, 3), -1);
    assert_int_equal(kv_parse_doubles("1,nan,3", v, 3), -1);
    assert_int_equal(kv_parse_doubles("1,,3", v, 3), -1);
    assert_int_equal(kv_parse_doubles(",1,2,3", v, 3), -1);
    assert_int_equal(kv_parse_doubles("1,2,3,", v, 3), -1);
    assert_int_equal(kv_parse_doubles("-1e3,+2,.5", v, 3), 0);
    assert_true(v[0] == -1e3 && v[1] == 2 && v[2] == 0.5);
    assert_int_equal(kv_parse_double("1e400", v), -1);
    assert_int_equal(kv_parse_long("12", 0, 20, &l), 0);
    assert_int_equal(l, 12);
    assert_int_equal(kv_parse_long("21", 0, 20, &l), -1);
    assert_int_equal(kv_parse_long("1.5", 0, 20, &l), -1);
}

/* tcfg_write output read back gives the same configuration (same output). */
static void test_write_read_back(void **state)
{
    (void)state;
    tcfg_defaults(&c);
    assert_int_equal(set("gate_prob", "0.987654321"), 0);
    assert_int_equal(set("sensor.0.meas_cov_m2", "2.5, -0.1, 3.3"), 0);
    assert_int_equal(set("term.shiryaev.h", "-3.25"), 0);
    assert_int_equal(set("hmm.pi0_high", "0.4"), 0);
    assert_int_equal(set("hmm.events", "paper"), 0);
    assert_int_equal(set("confirm", "sprt"), 0);
    if (TRK_MAX_SENSORS >= 2) {
        assert_int_equal(set("sensors", "2"), 0);
        assert_int_equal(set("sensor.1.pd", "0.55"), 0);
    }
    static char buf1[16384], buf2[16384];
    FILE *f = tmpfile();
    assert_non_null(f);
    tcfg_write(f, &c);
    rewind(f);
    size_t n1 = fread(buf1, 1, sizeof buf1 - 1, f);
    fclose(f);
    buf1[n1] = 0;
    const char *path = tmp_file("rt.conf", buf1, n1);
    tcfg_defaults(&c2);
    assert_int_equal(kv_parse_file(path, tcfg_set, &c2, err, sizeof err), 0);
    remove(path);
    f = tmpfile();
    tcfg_write(f, &c2);
    rewind(f);
    size_t n2 = fread(buf2, 1, sizeof buf2 - 1, f);
    fclose(f);
    buf2[n2] = 0;
    assert_string_equal(buf1, buf2);
    assert_true(c2.params.gate_prob == c.params.gate_prob);
    assert_true(c2.params.sensor[0].meas_cov_m2[1] == c.params.sensor[0].meas_cov_m2[1]);
    assert_int_equal(c2.confirm, TRK_CONFIRM_SPRT);
    assert_int_equal(c2.hmm_events, TRK_EVENTS_PAPER);
}

static void expect_check_fails(const char *want)
{
    err[0] = 0;
    assert_int_equal(tcfg_check(&c, err, sizeof err), -1);
    if (!strstr(err, want)) fail_msg("message '%s' lacks '%s'", err, want);
}

/* A value of key refused (-1) with want in the message. */
static void refused(const char *k, const char *v, const char *want)
{
    err[0] = 0;
    assert_int_equal(set(k, v), -1);
    if (!strstr(err, want)) fail_msg("%s = %s: '%s', want '%s'", k, v, err, want);
}

/* A polar sensor, its pose, P_D profile and coverage: each key sets its
 * field, refuses what the tracker refuses, a misspelling names the key,
 * the written configuration reads back the same, tcfg_check refuses what
 * two keys say together. */
static void test_polar_keys(void **state)
{
    (void)state;
    tcfg_defaults(&c);
    const struct trk_sensor_params *sp = &c.params.sensor[0];
    /* the tools' defaults: Cartesian, a valid noise for a polar sensor */
    assert_int_equal(sp->kind, TRK_SENSOR_CARTESIAN);
    assert_true(sp->sigma_range_m == 1 && sp->sigma_bearing_rad == TRK_REAL_C(0.01));
    assert_int_equal(sp->conversion, TRK_POLAR_FIRST_ORDER);
    assert_int_equal(sp->pd_profile.n, 0);
    assert_true(sp->coverage.max_range_m == 0 && sp->coverage.half_width_rad == 0);
    assert_int_equal(set("sensor.0.kind", "polar"), 0);
    assert_int_equal(sp->kind, TRK_SENSOR_POLAR);
    assert_int_equal(set("sensor.0.sigma_range_m", "2.5"), 0);
    assert_true(sp->sigma_range_m == TRK_REAL_C(2.5));
    assert_int_equal(set("sensor.0.sigma_bearing_rad", "0.5"), 0); /* the limit itself */
    assert_true(sp->sigma_bearing_rad == TRK_REAL_C(0.5));
    assert_int_equal(set("sensor.0.conversion", "unbiased"), 0);
    assert_int_equal(sp->conversion, TRK_POLAR_UNBIASED);
    assert_int_equal(set("sensor.0.pose.x_m", "-1200.5"), 0);
    assert_int_equal(set("sensor.0.pose.y_m", "300"), 0);
    assert_int_equal(set("sensor.0.pose.heading_rad", "-1.25"), 0);
    assert_true(sp->pose.x_m == TRK_REAL_C(-1200.5) && sp->pose.y_m == 300 && sp->pose.heading_rad == TRK_REAL_C(-1.25));
    /* values a float build holds exactly: the written text is the same in both */
    assert_int_equal(set("sensor.0.pd_profile", " 0:0.75, 1000 : 0.5,2500:0.125 "), 0);
    assert_int_equal(sp->pd_profile.n, 3);
    assert_true(sp->pd_profile.range_m[0] == 0 && sp->pd_profile.pd[0] == TRK_REAL_C(0.75));
    assert_true(sp->pd_profile.range_m[1] == 1000 && sp->pd_profile.pd[1] == TRK_REAL_C(0.5));
    assert_true(sp->pd_profile.range_m[2] == 2500 && sp->pd_profile.pd[2] == TRK_REAL_C(0.125));
    assert_int_equal(set("sensor.0.clutter_profile", "500:1e-6, 8000:2e-8"), 0);
    assert_true(sp->clutter_profile.n == 2 && sp->clutter_profile.range_m[1] == 8000 &&
                sp->clutter_profile.density_per_m2[0] == TRK_REAL_C(1e-6));
    assert_int_equal(set("sensor.0.coverage.min_range_m", "20"), 0);
    assert_int_equal(set("sensor.0.coverage.max_range_m", "3000"), 0);
    assert_int_equal(set("sensor.0.coverage.half_width_rad", "1.5"), 0);
    assert_true(sp->coverage.min_range_m == 20 && sp->coverage.max_range_m == 3000 &&
                sp->coverage.half_width_rad == TRK_REAL_C(1.5));
    assert_int_equal(tcfg_check(&c, err, sizeof err), 0);
    /* the tracker's parameters carry them */
    static struct trk_tracker_params pp;
    tcfg_params(&c, &pp);
    assert_int_equal(pp.sensor[0].kind, TRK_SENSOR_POLAR);
    assert_int_equal(pp.sensor[0].pd_profile.n, 3);
    assert_true(pp.sensor[0].pose.heading_rad == TRK_REAL_C(-1.25));
    /* written and read back: the same text */
    static char buf1[16384], buf2[16384];
    FILE *f = tmpfile();
    assert_non_null(f);
    tcfg_write(f, &c);
    rewind(f);
    const size_t n1 = fread(buf1, 1, sizeof buf1 - 1, f);
    fclose(f);
    buf1[n1] = 0;
    assert_non_null(strstr(buf1, "sensor.0.pd_profile = 0:0.75, 1000:0.5, 2500:0.125\n"));
    assert_non_null(strstr(buf1, "sensor.0.clutter_profile = 500:")); /* the values read back: below */
    assert_non_null(strstr(buf1, "sensor.0.kind = polar\n"));
    assert_non_null(strstr(buf1, "sensor.0.conversion = unbiased\n"));
    assert_non_null(strstr(buf1, "sensor.0.pose.heading_rad = -1.25\n"));
    const char *path = tmp_file("polar.conf", buf1, n1);
    tcfg_defaults(&c2);
    assert_int_equal(kv_parse_file(path, tcfg_set, &c2, err, sizeof err), 0);
    remove(path);
    f = tmpfile();
    tcfg_write(f, &c2);
    rewind(f);
    const size_t n2 = fread(buf2, 1, sizeof buf2 - 1, f);
    fclose(f);
    buf2[n2] = 0;
    assert_string_equal(buf1, buf2);
    /* "none" clears the profile */
    assert_int_equal(set("sensor.0.pd_profile", "none"), 0);
    assert_int_equal(sp->pd_profile.n, 0);
    refused("sensor.0.clutter_profile", "500:1e-6, 8000:0", "density 0 must be in (0, 1e6]");
    assert_int_equal(sp->clutter_profile.n, 2);
    /* refusals, the field untouched */
    refused("sensor.0.kind", "sonar", "must be one of: cartesian polar");
    assert_int_equal(sp->kind, TRK_SENSOR_POLAR);
    refused("sensor.0.conversion", "exact", "must be one of: first_order unbiased");
    refused("sensor.0.sigma_range_m", "0", "must be in (0, 1e+06]");
    refused("sensor.0.sigma_range_m", "-1", "must be in (0, 1e+06]");
    refused("sensor.0.sigma_range_m", "nan", "finite");
    assert_true(sp->sigma_range_m == TRK_REAL_C(2.5));
    refused("sensor.0.sigma_bearing_rad", "0.51", "must be in (0, 0.5]");
    refused("sensor.0.sigma_bearing_rad", "0", "must be in (0, 0.5]");
    refused("sensor.0.pose.heading_rad", "6.3", "must be in [-6.28319, 6.28319]");
    refused("sensor.0.pose.x_m", "2e15", "must be in");
    refused("sensor.0.pose.y_m", "inf", "finite");
    assert_true(sp->pose.y_m == 300);
    refused("sensor.0.coverage.min_range_m", "-1", "must be in [0, 1e+15]");
    refused("sensor.0.coverage.half_width_rad", "3.2", "must be in [0, 3.14159]");
    refused("sensor.0.pd_profile", "0:0.9", "2 .. ");                 /* one point */
    refused("sensor.0.pd_profile", "0:0.9, 10", "2 .. ");             /* no P_D */
    refused("sensor.0.pd_profile", "0:0.9,, 10:0.5", "2 .. ");        /* empty point */
    refused("sensor.0.pd_profile", "0:0.9, 10:0.5,", "2 .. ");        /* trailing comma */
    refused("sensor.0.pd_profile", "0:0.9 10:0.5", "2 .. ");          /* no comma */
    refused("sensor.0.pd_profile", "10:0.9, 10:0.5", "increasing");   /* not increasing */
    refused("sensor.0.pd_profile", "-1:0.9, 10:0.5", "increasing");   /* negative range */
    refused("sensor.0.pd_profile", "0:0.9, 10:1.5", "point 2: P_D 1.5");
    refused("sensor.0.pd_profile", "0:nan, 10:0.5", "2 .. ");
    char many[1024] = "";
    for (int i = 0; i <= TRK_PD_PROFILE_MAX; i++)
        snprintf(many + strlen(many), sizeof many - strlen(many), "%s%d:0.5", i ? ", " : "", 10 * i);
    refused("sensor.0.pd_profile", many, "TRK_PD_PROFILE_MAX");
    assert_int_equal(sp->pd_profile.n, 0);
    /* misspelled keys name the nearest one */
    assert_int_equal(set("sensor.0.sigma_range", "2"), 1);
    assert_string_equal(err, "sensor.0.sigma_range_m");
    assert_int_equal(set("sensor.0.coverage.max_rang_m", "2"), 1);
    assert_string_equal(err, "sensor.0.coverage.max_range_m");
    assert_int_equal(set("sensor.0.pose.headng_rad", "2"), 1);
    assert_string_equal(err, "sensor.0.pose.heading_rad");
    assert_int_equal(set("sensor.0.pd_profil", "none"), 1);
    assert_string_equal(err, "sensor.0.pd_profile");
    /* what two keys say together */
    tcfg_defaults(&c);
    assert_int_equal(set("sensor.0.coverage.min_range_m", "500"), 0);
    assert_int_equal(set("sensor.0.coverage.max_range_m", "500"), 0);
    expect_check_fails("sensor.0.coverage.max_range_m = 500 must exceed coverage.min_range_m = 500");
    assert_int_equal(set("sensor.0.coverage.max_range_m", "0"), 0); /* no limit */
    assert_int_equal(tcfg_check(&c, err, sizeof err), 0);
    assert_int_equal(set("sensor.0.pd_profile", "0:0.9, 100:0.5"), 0);
    assert_int_equal(set("sensor.0.amplitude", "rayleigh"), 0);
    assert_int_equal(tcfg_check(&c, err, sizeof err), 0); /* the target's SNR over range */
    assert_int_equal(set("sensor.0.pfa", "0.6"), 0);
    expect_check_fails("sensor.0.pd_profile: P_D 0.5 with the Rayleigh amplitude model must lie in (pfa, 1)");
    assert_int_equal(set("sensor.0.amplitude", "k"), 0);
    expect_check_fails("sensor.0.pd_profile with a tabulated amplitude model");
    assert_int_equal(set("sensor.0.pd_profile", "none"), 0);
    assert_int_equal(set("sensor.0.persistent_share", "0.2"), 0);
    assert_int_equal(set("sensor.0.persistent_pd", "0.9"), 0);
    expect_check_fails("sensor.0.persistent_share needs sensor.0.amplitude = rayleigh");
    assert_int_equal(set("sensor.0.amplitude", "rayleigh"), 0);
    assert_int_equal(set("sensor.0.pfa", "0.001"), 0);
    assert_int_equal(tcfg_check(&c, err, sizeof err), 0);
    assert_int_equal(set("sensor.0.persistent_share", "1"), -1); /* [0, 1) */
}

static void test_check(void **state)
{
    (void)state;
    tcfg_defaults(&c);
    assert_int_equal(set("confirm", "mn"), 0);
    assert_int_equal(set("confirm.mn.m", "6"), 0); /* m > n = 5 */
    expect_check_fails("confirm.mn");
    tcfg_defaults(&c);
    assert_int_equal(set("term", "kn"), 0);
    assert_int_equal(set("term.kn.k", "5"), 0); /* k >= n = 5 */
    expect_check_fails("term.kn");
    tcfg_defaults(&c);
    assert_int_equal(set("visibility", "0"), 0); /* the existence methods need it */
    expect_check_fails("needs visibility = 1");
    /* every method the tracker runs, with its defaults, passes; a bad
     * combination is refused with the method named */
    static const char *const confirms[] = {"sprt", "clutter_density", "clutter_amplitude"};
    static const char *const terms[] = {"page", "shiryaev"};
    for (int i = 0; i < 3; i++) {
        tcfg_defaults(&c);
        assert_int_equal(set("confirm", confirms[i]), 0);
        if (TRK_WITH_CLUTTER_TESTS || i == 0) {
            if (tcfg_check(&c, err, sizeof err) != 0) fail_msg("confirm = %s: %s", confirms[i], err);
        } else {
            expect_check_fails("TRK_WITH_CLUTTER_TESTS");
        }
    }
    for (int i = 0; i < 2; i++) {
        tcfg_defaults(&c);
        assert_int_equal(set("term", terms[i]), 0);
        if (tcfg_check(&c, err, sizeof err) != 0) fail_msg("term = %s: %s", terms[i], err);
    }
    tcfg_defaults(&c);
    assert_int_equal(set("confirm", "sprt"), 0);
    assert_int_equal(set("confirm.sprt.alpha", "0.6"), 0);
    assert_int_equal(set("confirm.sprt.beta", "0.6"), 0); /* alpha + beta >= 1 */
    expect_check_fails("confirm = sprt");
    tcfg_defaults(&c);
    assert_int_equal(set("term", "page"), 0);
    assert_int_equal(set("hmm.p_low_high", "0"), 0);
    assert_int_equal(set("hmm.q_high_low", "0"), 0); /* stationary prior needs p + q > 0 */
    expect_check_fails("term = page");
    /* the assembled parameters carry the chosen method and its settings */
    tcfg_defaults(&c);
    assert_int_equal(set("term", "shiryaev"), 0);
    assert_int_equal(set("term.shiryaev.h", "3.5"), 0);
    assert_int_equal(set("confirm", "sprt"), 0);
    assert_int_equal(set("confirm.sprt.pd", "0.7"), 0);
    {
        static struct trk_tracker_params tp;
        tcfg_params(&c, &tp);
        assert_int_equal(tp.confirm.method, TRK_CONFIRM_SPRT);
        assert_true(tp.confirm.u.sprt.pd == TRK_REAL_C(0.7));
        assert_int_equal(tp.term.method, TRK_TERM_SHIRYAEV);
        assert_true(tp.term.u.shiryaev.h == TRK_REAL_C(3.5));
        assert_int_equal(tp.term.u.shiryaev.hmm.n_sensors, 1);
        assert_true(tp.term.u.shiryaev.hmm.sensor[0].pd_high == c.hmm.pd_high);
    }
    /* a Rayleigh amplitude model is built and given to the tracker */
    tcfg_defaults(&c);
    assert_int_equal(set("sensor.0.amplitude", "rayleigh"), 0);
    assert_int_equal(tcfg_check(&c, err, sizeof err), 0);
    {
        struct tcfg_runtime rt;
        struct trk_tracker_params tp;
        assert_int_equal(tcfg_load(&c, &rt, err, sizeof err), 0);
        tcfg_params_rt(&c, &rt, &tp);
        assert_int_equal(tp.sensor[0].use_amplitude, 1);
        TRK_ASSERT_NEAR(trk_amplitude_pd(&tp.sensor[0].amplitude), trk_amplitude_pd(&rt.amp[0]), 0, 0);
        tcfg_unload(&rt);
        tcfg_params_rt(&c, NULL, &tp);
        assert_int_equal(tp.sensor[0].use_amplitude, 0);
    }
    tcfg_defaults(&c);
    assert_int_equal(set("sensor.0.amplitude", "k"), 0);
    expect_check_fails("needs sensor.0.amp_table");
    /* tables: missing, garbage, wrong kind are refused before anything runs */
    tcfg_defaults(&c);
    assert_int_equal(set("q2_table", "/nonexistent/q2.tbl"), 0);
    expect_check_fails("cannot open");
    const char junk[] = "this is not a table, just text that is long enough to look like one..."
                        "....................................................................";
    const char *path = tmp_file("junk.tbl", junk, sizeof junk - 1);
    tcfg_defaults(&c);
    assert_int_equal(set("sensor.0.amp_table", path), 0);
    expect_check_fails("TRK_E_TABLE_");
    tcfg_defaults(&c);
    assert_int_equal(set("q2_table", path), 0);
    expect_check_fails("TRK_E_TABLE_");
    remove(path);
    path = tmp_file("empty.tbl", "", 0);
    tcfg_defaults(&c);
    assert_int_equal(set("q2_table", path), 0);
    expect_check_fails("empty");
    remove(path);
    /* a second sensor */
    if (TRK_MAX_SENSORS >= 2) {
        tcfg_defaults(&c);
        assert_int_equal(set("sensors", "2"), 0);
        assert_int_equal(set("sensor.1.pd", "0.5"), 0);
        assert_int_equal(tcfg_check(&c, err, sizeof err), 0);
    }
}

static void test_help(void **state)
{
    (void)state;
    static char buf[16384];
    FILE *f = tmpfile();
    assert_non_null(f);
    tcfg_help(f);
    rewind(f);
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    fclose(f);
    buf[n] = 0;
    /* every key of the printed configuration is documented */
    tcfg_defaults(&c);
    static char conf[16384];
    f = tmpfile();
    tcfg_write(f, &c);
    rewind(f);
    n = fread(conf, 1, sizeof conf - 1, f);
    fclose(f);
    conf[n] = 0;
    for (char *line = strtok(conf, "\n"); line; line = strtok(NULL, "\n")) {
        if (line[0] == '#') continue;
        char key[128];
        assert_int_equal(sscanf(line, "%127[^ =]", key), 1);
        /* "sensor.0.pd" is documented as "sensor.N.pd"; "confirm.mn.m" as "confirm.mn.m" */
        const char *doc = key;
        char generic[128];
        if (strncmp(key, "sensor.", 7) == 0) {
            snprintf(generic, sizeof generic, "sensor.N.%s", strchr(key + 7, '.') + 1);
            doc = generic;
        }
        const char *last = strrchr(doc, '.');
        if (!strstr(buf, doc) && !(last && strstr(buf, last + 1)))
            fail_msg("key %s is not in the help", key);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_defaults),      cmocka_unit_test(test_set_keys),
        cmocka_unit_test(test_bad_values),    cmocka_unit_test(test_file),
        cmocka_unit_test(test_number_parsers), cmocka_unit_test(test_write_read_back),
        cmocka_unit_test(test_check),         cmocka_unit_test(test_help),
        cmocka_unit_test(test_key_list),      cmocka_unit_test(test_polar_keys),
    };
    return trk_run_tests("lcm_config", tests, NULL, NULL);
}

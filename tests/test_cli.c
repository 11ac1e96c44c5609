/* test_cli.c - cli_opt (tools/cli/cli.h): `--name value` and
 * `--name=value`, other options left alone, a missing value; and the stop
 * flag set by SIGINT/SIGTERM after cli_catch_stop_signals. */
#define _POSIX_C_SOURCE 200809L
#include <signal.h>

#include "cli.h"
#include "trk_test.h"

static void test_forms(void **state)
{
    (void)state;
    char *argv[] = {"prog", "--scans", "12", "--scans=7", "--scans-max", "3", "--scans=", "--x", "--scans", NULL};
    const int argc = 9;
    const char *v = NULL;
    int i = 1;
    assert_int_equal(cli_opt(argc, argv, &i, "--scans", &v, "t"), 1); /* separate value */
    assert_string_equal(v, "12");
    assert_int_equal(i, 2);
    i = 3;
    assert_int_equal(cli_opt(argc, argv, &i, "--scans", &v, "t"), 1); /* joined value */
    assert_string_equal(v, "7");
    assert_int_equal(i, 3);
    i = 4;
    v = NULL;
    assert_int_equal(cli_opt(argc, argv, &i, "--scans", &v, "t"), 0); /* a longer name */
    assert_null(v);
    assert_int_equal(i, 4);
    i = 6;
    assert_int_equal(cli_opt(argc, argv, &i, "--scans", &v, "t"), 1); /* empty joined value */
    assert_string_equal(v, "");
    i = 7;
    assert_int_equal(cli_opt(argc, argv, &i, "--scans", &v, "t"), 0); /* another option */
    i = 8;
    assert_int_equal(cli_opt(argc, argv, &i, "--scans", &v, NULL), -1); /* last: no value */
    assert_int_equal(i, 8);
}

static void test_stop_signals(void **state)
{
    (void)state;
    cli_catch_stop_signals();
    assert_int_equal(cli_stop_flag, 0);
    assert_int_equal(raise(SIGTERM), 0);
    assert_int_equal(cli_stop_flag, 1);
    assert_int_equal(cli_stop_signal, SIGTERM);
    cli_stop_flag = 0;
    assert_int_equal(raise(SIGINT), 0);
    assert_int_equal(cli_stop_flag, 1);
    assert_int_equal(cli_stop_signal, SIGINT);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_forms),
        cmocka_unit_test(test_stop_signals),
    };
    return trk_run_tests("cli", tests, NULL, NULL);
}

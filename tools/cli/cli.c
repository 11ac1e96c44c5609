/* cli.c - command-line plumbing shared by the tools (cli.h). */
#define _POSIX_C_SOURCE 200809L
#include "cli.h"

#include <stdio.h>
#include <string.h>

int cli_opt(int argc, char **argv, int *i, const char *name, const char **val, const char *prog)
{
    const char *a = argv[*i];
    size_t n = strlen(name);
    if (strncmp(a, name, n) != 0) return 0;
    if (a[n] == '=') {
        *val = a + n + 1;
        return 1;
    }
    if (a[n]) return 0;
    if (*i + 1 >= argc) {
        fprintf(stderr, "%s%s%s needs a value\n", prog ? prog : "", prog ? ": " : "", name);
        return -1;
    }
    *val = argv[++*i];
    return 1;
}

volatile sig_atomic_t cli_stop_flag = 0, cli_stop_signal = 0;

static void on_stop_signal(int sig)
{
    cli_stop_flag = 1;
    cli_stop_signal = sig;
}

void cli_catch_stop_signals(void)
{
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_stop_signal;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, NULL);
    sigaction(SIGTERM, &sa, NULL);
}

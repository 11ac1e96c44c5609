/* cli.h - command-line plumbing shared by the tools: `--name value` /
 * `--name=value` options, and a clean stop on SIGINT/SIGTERM. */
#ifndef TRK_TOOLS_CLI_H
#define TRK_TOOLS_CLI_H

#include <signal.h>

/* Is argv[*i] the option `name` (a value after it, or `name=value`)?
 * 1: yes, *val set and *i advanced past a separate value; -1: yes but the
 * value is missing ("PROG: NAME needs a value" on stderr, prog may be NULL);
 * 0: another argument. */
int cli_opt(int argc, char **argv, int *i, const char *name, const char **val, const char *prog);

/* After cli_catch_stop_signals(), SIGINT and SIGTERM no longer kill the
 * process: they set cli_stop_flag to 1 and cli_stop_signal to the signal's
 * number, for the main loop to finish cleanly. */
extern volatile sig_atomic_t cli_stop_flag, cli_stop_signal;
void cli_catch_stop_signals(void);

#endif

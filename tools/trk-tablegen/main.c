/* trk-tablegen - offline generator of the library's lookup tables
 * (trk/table.h), and their inspector.
 *
 *   trk-tablegen amp ...      amplitude model table (trk/amplitude.h)
 *   trk-tablegen info FILE    load a table through the library, print it
 *   trk-tablegen --help       list of subcommands; `trk-tablegen CMD --help`
 *
 * Subcommands are registered by TABLEGEN_CMD lines (tablegen.h).
 * Compiled with -DTRK_TOOL_MPI (mk/mpi.mk) this is trk-tablegen-mpi: the
 * same program on every rank of an MPI job, the work spread over the ranks
 * (tools/par/par.h), the table written by rank 0. */
#include <stdio.h>

#include "cli.h"
#include "par.h"
#include "tablegen.h"
#include "trk/types.h"

#ifdef TRK_TOOL_MPI
#include "par_mpi.h" /* its PAR_TOOL_MAIN */
#define TABLEGEN_PROG "trk-tablegen-mpi"
#else
#define TABLEGEN_PROG "trk-tablegen"
#endif

#define TABLEGEN_CMD_ENTRY(n)                          \
    extern const char *const tablegen_summary_##n;     \
    int tablegen_cmd_##n(int argc, char **argv);
#include "tablegen_cmds.inc"
#undef TABLEGEN_CMD_ENTRY

int tablegen_valid_ident(const char *s)
{
    if (!s || !*s || !((*s >= 'a' && *s <= 'z') || (*s >= 'A' && *s <= 'Z') || *s == '_')) return 0;
    for (; *s; s++)
        if (!((*s >= 'a' && *s <= 'z') || (*s >= 'A' && *s <= 'Z') || (*s >= '0' && *s <= '9') || *s == '_'))
            return 0;
    return 1;
}

int tablegen_parse_ident(const char *s, void *dst)
{
    if (!tablegen_valid_ident(s)) return -1;
    *(const char **)dst = s;
    return 0;
}

int tablegen_checkpoint(const char *cmd, const char *path, double interval_s, int argc, char **argv)
{
    struct par *p = tablegen_par();
    if (!p || !path) return 0;
    char tool[64];
    snprintf(tool, sizeof tool, "trk-tablegen %s", cmd);
    return par_checkpoint_cli(p, tool, path, interval_s, argc, argv);
}

static int run(int argc, char **argv)
{
    if (trk_config_check() != TRK_OK) {
        fprintf(stderr, TABLEGEN_PROG ": libtrk was built with other capacities or real type\n");
        return 2;
    }
    /* the registry (its summaries are objects of the subcommands' files) */
#define TABLEGEN_CMD_ENTRY(n) {#n, tablegen_summary_##n, tablegen_cmd_##n},
    struct cli_cmd cmds[] = {
#include "tablegen_cmds.inc"
        {NULL, NULL, NULL}};
#undef TABLEGEN_CMD_ENTRY
    char head[256];
    snprintf(head, sizeof head,
             "usage: trk-tablegen COMMAND [options]   (trk-tablegen COMMAND --help)\n"
             "Offline generator of trk's lookup tables (%s build: tables default to %zu-byte reals).\n"
             "commands:\n",
             TRK_REAL_IS_FLOAT ? "float" : "double", sizeof(trk_real));
    return cli_dispatch(TABLEGEN_PROG, "command", head, cmds, NULL, argc, argv);
}

PAR_TOOL_MAIN(tablegen_par, run, TABLEGEN_PROG) /* main; every rank runs it, rank 0 writes */

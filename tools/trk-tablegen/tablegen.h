/* tablegen.h - subcommands of trk-tablegen.
 *
 * A subcommand lives in its own file tools/trk-tablegen/NAME.c and is defined
 * with
 *     TABLEGEN_CMD(name, "one-line summary for --help")
 *     {   ...   return exit status;   }
 * (argv[0] is the subcommand's name; its options are a table of the one
 * option parser, tools/cli/cli.h). The build collects every TABLEGEN_CMD
 * line into build/gen/tablegen_cmds.inc (tools/trk-tablegen/tool.mk);
 * main.c dispatches on the first argument (cli_dispatch). Nothing else to
 * edit. */
#ifndef TRK_TABLEGEN_H
#define TRK_TABLEGEN_H

#define TABLEGEN_CMD(cname, summary_)                          \
    const char *const tablegen_summary_##cname = summary_;     \
    int tablegen_cmd_##cname(int argc, char **argv)

/* Shared helpers (main.c). */
/* This process's work distribution (tools/par/par.h): the rank of the job
 * in trk-tablegen-mpi, NULL (this process's threads) in trk-tablegen. */
struct par *tablegen_par(void);
/* trk-tablegen-mpi: --checkpoint FILE for subcommand `cmd` (the job key:
 * its arguments but --threads, --quiet and the checkpoint's own), after
 * cli_parse. 0, or 2 after a message (a refused checkpoint). */
int tablegen_checkpoint(const char *cmd, const char *path, double interval_s, int argc, char **argv);
/* A C identifier (the --name of --format c)? */
int tablegen_valid_ident(const char *s);
/* --name IDENT (a CLI_CUSTOM parser): *(const char **)dst = s when s is a C
 * identifier; 0, or -1. */
int tablegen_parse_ident(const char *s, void *dst);

#endif

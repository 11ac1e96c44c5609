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
/* A C identifier (the --name of --format c)? */
int tablegen_valid_ident(const char *s);
/* --name IDENT (a CLI_CUSTOM parser): *(const char **)dst = s when s is a C
 * identifier; 0, or -1. */
int tablegen_parse_ident(const char *s, void *dst);

#endif

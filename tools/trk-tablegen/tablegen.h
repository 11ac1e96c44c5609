/* tablegen.h - subcommands of trk-tablegen.
 *
 * A subcommand lives in its own file tools/trk-tablegen/NAME.c and is defined
 * with
 *     TABLEGEN_CMD(name, "one-line summary for --help")
 *     {   ...   return exit status;   }
 * (argv[0] is the subcommand's name). The build collects every TABLEGEN_CMD
 * line into build/gen/tablegen_cmds.inc (tools/trk-tablegen/tool.mk); main.c
 * dispatches on the first argument. Nothing else to edit. */
#ifndef TRK_TABLEGEN_H
#define TRK_TABLEGEN_H

#define TABLEGEN_CMD(cname, summary_)                          \
    const char *const tablegen_summary_##cname = summary_;     \
    int tablegen_cmd_##cname(int argc, char **argv)

/* Shared helpers (main.c). */
int tablegen_parse_uint(const char *s, unsigned long max, unsigned long *v);
int tablegen_parse_real(const char *s, double *v);
/* A C identifier (the --name of --format c)? */
int tablegen_valid_ident(const char *s);

#endif

/* trk-tablegen - offline generator of the library's lookup tables
 * (trk/table.h), and their inspector.
 *
 *   trk-tablegen amp ...      amplitude model table (trk/amplitude.h)
 *   trk-tablegen info FILE    load a table through the library, print it
 *   trk-tablegen --help       list of subcommands; `trk-tablegen CMD --help`
 *
 * Subcommands are registered by TABLEGEN_CMD lines (tablegen.h). */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "tablegen.h"
#include "trk/types.h"

#define TABLEGEN_CMD_ENTRY(n)                          \
    extern const char *const tablegen_summary_##n;     \
    int tablegen_cmd_##n(int argc, char **argv);
#include "tablegen_cmds.inc"
#undef TABLEGEN_CMD_ENTRY

static const struct {
    const char *name;
    int (*fn)(int, char **);
    const char *const *summary;
} cmds[] = {
#define TABLEGEN_CMD_ENTRY(n) {#n, tablegen_cmd_##n, &tablegen_summary_##n},
#include "tablegen_cmds.inc"
#undef TABLEGEN_CMD_ENTRY
    {NULL, NULL, NULL}};

int tablegen_parse_uint(const char *s, unsigned long max, unsigned long *v)
{
    char *end;
    errno = 0;
    if (!s || !*s || *s == '-') return -1;
    unsigned long x = strtoul(s, &end, 10);
    if (errno || *end || x > max) return -1;
    *v = x;
    return 0;
}

int tablegen_parse_real(const char *s, double *v)
{
    char *end;
    errno = 0;
    if (!s || !*s) return -1;
    double x = strtod(s, &end);
    if (errno == ERANGE || *end) return -1;
    *v = x;
    return 0;
}

int tablegen_valid_ident(const char *s)
{
    if (!s || !*s || !((*s >= 'a' && *s <= 'z') || (*s >= 'A' && *s <= 'Z') || *s == '_')) return 0;
    for (; *s; s++)
        if (!((*s >= 'a' && *s <= 'z') || (*s >= 'A' && *s <= 'Z') || (*s >= '0' && *s <= '9') || *s == '_'))
            return 0;
    return 1;
}

static void usage(FILE *fp)
{
    fprintf(fp,
            "usage: trk-tablegen COMMAND [options]   (trk-tablegen COMMAND --help)\n"
            "Offline generator of trk's lookup tables (%s build: tables default to %zu-byte reals).\n"
            "commands:\n",
            TRK_REAL_IS_FLOAT ? "float" : "double", sizeof(trk_real));
    for (int i = 0; cmds[i].name; i++) fprintf(fp, "  %-8s %s\n", cmds[i].name, *cmds[i].summary);
}

int main(int argc, char **argv)
{
    if (trk_config_check() != TRK_OK) {
        fprintf(stderr, "trk-tablegen: libtrk was built with other capacities or real type\n");
        return 2;
    }
    if (argc < 2) {
        usage(stderr);
        return 2;
    }
    if (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0 || strcmp(argv[1], "help") == 0) {
        usage(stdout);
        return 0;
    }
    for (int i = 0; cmds[i].name; i++)
        if (strcmp(argv[1], cmds[i].name) == 0) return cmds[i].fn(argc - 1, argv + 1);
    fprintf(stderr, "trk-tablegen: unknown command '%s'\n", argv[1]);
    usage(stderr);
    return 2;
}

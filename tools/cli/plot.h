/* plot.h - gnuplot output for the tools (CSV files: fileio.h).
 *
 * plot_gnuplot(prog, base, body) writes base.gp: a preamble choosing the pngcairo
 * terminal (png when pngcairo is missing) with output base.png, then `body`
 * (gnuplot commands, e.g. "plot 'x.csv' using 1:2 with lines"). If gnuplot
 * is on PATH it runs it and returns 0 when base.png was written; otherwise it
 * says so on stderr ("PROG: ..."), keeps the .gp script (run it later with
 * `gnuplot base.gp`) and returns 1. -1 on an I/O error. */
#ifndef TRK_TOOLS_PLOT_H
#define TRK_TOOLS_PLOT_H

#include <stdio.h>

int plot_gnuplot(const char *prog, const char *base, const char *body);
/* 1 when an executable `gnuplot` is on PATH. */
int plot_have_gnuplot(void);

#endif

/* progress.h - progress bar on stderr for long tool runs: runs done, rate,
 * ETA. On a terminal one line is redrawn (at most 5 times a second); into a
 * file or pipe a plain line is written every 10 % of the work.
 * Not thread-safe: call progress_add from one thread at a time (e.g. inside
 * `#pragma omp critical`, or let only one thread report). */
#ifndef TRK_TOOLS_PROGRESS_H
#define TRK_TOOLS_PROGRESS_H

struct progress {
    const char *label;
    long total, done;
    double t0, last_draw;
    int tty, enabled, last_decile;
};

/* enabled = 0 makes every call a no-op (a --quiet flag). */
void progress_start(struct progress *p, const char *label, long total, int enabled);
void progress_add(struct progress *p, long n);
/* Final line with the elapsed time. */
void progress_end(struct progress *p);
/* Monotonic seconds (for tools that time themselves). */
double progress_now_s(void);

#endif

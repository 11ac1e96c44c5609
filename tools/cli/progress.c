/* progress.c - progress bar on stderr (progress.h). */
#define _POSIX_C_SOURCE 200809L
#include "progress.h"

#include <stdio.h>
#include <time.h>
#include <unistd.h>

double progress_now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static void fmt_time(char *buf, size_t n, double s)
{
    if (!(s >= 0) || s > 1e7) {
        snprintf(buf, n, "--:--");
        return;
    }
    long t = (long)(s + 0.5);
    if (t >= 3600) snprintf(buf, n, "%ldh%02ldm", t / 3600, (t / 60) % 60);
    else snprintf(buf, n, "%ldm%02lds", t / 60, t % 60);
}

static void draw(struct progress *p, int final)
{
    const double now = progress_now_s(), el = now - p->t0;
    const double rate = el > 0 ? (double)p->done / el : 0;
    const double frac = p->total > 0 ? (double)p->done / (double)p->total : 1;
    char eta[32], elapsed[32];
    fmt_time(eta, sizeof eta, rate > 0 ? (double)(p->total - p->done) / rate : -1);
    fmt_time(elapsed, sizeof elapsed, el);
    if (p->tty) {
        char bar[31];
        int fill = (int)(frac * 30);
        for (int i = 0; i < 30; i++) bar[i] = i < fill ? '#' : '.';
        bar[30] = 0;
        fprintf(stderr, "\r%s [%s] %ld/%ld %5.1f%% %.3g/s ETA %s  ", p->label, bar, p->done,
                p->total, 100 * frac, rate, final ? elapsed : eta);
        if (final) fputc('\n', stderr);
    } else {
        fprintf(stderr, "%s: %ld/%ld (%.0f%%) %.3g/s %s %s\n", p->label, p->done, p->total,
                100 * frac, rate, final ? "elapsed" : "ETA", final ? elapsed : eta);
    }
    fflush(stderr);
    p->last_draw = now;
}

void progress_start(struct progress *p, const char *label, long total, int enabled)
{
    p->label = label;
    p->total = total;
    p->done = 0;
    p->t0 = progress_now_s();
    p->last_draw = 0;
    p->tty = isatty(fileno(stderr));
    p->enabled = enabled;
    p->last_decile = 0;
}

void progress_add(struct progress *p, long n)
{
    p->done += n;
    if (!p->enabled) return;
    if (p->tty) {
        if (progress_now_s() - p->last_draw >= 0.2) draw(p, 0);
    } else if (p->total > 0) {
        int dec = (int)(10 * p->done / p->total);
        if (dec > p->last_decile && p->done < p->total) {
            p->last_decile = dec;
            draw(p, 0);
        }
    }
}

void progress_end(struct progress *p)
{
    if (p->enabled) draw(p, 1);
}

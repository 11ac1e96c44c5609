/* lcm_consumer.c - an external program built against trk's installed LCM
 * types with pkg-config alone (make install-check):
 *
 *   cc -std=c99 lcm_consumer.c $(pkg-config --cflags --libs trk-lcm)
 *
 * Publishes a trk.track_list_t on TRK_TRACKS over LCM's in-process transport
 * (memq://) with the installed lcm-gen C code (publish/subscribe functions
 * included) and checks that the subscriber decodes the same values. Exit
 * status 0, or 1. */
#include <stdio.h>
#include <string.h>

#include <lcm/lcm.h>

#include "trk/lcm/trk_track_list_t.h"

static int received;
static trk_track_list_t got;

static void on_tracks(const lcm_recv_buf_t *rbuf, const char *channel, const trk_track_list_t *msg, void *user)
{
    (void)rbuf, (void)channel, (void)user;
    got = *msg;
    received++;
}

int main(void)
{
    lcm_t *lc = lcm_create("memq://");
    if (!lc) {
        printf("lcm_consumer: lcm_create(memq://) failed\n");
        return 1;
    }
    trk_track_list_t_subscription_t *sub = trk_track_list_t_subscribe(lc, "TRK_TRACKS", on_tracks, NULL);
    static trk_track_list_t m;
    memset(&m, 0, sizeof m);
    m.utime = 1700000000000000;
    m.seq = 7;
    m.n_tracks = 2;
    m.tracks[0].id = 11;
    m.tracks[0].status = TRK_TRACK_T_STATUS_CONFIRMED;
    m.tracks[0].x[0] = 123.5;
    m.tracks[1].id = 12;
    m.tracks[1].status = TRK_TRACK_T_STATUS_TENTATIVE;
    m.tracks[1].x[2] = -4.25;
    int rc = trk_track_list_t_publish(lc, "TRK_TRACKS", &m);
    if (rc == 0) rc = lcm_handle(lc);
    trk_track_list_t_unsubscribe(lc, sub);
    lcm_destroy(lc);
    int ok = rc == 0 && received == 1 && got.utime == m.utime && got.seq == 7 && got.n_tracks == 2 &&
             got.tracks[0].id == 11 && got.tracks[0].status == TRK_TRACK_T_STATUS_CONFIRMED &&
             got.tracks[0].x[0] == 123.5 && got.tracks[1].id == 12 && got.tracks[1].x[2] == -4.25;
    printf("lcm_consumer: %s: %d message(s) on TRK_TRACKS over memq://, %d tracks (ids %lld, %lld), %d bytes encoded\n",
           ok ? "ok" : "FAILED", received, (int)got.n_tracks, (long long)got.tracks[0].id,
           (long long)got.tracks[1].id, trk_track_list_t_encoded_size(&m));
    return ok ? 0 : 1;
}

/* consumer.c - an external program built against an installed trk with
 * pkg-config alone (make install-check): one call into each installed
 * library through the public headers.
 *
 *   cc -std=c99 consumer.c $(pkg-config --cflags --libs trk)        (or trk-float)
 *   ./consumer AMP_TABLE_FILE
 *
 * libtrk: the ABI check and a tracker scan; libtrk_host: the table file
 * reader (trk_table_load_file) and the amplitude model on it; libtrk_perf:
 * the MRE steady state. Exit status 0, 1 when a call fails, 3 when the
 * library was built with another configuration than the headers (TRK_E_ABI:
 * e.g. double headers with the float library). */
#include <stdint.h>
#include <stdio.h>

#include "trk/table_file.h"
#include "trk/trk.h"

static uint64_t table_buf[1u << 16];
static struct trk_tracker tracker;

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: consumer AMP_TABLE_FILE\n");
        return 1;
    }
    if (trk_config_check() != TRK_OK || trk_tracker_abi_check() != TRK_OK) {
        printf("consumer: %s: headers with sizeof(trk_real) %zu, the library %zu\n", trk_status_str(TRK_E_ABI),
               sizeof(trk_real), trk_real_size());
        return 3;
    }
    /* libtrk_host + libtrk: the table file and the amplitude model */
    struct trk_table table;
    size_t len;
    trk_status st = trk_table_load_file(argv[1], table_buf, sizeof table_buf, &table, &len);
    struct trk_amplitude amp;
    if (st == TRK_OK) st = trk_amplitude_init_table(&amp, &table);
    if (st != TRK_OK) {
        printf("consumer: table %s: %s\n", argv[1], trk_status_str(st));
        return 1;
    }
    /* libtrk_perf: the MRE steady state of a PDAF with q2 = 0.8 */
    struct trk_mre_params mp = {0};
    mp.nz = 2;
    mp.dt_s = TRK_REAL_C(2.0);
    mp.q_m2_per_s3 = TRK_REAL_C(0.01);
    mp.r_m2 = TRK_REAL_C(9.0);
    mp.gate_prob = TRK_REAL_C(0.99);
    mp.clutter_density = TRK_REAL_C(5e-6);
    mp.q2 = TRK_REAL_C(0.8);
    struct trk_mre mre;
    struct trk_mre_result res;
    st = trk_mre_init(&mre, &mp);
    if (st == TRK_OK) st = trk_mre_steady_state(&mre, NULL, &res);
    if (st != TRK_OK) {
        printf("consumer: MRE: %s\n", trk_status_str(st));
        return 1;
    }
    /* libtrk: a tracker and one scan with one detection */
    struct trk_tracker_params tp;
    trk_tracker_default_params(&tp);
    const char *field = NULL;
    st = trk_tracker_check_params(&tp, &field);
    if (st == TRK_OK) st = trk_tracker_init(&tracker, &tp);
    struct trk_detection det = {0};
    det.x_m = TRK_REAL_C(100.0);
    det.y_m = TRK_REAL_C(200.0);
    struct trk_scan scan = {1000000, 0, 1, &det, NULL, 0, {0, 0, 0}, NULL};
    struct trk_scan_report rep;
    if (st == TRK_OK) st = trk_tracker_process_scan(&tracker, &scan, &rep);
    if (st != TRK_OK) {
        printf("consumer: tracker: %s%s%s\n", trk_status_str(st), field ? " " : "", field ? field : "");
        return 1;
    }
    printf("consumer: trk_real %s; table %s (%zu bytes): threshold %.4f, P_D %.4f; MRE RMSE %.3f m "
           "(%d iterations); one scan: %u detection(s), %u candidate(s)\n",
           sizeof(trk_real) == sizeof(float) ? "float" : "double", argv[1], len,
           (double)trk_amplitude_threshold(&amp), (double)trk_amplitude_pd(&amp), (double)res.rmse_m,
           res.iterations, (unsigned)rep.n_detections, (unsigned)rep.n_candidates);
    return 0;
}

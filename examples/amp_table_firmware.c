/* amp_table_firmware.c - the firmware way to use an amplitude table.
 *
 * The table was generated offline as C source,
 *     trk-tablegen amp --clutter-model k --k-shape 1 --snr-db 15 --pfa 1e-3 \
 *         --format c --name amp_table --out amp_table_data.h
 * (mk/tables.mk does this into build/gen/ for every build, in the build's
 * real width), and is linked as a const array: on a microcontroller it stays
 * in flash. trk_table_parse checks it once at start-up (magic, version, real
 * width, CRC-32, layout, finite and monotone values) and returns a view on
 * the array: no copy, no heap. The amplitude model then answers ln l^a(a)
 * for each detection by table lookup (a few ns), the PDAFAI weight factor of
 * Brekke eqs 19-20; a detection below the threshold is refused with
 * TRK_E_RANGE and counted, as the tracker does. */
#include <stdio.h>

#include "amp_table_data.h" /* static const union {bytes, double} amp_table; AMP_TABLE_SIZE */
#include "trk/amplitude.h"
#include "trk/table.h"

/* Statically allocated state, as firmware has it. */
static struct trk_table table;
static struct trk_amplitude model;

int main(void)
{
    trk_status st = trk_table_parse(&table, amp_table.bytes, AMP_TABLE_SIZE);
    if (st != TRK_OK) {
        printf("amplitude table rejected: %s\n", trk_status_str(st));
        return 1;
    }
    st = trk_amplitude_init_table(&model, &table);
    if (st != TRK_OK) {
        printf("not a usable amplitude table: %s\n", trk_status_str(st));
        return 1;
    }
    printf("amplitude table in place: %u bytes at %p, K clutter nu %g, SNR %g dB, P_FA %g\n",
           (unsigned)table.info.size, (const void *)table.bytes, (double)model.nu, (double)model.snr_db,
           (double)model.pfa);
    printf("threshold t = %.6f, P_D = %.6f\n", (double)trk_amplitude_threshold(&model),
           (double)trk_amplitude_pd(&model));

    /* one scan's detection amplitudes (units of sqrt(clutter power)) */
    const trk_real amplitude[] = {TRK_REAL_C(5.0), TRK_REAL_C(3.9), TRK_REAL_C(6.5), TRK_REAL_C(9.0),
                                  TRK_REAL_C(15.0), TRK_REAL_C(30.0), TRK_REAL_C(-1.0)};
    int rejected = 0;
    for (size_t i = 0; i < sizeof amplitude / sizeof amplitude[0]; i++) {
        trk_real log_lr;
        st = trk_amplitude_log_lr(&model, amplitude[i], &log_lr);
        if (st != TRK_OK) {
            rejected++;
            printf("  a = %6.2f  rejected (%s)\n", (double)amplitude[i], trk_status_str(st));
            continue;
        }
        printf("  a = %6.2f  ln l^a = %9.4f\n", (double)amplitude[i], (double)log_lr);
    }
    printf("%d detection(s) rejected\n", rejected);
    return rejected == 2 ? 0 : 1; /* 3.9 is below the threshold, -1 is no amplitude */
}

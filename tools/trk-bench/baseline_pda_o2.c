/* baseline_pda_o2.c - BENCHMARK BASELINE, NOT LIBRARY CODE: the
 * loop of baseline_pda.c compiled again at -O2 -funroll-loops (tool.mk), the
 * flags the library had before it moved to -O3, so that trk-bench can show
 * the loop at its faster build as well: -O3 makes gcc 12's float loop
 * slower. */
#define baseline_pda_cv2 baseline_pda_cv2_o2
#include "baseline_pda.c"

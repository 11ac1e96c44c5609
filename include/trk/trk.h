/** @file
 * trk/trk.h - umbrella header: includes every public header of libtrk. */
#ifndef TRK_TRK_H
#define TRK_TRK_H

#include "trk/config.h"
#include "trk/types.h"
#include "trk/linalg.h"
#include "trk/special.h"
#include "trk/kalman.h"
#include "trk/gate.h"
#include "trk/pda.h"
#include "trk/table.h"
#include "trk/amplitude.h"
#include "trk/visibility.h"
#include "trk/hmm_detect.h"
#include "trk/confirm_mn.h"
#include "trk/confirm_sprt.h"
#include "trk/clutter_test.h"
#include "trk/term_kn.h"
#include "trk/term_page.h"
#include "trk/term_shiryaev.h"
#include "trk/tracker.h"
#include "trk/jpda.h"
#include "trk/imm.h"
#include "trk/q2.h"
#include "trk/mre.h"
#include "trk/toc.h"
#include "trk/crlb.h"

#endif

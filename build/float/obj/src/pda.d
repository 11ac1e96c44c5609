build/float/obj/src/pda.o: src/pda.c include/trk/pda.h \
 include/trk/kalman.h include/trk/types.h include/trk/config.h \
 include/trk/check_config.h src/pda_impl.h src/kalman_impl.h \
 src/linalg_impl.h include/trk/gate.h
include/trk/pda.h:
include/trk/kalman.h:
include/trk/types.h:
include/trk/config.h:
include/trk/check_config.h:
src/pda_impl.h:
src/kalman_impl.h:
src/linalg_impl.h:
include/trk/gate.h:

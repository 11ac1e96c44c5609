build/obj/src/gate.o: src/gate.c include/trk/gate.h include/trk/types.h \
 include/trk/config.h include/trk/check_config.h src/kalman_impl.h \
 src/linalg_impl.h include/trk/kalman.h include/trk/special.h
include/trk/gate.h:
include/trk/types.h:
include/trk/config.h:
include/trk/check_config.h:
src/kalman_impl.h:
src/linalg_impl.h:
include/trk/kalman.h:
include/trk/special.h:

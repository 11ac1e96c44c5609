build/obj/src/kalman.o: src/kalman.c include/trk/kalman.h \
 include/trk/types.h include/trk/config.h include/trk/check_config.h \
 src/kalman_impl.h src/linalg_impl.h
include/trk/kalman.h:
include/trk/types.h:
include/trk/config.h:
include/trk/check_config.h:
src/kalman_impl.h:
src/linalg_impl.h:

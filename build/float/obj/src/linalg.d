build/float/obj/src/linalg.o: src/linalg.c include/trk/linalg.h \
 include/trk/types.h include/trk/config.h include/trk/check_config.h \
 src/linalg_impl.h
include/trk/linalg.h:
include/trk/types.h:
include/trk/config.h:
include/trk/check_config.h:
src/linalg_impl.h:

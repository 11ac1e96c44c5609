build/float/obj/src/status.o: src/status.c include/trk/types.h \
 include/trk/config.h include/trk/check_config.h
include/trk/types.h:
include/trk/config.h:
include/trk/check_config.h:

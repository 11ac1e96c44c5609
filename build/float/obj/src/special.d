build/float/obj/src/special.o: src/special.c include/trk/special.h \
 include/trk/types.h include/trk/config.h include/trk/check_config.h
include/trk/special.h:
include/trk/types.h:
include/trk/config.h:
include/trk/check_config.h:

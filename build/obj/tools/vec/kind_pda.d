build/obj/tools/vec/kind_pda.o: tools/vec/kind_pda.c include/trk/kalman.h \
 include/trk/types.h include/trk/config.h include/trk/check_config.h \
 include/trk/pda.h tools/vec/vec.h
include/trk/kalman.h:
include/trk/types.h:
include/trk/config.h:
include/trk/check_config.h:
include/trk/pda.h:
tools/vec/vec.h:

build/obj/tools/trk-vectors/main.o: tools/trk-vectors/main.c \
 include/trk/types.h include/trk/config.h include/trk/check_config.h \
 tools/vec/vec.h
include/trk/types.h:
include/trk/config.h:
include/trk/check_config.h:
tools/vec/vec.h:

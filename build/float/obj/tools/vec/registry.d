build/float/obj/tools/vec/registry.o: tools/vec/registry.c \
 tools/vec/vec.h build/float/gen/vec_kinds.inc
tools/vec/vec.h:
build/float/gen/vec_kinds.inc:

build/obj/tools/vec/registry.o: tools/vec/registry.c tools/vec/vec.h \
 build/gen/vec_kinds.inc
tools/vec/vec.h:
build/gen/vec_kinds.inc:
